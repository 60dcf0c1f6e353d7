// The one way tools print an error: "TOOL: error: MESSAGE". Messages from the scene loader already read
// "FILE:LINE:COL: error: ..." (the compilers' convention, which editors jump to); those get only the tool's
// name in front, not a second "error:".
#pragma once

#include <cstdio>
#include <string>

namespace ede::tools {

inline void report_error(const char* tool, const std::string& message) {
  const bool located = message.find(": error: ") != std::string::npos;
  std::fprintf(stderr, "%s: %s%s\n", tool, located ? "" : "error: ", message.c_str());
}

}  // namespace ede::tools
