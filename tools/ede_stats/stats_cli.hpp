// What the ede-stats subcommands share: messages and exit codes, opening a log, times typed on the command
// line, and the tail of every subcommand (CSV, then figure).
//
// Exit status: 1 for a problem with the input (a missing log, a time after its end, an unknown species),
// 2 for a command line that parsed but asks for something impossible, like CLI11's own parse errors.
// CSV numbers are exact (17 significant digits: the analysis runs in double whatever the log's scalar
// type, so that reads back exactly); reports use 6. A figure is drawn by a script of tools/plot from the
// CSV the command wrote (a temporary file when no -o was given). Rejected: printing the CSV on stdout
// without -o, which would mix it with the report a user reads.
#pragma once

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ede/ede.hpp"
#include "number_text.hpp"
#include "open_log.hpp"
#include "report_error.hpp"
#include "time_option.hpp"

namespace ede::stats_tool {

// A test's p-value in a report: "< 1e-300" where the tail underflows, else `digits` significant digits.
inline std::string p_value_text(double p, int digits = 6) {
  return p < 1e-300 ? "< 1e-300" : ede::tools::brief(p, digits);
}

inline int fail(const std::string& message) {
  ede::tools::report_error("ede-stats", message);
  return 1;
}

// With `command`, the message and the help it points to are the subcommand's
// ("ede-stats pressure: ... (see ede-stats pressure --help)").
inline int usage_error(const std::string& message, const std::string& command = "") {
  const std::string program = command.empty() ? "ede-stats" : "ede-stats " + command;
  std::fprintf(stderr, "%s: %s (see %s --help)\n", program.c_str(), message.c_str(), program.c_str());
  return 2;
}

inline void warn(const std::string& message) { std::fprintf(stderr, "ede-stats: warning: %s\n", message.c_str()); }

using tools::brief;       // short, for reports
using tools::exact;       // exact, for CSV
using tools::exact_cell;  // exact, NaN as an empty field

// A log (with the warning for an incomplete one) and its overview (disks, end time, event counts).
struct OpenedLog {
  Log log;
  LogOverview overview;
};
Result<OpenedLog> open_log_overview(const std::string& path);

// A time typed after `option` (a number exact in the log's type, or `end`) as the analysis takes it: a
// double within the log. `text` empty: `fallback` ("end" or "0").
Result<double> read_analysis_time(const OpenedLog& opened, const std::string& text, const std::string& option,
                                  const std::string& fallback);

// The species typed after --species ("" for every disk), as an index; the error names the log.
Result<std::int32_t> read_species(const Log& log, const std::string& name);

// The tail of every subcommand, once its numbers are known: the CSV (to -o, or to a temporary file when
// only a figure is asked for), then after_csv if given (hist reports there), then with --plot the figure
// `script` draws (its arguments: the CSV's path, then `args`) and the line "<figure_label><plot>".
struct CsvAndFigure {
  std::string output, plot;                     // -o and --plot as given; either may be empty
  std::string csv;                              // the CSV's text
  std::string script;                           // a script of tools/plot
  std::vector<std::string> args;                // the script's arguments after the CSV's path
  std::string figure_label = {};                // empty: no line naming the figure
  std::function<Status()> after_csv = nullptr;  // may fail; its error is the command's
  std::string extra_csv = {};                   // a second CSV for the script, at extra_csv_arg (hist's curve)
  std::size_t extra_csv_arg = 0;                // its index in args, where "" stands until it is written
};
int write_csv_and_plot(const CsvAndFigure& f);

}  // namespace ede::stats_tool
