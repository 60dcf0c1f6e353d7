// ede-bench's subcommands. Each is a thin command over ede_study (study/) and the public library: it adds
// its subcommand and options to the app, and after parsing runs the study and prints what it measured
// (Markdown tables on stdout, CSV with -o or into --out-dir). The options mean what docs/cli.md says in
// every command: --set key=value overrides a value of every scene the command runs (checked like the
// file's own, before anything runs), -o FILE is the CSV table, --out-dir DIR a folder of outputs.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace ede::bench {

struct Command {
  CLI::App* app;             // the subcommand: run it when it was given
  std::function<int()> run;  // the exit status (options are read after parsing)
};

Command speed_command(CLI::App& app);
Command peers_command(CLI::App& app);
Command log_command(CLI::App& app);
Command stress_command(CLI::App& app);
Command effects_command(CLI::App& app);
Command accuracy_command(CLI::App& app);
Command grow_command(CLI::App& app);
Command setup_command(CLI::App& app);

// --- what the commands share (bench_cli.cpp) ---------------------------------------------------------

// --set key=value (repeatable), into `overrides`.
void add_set_option(CLI::App* app, std::vector<std::string>& overrides);
// Whether `overrides` sets `key` ("stop.events").
bool sets_key(const std::vector<std::string>& overrides, const std::string& key);
// Loads every scene with the overrides (nothing runs); on the first error prints it as every tool does
// (ede-bench: error: ..., or FILE:LINE:COL: error: ...) and returns false.
bool check_scenes(const std::vector<std::string>& scenes, const std::vector<std::string>& overrides);
// Prints a failure as every tool does and returns the exit status of a failed command (1).
int fail(const std::string& message);
// Writes `text` to `path` (a CSV table); false after printing why it could not.
bool write_file(const std::string& path, const std::string& text);

}  // namespace ede::bench
