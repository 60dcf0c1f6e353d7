// run_plot_script; see plot_runner.hpp. Arguments are passed without a shell (fork + execv), so file
// names with spaces or quotes are safe.
//
// The scripts are looked for beside the running program first (<bin>/EDE_PLOT_DIR_FROM_BIN, i.e.
// <prefix>/share/ede/plot for an installed tool, found through /proc/self/exe), then in the source tree
// the tool was built from (EDE_PLOT_DIR), so an installed tool plots from any folder and a tool in build/
// uses the scripts being edited. Rejected: only the compile-time source path (an installed tool broke once
// the source tree moved), an environment variable (one more thing to set).
#include "plot_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#ifndef EDE_PLOT_DIR
#define EDE_PLOT_DIR "tools/plot"
#endif
#ifndef EDE_PLOT_DIR_FROM_BIN
#define EDE_PLOT_DIR_FROM_BIN "../share/ede/plot"
#endif

namespace ede::tools {

namespace {

std::string python() { return access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3"; }

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The places a script may be, in the order they are tried.
std::vector<std::string> script_candidates(const std::string& script) {
  std::vector<std::string> places;
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) places.push_back((self.parent_path() / EDE_PLOT_DIR_FROM_BIN / script).lexically_normal().string());
  places.push_back(std::string(EDE_PLOT_DIR) + "/" + script);
  return places;
}

}  // namespace

Status run_plot_script(const std::string& script, const std::vector<std::string>& args) {
  std::string path, tried;
  for (const std::string& place : script_candidates(script)) {
    if (access(place.c_str(), R_OK) == 0) {
      path = place;
      break;
    }
    tried += (tried.empty() ? "" : " or ") + place;
  }
  if (path.empty()) return Error{"plotting script not found: " + tried};
  char err_template[] = "/tmp/ede-plot-XXXXXX";
  const int err_fd = mkstemp(err_template);
  if (err_fd < 0) return Error{"cannot create a temporary file for the plotting script's messages"};
  const pid_t pid = fork();
  if (pid < 0) return Error{"cannot start python3"};
  if (pid == 0) {
    dup2(err_fd, 2);
    std::vector<std::string> argv_s = {python(), path};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    std::fprintf(stderr, "cannot run %s\n", argv[0]);
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  close(err_fd);
  const std::string err = read_all(err_template);
  std::remove(err_template);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return Ok{};
  if (err.find("No module named 'matplotlib'") != std::string::npos)
    return Error{"figures need matplotlib: install python3-matplotlib (scripts/install-deps.sh does)"};
  return Error{"the plotting script " + script + " failed:\n" + err};
}

}  // namespace ede::tools
