// Parsing a tool's command line with CLI11, the same way in every tool: --help and --version print and exit
// 0; a command line CLI11 rejects prints CLI11's message and exits 2, the status every tool gives a bad
// command line. Rejected: CLI11_PARSE, which exits with CLI11's own codes instead (106, 109, ...).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace ede::tools {

// Adds --version to the app and every subcommand (call after adding them): "ede-sim, ede 0.1.0".
void add_version_flags(CLI::App& app, const std::string& tool);

// Parses; the exit status when the program should stop here (0 after --help, 2 after a parse error),
// nothing when it should go on.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv);

// The same for a tool with subcommands and a default one: a first argument that names no subcommand (and
// is not -h or --help) is the start of the default subcommand's arguments, so `ede-replay LOG --at T`
// reads as `ede-replay state LOG --at T`.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const std::string& default_subcommand);

}  // namespace ede::tools
