// What the structure and transport subcommands of ede-stats (gr, sk, psi6, msd, vacf) share: the frame
// window typed on the command line (--at, or --from/--to/--frames), and the tail that prints a summary
// (lines, or with --json one JSON object with the summary and every column), writes the table as CSV and
// draws it with tools/plot/plot_table.py. Rejected: one file per subcommand repeating these ~100 lines.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "stats_cli.hpp"

namespace ede::stats_tool {

struct FrameCli {
  std::string at, from, to;
  std::size_t frames = 1;
  void add(CLI::App* cmd, const char* what);
  // FrameTimes of the log: --at T alone, or --frames equally spaced times from --from to --to.
  Result<FrameTimes> read(const Log& log) const;
};

// A window for the transport commands: --from (default the start), --to (default end).
Result<std::pair<std::optional<double>, std::optional<double>>> read_window(const Log& log, const std::string& from,
                                                                             const std::string& to);

struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  void add(const std::string& name, std::vector<double> values) {
    names.push_back(name);
    columns.push_back(std::move(values));
  }
  std::string csv() const;
};

struct Summary {
  std::vector<std::pair<std::string, std::string>> text;   // label, value as printed
  std::vector<std::pair<std::string, double>> numbers;     // key, value for --json
  void add(const std::string& label, const std::string& value) { text.emplace_back(label, value); }
  void number(const std::string& key, double value) { numbers.emplace_back(key, value); }
};

struct TableOutput {
  std::string output, plot;
  bool json = false;
  void add(CLI::App* cmd, const char* csv_help, const char* plot_help);
};

// The figure plot_table.py draws: x against the y columns (with an error column, maybe), linear or
// log-log of |y|, and reference curves (columns named in `dashed`).
// Another script (e.g. plot_impacts.py, two panels) takes the CSV, the figure's path and the title only.
struct Figure {
  std::string x = {}, ys = {}, error = {}, dashed = {}, title = {}, xlabel = {}, ylabel = {}, scale = "linear";
  std::string script = "plot_table.py";
};

bool plot_name_ok(const std::string& path);
// Prints the summary (or the JSON), writes the CSV and draws the figure.
int finish_table(const std::string& command, const TableOutput& out, const Summary& s, const Table& t, const Figure& f);

}  // namespace ede::stats_tool
