// run_plot_script; see plot_runner.hpp. The script runs through run_program (spawn.hpp): no shell, so
// file names with spaces or quotes are safe, and its stderr comes back for the message.
#include "plot_runner.hpp"

#include <unistd.h>

#include "spawn.hpp"

#ifndef EDE_PLOT_DIR
#define EDE_PLOT_DIR "tools/plot"
#endif

namespace ede::tools {

Status run_plot_script(const std::string& script, const std::vector<std::string>& args) {
  const std::string path = std::string(EDE_PLOT_DIR) + "/" + script;
  if (::access(path.c_str(), R_OK) != 0) return Error{"plotting script not found: " + path};
  const bool debian = ::access("/usr/bin/python3", X_OK) == 0;
  SpawnRequest request{{debian ? "/usr/bin/python3" : "python3", path}, !debian, ""};
  request.argv.insert(request.argv.end(), args.begin(), args.end());
  auto run = run_program(request);
  if (!run) return run.error();
  if (run.value().exit_status == 0) return Ok{};
  const std::string& err = run.value().err;
  if (err.find("No module named 'matplotlib'") != std::string::npos)
    return Error{"figures need matplotlib: install python3-matplotlib (scripts/install-deps.sh does)"};
  return Error{"the plotting script " + script + " failed:\n" + err};
}

}  // namespace ede::tools
