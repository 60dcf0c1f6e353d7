// Running a plotting script of tools/plot on a CSV: the tools write numbers, matplotlib draws them.
//
// Scripts run with Debian's /usr/bin/python3 (where python3-matplotlib installs), falling back to python3
// on PATH; a missing matplotlib gives a message saying what to install, not a Python traceback.
// Rejected: drawing in C++ (a plotting library to link for figures matplotlib already draws well).
#pragma once

#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::tools {

// Runs `python3 <plot dir>/<script> <args...>` (the installed scripts beside the program, else the source
// tree's tools/plot); the error carries the script's stderr.
Status run_plot_script(const std::string& script, const std::vector<std::string>& args);

// The same for a script that writes the figure `figure` (one of args): it writes a temporary file beside
// it (same extension, so matplotlib picks the format), renamed over `figure` only when the script
// succeeded; never over one of the tool's inputs.
Status run_plot_script_to(const std::string& script, std::vector<std::string> args, const std::string& figure);

}  // namespace ede::tools
