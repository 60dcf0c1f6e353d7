// Running a built tool from a test: command line in, exit status and captured stdout/stderr out; and what
// the tool tests share around it: scratch files, logs written by ede-sim, lines and CSV fields of output.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

// Unique per process: ctest runs test cases in parallel processes, which must not share scratch files.
inline std::string temp_path(const std::string& name) {
  return std::string(EDE_BINARY_DIR) + "/tests/" + std::to_string(::getpid()) + "-" + name;
}

// Runs `tool args` (args already shell-quoted as needed) with stdout and stderr captured to temp files.
// With `seconds`, the run is killed after that long (status 124 from timeout(1): a hang).
inline ToolRun run_tool(const std::string& tool, const std::string& args, const std::string& tag, int seconds = 0) {
  const std::string base = std::string(EDE_BINARY_DIR) + "/tests/tool-" + std::to_string(::getpid()) + "-" + tag;
  const std::string limit = seconds > 0 ? "timeout -k 5 " + std::to_string(seconds) + " " : "";
  const std::string cmd = limit + tool_path(tool) + " " + args + " >" + base + ".out 2>" + base + ".err";
  const int raw = std::system(cmd.c_str());
  ToolRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = read_file(base + ".out");
  r.err = read_file(base + ".err");
  return r;
}

// Runs `ede-sim SCENE -q OPTIONS -o LOG` (options such as " --set stop.time=1", each with a leading
// space) and requires it to succeed; returns the log's path.
inline std::string sim_log(const std::string& scene, const std::string& options, const std::string& log,
                           const std::string& tag) {
  const ToolRun r = run_tool("ede-sim", scene + " -q" + options + " -o " + log, tag);
  INFO(scene << options << ": " << r.err);
  REQUIRE(r.status == 0);
  return log;
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The fields of a CSV row without quoting; a trailing comma ends in an empty field.
inline std::vector<std::string> csv_fields(const std::string& row) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(row);
  while (std::getline(in, field, ',')) out.push_back(field);
  if (!row.empty() && row.back() == ',') out.push_back("");
  return out;
}

}  // namespace ede::test
