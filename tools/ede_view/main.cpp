// ede-view: a small HTTP server on localhost with one page (web/) to watch runs live and scrub logs.
//
//   ede-view [--logs DIR]... [--scenes DIR]... [--out-dir DIR] [--host 127.0.0.1] [--port 8080]
//
// Thin: parses the command line, makes the server (server.cpp: routes, limits, errors), prints its address
// and serves until Ctrl-C or SIGTERM (exit 130 or 143, the tools' convention; docs/cli.md). Signals are
// taken by a thread with sigwait, which stops the server from outside any handler. Rejected: stopping
// from a signal handler (httplib's stop() is not async-signal-safe).
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <malloc.h>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "command_line.hpp"
#include "report_error.hpp"
#include "server.hpp"
#include "tool_main.hpp"

namespace {

namespace fs = std::filesystem;

int fail(const std::string& message) {
  ede::tools::report_error("ede-view", message);
  return 1;
}

// A folder given on the command line as a Root: it must exist.
bool add_root(std::vector<ede::view::Root>& roots, const std::string& dir, const char* option, std::string& error) {
  std::error_code ec;
  const fs::path canonical = fs::canonical(dir, ec);
  if (ec || !fs::is_directory(canonical)) {
    error = std::string(option) + " " + dir + ": not a folder. Fix: give an existing folder.";
    return false;
  }
  roots.push_back({canonical});
  return true;
}

int body(int argc, char** argv) {
  CLI::App app{"ede-view: watch runs live and scrub event logs in the browser (localhost only by default)"};
  ede::view::ServerOptions opt;
  std::vector<std::string> logs, scenes;
  std::string out_dir = "ede-view-runs";
  app.add_option("--logs", logs, "a folder whose .ede logs the page may open (repeatable)");
  app.add_option("--scenes", scenes,
                 "a folder of scene files (.toml) for live runs (repeatable; default: the examples)");
  app.add_option("--out-dir", out_dir, "where every live run writes its log (also served as logs)")->capture_default_str();
  app.add_option("--host", opt.host, "the address to listen on (127.0.0.1: this machine only)")->capture_default_str();
  app.add_option("--port", opt.port, "the port (0: any free one; the address is printed)")->capture_default_str()->check(CLI::Range(0, 65535));
  app.add_option("--max-disks", opt.max_live_disks, "the most disks a live run may have")->capture_default_str();
  std::uint64_t frame_mib = opt.frame_memory >> 20;
  app.add_option("--frame-memory", frame_mib,
                 "MiB of frames being sent at once; above it a page is told to ask again (503)")
      ->capture_default_str()
      ->check(CLI::Range(std::uint64_t(1), std::uint64_t(1) << 20));
  ede::tools::add_version_flags(app, "ede-view");
  if (auto status = ede::tools::parse_command_line(app, argc, argv)) return *status;

  opt.frame_memory = frame_mib << 20;
  std::string error;
  for (const std::string& d : logs)
    if (!add_root(opt.log_roots, d, "--logs", error)) return fail(error);
  if (scenes.empty()) {
    for (const char* d : {EDE_VIEW_EXAMPLES_DIR, "examples"})
      if (fs::is_directory(d)) {
        scenes.push_back(d);
        break;
      }
  }
  for (const std::string& d : scenes)
    if (!add_root(opt.scene_roots, d, "--scenes", error)) return fail(error);
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (!add_root(opt.log_roots, out_dir, "--out-dir", error)) return fail(error);
  opt.out_dir = opt.log_roots.back().canonical;

  // Frames are a few MB allocated and freed many times a second: keep that memory in the heap instead of
  // mapping and unmapping it each time (every fresh page is a page fault; they cost more than the frame).
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  // One heap for every thread: glibc gives threads arenas of their own (up to 8 per core), each keeping the
  // frames and states it freed, so 128 workers serving large frames grew the process by ~300 MB with ~30 MB
  // in use (test_view_abuse.py); the threads mostly wait on sockets, so they hardly contend for it.
  mallopt(M_ARENA_MAX, 1);

  // Block the signals in every thread (httplib's workers inherit the mask); one thread waits for them.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  ede::view::Server server(opt);
  const int port = server.bind();
  if (port < 0) return fail("cannot listen on " + opt.host + ":" + std::to_string(opt.port) +
                            " (in use, or not an address of this machine). Fix: another --port, or --port 0.");
  std::printf("ede-view: serving http://%s:%d/\n", opt.host.c_str(), port);
  std::printf("ede-view: live runs write their logs to %s\n", opt.out_dir.c_str());
  std::fflush(stdout);
  std::atomic<int> received{0};
  std::atomic<bool> ending{false};
  std::thread waiter([&] {
    int sig = 0;
    sigwait(&signals, &sig);
    if (!ending) received = sig;
    server.stop();
  });
  const bool served = server.serve();
  ending = true;
  if (received == 0) pthread_kill(waiter.native_handle(), SIGTERM);  // wakes the waiter: we end ourselves
  waiter.join();
  if (received) return 128 + received;
  return served ? 0 : fail("the server stopped: " + opt.host + ":" + std::to_string(port));
}

}  // namespace

int main(int argc, char** argv) { return ede::tools::run_tool("ede-view", body, argc, argv); }
