// run_plot_script; see plot_runner.hpp. The script runs through run_program (process.hpp): no shell, so
// file names with spaces or quotes are safe, and its stderr comes back for the message.
//
// The scripts are looked for beside the running program first (<bin>/EDE_PLOT_DIR_FROM_BIN, i.e.
// <prefix>/share/ede/plot for an installed tool, found through /proc/self/exe), then in the source tree
// the tool was built from (EDE_PLOT_DIR), so an installed tool plots from any folder and a tool in build/
// uses the scripts being edited. Rejected: only the compile-time source path (an installed tool broke once
// the source tree moved), an environment variable (one more thing to set).
#include "plot_runner.hpp"

#include <cstdio>

#include "file_checks.hpp"
#include "output_file.hpp"

#include <unistd.h>

#include <filesystem>

#include "process.hpp"

#ifndef EDE_PLOT_DIR
#define EDE_PLOT_DIR "tools/plot"
#endif
#ifndef EDE_PLOT_DIR_FROM_BIN
#define EDE_PLOT_DIR_FROM_BIN "../share/ede/plot"
#endif

namespace ede::tools {

namespace {

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
    if (::access(place.c_str(), R_OK) == 0) {
      path = place;
      break;
    }
    tried += (tried.empty() ? "" : " or ") + place;
  }
  if (path.empty()) return Error{"plotting script not found: " + tried};
  const bool debian = ::access("/usr/bin/python3", X_OK) == 0;
  SpawnRequest request;
  request.argv = {debian ? "/usr/bin/python3" : "python3", path};
  request.search_path = !debian;
  request.argv.insert(request.argv.end(), args.begin(), args.end());
  auto run = run_program(request);
  if (!run) return run.error();
  if (run.value().exit_status == 0) return Ok{};
  const std::string& err = run.value().err;
  if (err.find("No module named 'matplotlib'") != std::string::npos)
    return Error{"figures need matplotlib: install python3-matplotlib (scripts/install-deps.sh does)"};
  return Error{"the plotting script " + script + " failed:\n" + err};
}

Status run_plot_script_to(const std::string& script, std::vector<std::string> args, const std::string& figure) {
  if (Status s = check_not_an_input(figure); !s) return s;
  const std::string temp = temporary_name(figure);
  for (std::string& a : args)
    if (a == figure) a = temp;
  if (Status s = run_plot_script(script, args); !s) {
    std::remove(temp.c_str());
    return s;
  }
  return commit_temporary(temp, figure);
}

}  // namespace ede::tools
