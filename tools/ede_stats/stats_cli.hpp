// What the ede-stats subcommands share: messages and exit codes, exact numbers, times typed on the command
// line, opening a log, species by name, time grids, and the tail of every subcommand (CSV, then figure).
//
// Exit status: 1 for a problem with the input (a missing log, a time after its end, an unknown species),
// 2 for a command line that parsed but asks for something impossible, like CLI11's own parse errors.
// CSV numbers are printed with 17 significant digits (the analysis runs in double whatever the log's
// scalar type, so that reads back exactly); text reports use 6. A figure is drawn by a script of
// tools/plot from the CSV the command wrote (a temporary file when no -o was given).
#pragma once

#include <unistd.h>

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ede/analysis.hpp"
#include "open_log.hpp"
#include "report_error.hpp"
#include "log/log_reader.hpp"
#include "analysis/log_series.hpp"
#include "ede/error.hpp"
#include "exact_text.hpp"
#include "output_file.hpp"
#include "plot_runner.hpp"

namespace ede::stats_tool {

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

using tools::brief;   // 6 digits, for reports
using tools::exact;   // 17 digits, for CSV
using tools::Output;  // -o FILE, or stdout

// A scratch file for a plotting script's input, removed when it goes out of scope.
class TempFile {
 public:
  explicit TempFile(const std::string& suffix) {
    std::string name = "/tmp/ede-stats-XXXXXX" + suffix;
    const int fd = mkstemps(name.data(), int(suffix.size()));
    if (fd >= 0) {
      ::close(fd);
      path_ = name;
    }
  }
  ~TempFile() {
    if (!path_.empty()) std::remove(path_.c_str());
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// `text` as the whole of a file; the error names the file.
inline Status write_file(const std::string& path, const std::string& text) {
  Output out(path);
  if (!out.file()) return Error{out.error()};
  out.write(text);
  return out.close();
}

// Writes `text` to the -o file, and returns the path a plotting script should read it from: the -o
// file, or a temporary one (kept alive by `temp`) when only a figure was asked for.
inline Result<std::string> write_csv(const std::string& output, bool for_plot, const std::string& text,
                                     std::unique_ptr<TempFile>& temp) {
  std::string path = output;
  if (path.empty()) {
    if (!for_plot) return std::string();
    temp = std::make_unique<TempFile>(".csv");
    if (temp->path().empty()) return Error{"cannot create a temporary file for the figure's data"};
    path = temp->path();
  }
  if (Status s = write_file(path, text); !s) return s.error();
  return path;
}

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
};

inline int write_csv_and_plot(const CsvAndFigure& f) {
  std::unique_ptr<TempFile> temp;
  auto path = write_csv(f.output, !f.plot.empty(), f.csv, temp);
  if (!path) return fail(path.error().message);
  if (f.after_csv)
    if (Status s = f.after_csv(); !s) return fail(s.error().message);
  if (f.plot.empty()) return 0;
  std::vector<std::string> args = {path.value()};
  args.insert(args.end(), f.args.begin(), f.args.end());
  if (Status p = tools::run_plot_script(f.script, args); !p) return fail(p.error().message);
  if (!f.figure_label.empty()) std::printf("%s%s\n", f.figure_label.c_str(), f.plot.c_str());
  return 0;
}

inline Result<std::shared_ptr<LogReader>> open_log(const std::string& path) {
  auto log = ede::tools::open_log_warning("ede-stats", path);
  if (!log) return log.error();
  return log;  // open_log_warning has said so if it is incomplete or damaged
}

// A log opened with open_log, and its overview (disks, end time, event counts).
struct OpenedLog {
  std::shared_ptr<LogReader> log;
  LogOverview overview;
};

inline Result<OpenedLog> open_log_overview(const std::string& path) {
  auto log = open_log(path);
  if (!log) return log.error();
  auto overview = log_overview(log.value());
  if (!overview) return overview.error();
  return OpenedLog{log.value(), overview.value()};
}

// 0, dt, 2 dt, ... and `end` itself; empty when the grid would have more than max_points points.
inline std::vector<double> grid_to_end(double end, double dt, std::size_t max_points) {
  std::vector<double> times = time_grid(0, end, dt, max_points);
  if (!times.empty() && times.back() < end) times.push_back(end);
  return times;
}

// A time typed by the user: a finite number >= 0 or "end", not after `end`.
inline Result<double> parse_time(const std::string& text, const char* what, double end) {
  const tools::ReadTime<double> t = tools::read_time<double>(text);
  switch (t.kind) {
    case tools::TimeText::End: return end;
    case tools::TimeText::NotANumber:
      return Error{std::string(what) + " '" + text + "' is not a time (a number such as 0.5, or 'end')"};
    case tools::TimeText::Negative: return Error{std::string(what) + " '" + text + "' is negative"};
    case tools::TimeText::Number: break;
  }
  if (t.value > end)
    return Error{std::string(what) + " " + text + " is after the end of the log (t = " + exact(end) +
                 "); --at end gives the last state"};
  return t.value;
}

// The index of a species by name; "" means every disk (kAllSpecies). The error lists the species.
inline Result<std::int32_t> species_index(const LogHeaderInfo& h, const std::string& name) {
  if (name.empty()) return kAllSpecies;
  std::string known;
  for (std::size_t k = 0; k < h.species_names.size(); ++k) {
    if (h.species_names[k] == name) return std::int32_t(k);
    known += (k ? ", " : "") + h.species_names[k];
  }
  return Error{"the log has no species '" + name + "'; its species are: " + known};
}

}  // namespace ede::stats_tool
