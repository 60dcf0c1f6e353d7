// Running a built tool from a test: command line in, exit status and captured stdout/stderr out.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace ede::test {

struct ToolRun {
  int status = -1;  // exit status, or 128 + signal
  std::string out, err;
};

inline std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string tool_path(const std::string& name) { return std::string(EDE_BINARY_DIR) + "/tools/" + name; }
inline std::string source_path(const std::string& rel) { return std::string(EDE_SOURCE_DIR) + "/" + rel; }

// Runs `tool args` (args already shell-quoted as needed) with stdout and stderr captured to temp files.
inline ToolRun run_tool(const std::string& tool, const std::string& args, const std::string& tag) {
  const std::string base = std::string(EDE_BINARY_DIR) + "/tests/tool-" + std::to_string(::getpid()) + "-" + tag;
  const std::string cmd = tool_path(tool) + " " + args + " >" + base + ".out 2>" + base + ".err";
  const int raw = std::system(cmd.c_str());
  ToolRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = read_file(base + ".out");
  r.err = read_file(base + ".err");
  return r;
}

}  // namespace ede::test
