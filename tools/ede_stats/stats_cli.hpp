// What the hist, species, energy and collisions subcommands share: messages and exit codes, exact numbers,
// output files, times typed on the command line, species by name, and the figure step.
//
// Exit status: 1 for a problem with the input (a missing log, a time after its end, an unknown species),
// 2 for a command line that parsed but asks for something impossible, like CLI11's own parse errors.
// CSV numbers are printed with 17 significant digits (the analysis runs in double whatever the log's
// scalar type, so that reads back exactly); text reports use 6. A figure is drawn by a script of
// tools/plot from the CSV the command wrote (a temporary file when no -o was given).
#pragma once

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "ede/gas_observables.hpp"
#include "ede/log_reader.hpp"
#include "ede/result.hpp"
#include "plot_runner.hpp"

namespace ede::stats_tool {

inline int fail(const std::string& message) {
  std::fprintf(stderr, "ede-stats: error: %s\n", message.c_str());
  return 1;
}

inline int usage_error(const std::string& message) {
  std::fprintf(stderr, "ede-stats: %s (see ede-stats --help)\n", message.c_str());
  return 2;
}

inline void warn(const std::string& message) { std::fprintf(stderr, "ede-stats: warning: %s\n", message.c_str()); }

// Exact (17 digits) for CSV; short (6 digits) for reports.
inline std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}
inline std::string short_num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// An output file, or stdout when the path is empty; close() reports write errors.
class Output {
 public:
  explicit Output(const std::string& path) : path_(path) {
    file_ = path.empty() ? stdout : std::fopen(path.c_str(), "w");
    if (!file_) error_ = "cannot write '" + path + "': " + std::strerror(errno);
  }
  ~Output() {
    if (file_ && file_ != stdout) std::fclose(file_);
  }
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  std::FILE* file() const { return file_; }
  const std::string& error() const { return error_; }
  void write(const std::string& text) { std::fputs(text.c_str(), file_); }
  Status close() {
    const bool failed = std::ferror(file_) != 0;
    const int closed = file_ == stdout ? std::fflush(file_) : std::fclose(file_);
    if (file_ != stdout) file_ = nullptr;
    if (failed || closed != 0)
      return Error{"error while writing '" + (path_.empty() ? std::string("<stdout>") : path_) + "'"};
    return Ok{};
  }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::string error_;
};

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
  Output out(path);
  if (!out.file()) return Error{out.error()};
  out.write(text);
  if (Status s = out.close(); !s) return s.error();
  return path;
}

inline Result<std::shared_ptr<LogReader>> open_log(const std::string& path) {
  auto log = LogReader::open(path);
  if (!log) return log.error();
  if (log.value()->damaged())
    warn(path + " is damaged; analysing it up to the damage (" + log.value()->incomplete_reason() + ")");
  else if (!log.value()->complete())
    warn(path + " is incomplete (" + log.value()->incomplete_reason() + "); analysing it as far as it goes");
  return log;
}

// A time typed by the user: a finite number >= 0 or "end", not after `end`.
inline Result<double> parse_time(const std::string& text, const char* what, double end) {
  if (text == "end") return end;
  char* stop = nullptr;
  errno = 0;
  const double t = std::strtod(text.c_str(), &stop);
  if (text.empty() || stop != text.c_str() + text.size() || !std::isfinite(t) || errno == ERANGE)
    return Error{std::string(what) + " '" + text + "' is not a time (a number such as 0.5, or 'end')"};
  if (t < 0) return Error{std::string(what) + " '" + text + "' is negative"};
  if (t > end)
    return Error{std::string(what) + " " + text + " is after the end of the log (t = " + num(end) +
                 "); --at end gives the last state"};
  return t;
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

inline Status plot(const std::string& script, const std::vector<std::string>& args) {
  return tools::run_plot_script(script, args);
}

}  // namespace ede::stats_tool
