// What the ede-replay subcommands share: registration, messages, exact numbers, event rows and comparison.
//
// Each subcommand lives in its own file and registers itself on the CLI11 app with add_*_command, which
// returns the function main calls once the command line is parsed. Numbers are printed with the digits
// that read back to the identical value of the log's scalar type (float 9, double 17, long double 21),
// like the state CSV, and parsed with the matching strto* so a time typed by a user means exactly that
// value of T; comparisons are bitwise.
#pragma once

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>

#include "ede/event.hpp"
#include "ede/log_reader.hpp"
#include "ede/replay.hpp"
#include "scalar_dispatch.hpp"

namespace ede::replay_tool {

using Command = std::function<int()>;

Command add_state_command(CLI::App& app);
Command add_info_command(CLI::App& app);
Command add_events_command(CLI::App& app);
Command add_verify_command(CLI::App& app);
Command add_diff_command(CLI::App& app);

// An error about the input: message on stderr, exit status 1.
inline int fail(const std::string& message) {
  std::fprintf(stderr, "ede-replay: error: %s\n", message.c_str());
  return 1;
}

// A command line that parsed but asks for something impossible: exit status 2, like a parse error.
inline int usage_error(const std::string& message) {
  std::fprintf(stderr, "ede-replay: %s (see ede-replay --help)\n", message.c_str());
  return 2;
}

inline Result<std::shared_ptr<LogReader>> open_log(const std::string& path) { return LogReader::open(path); }

// Exact text of a scalar.
inline std::string exact(float v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.9g", double(v));
  return b;
}
inline std::string exact(double v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}
inline std::string exact(long double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.21Lg", v);
  return b;
}

inline float parse_number(const char* s, char** end, float) { return std::strtof(s, end); }
inline double parse_number(const char* s, char** end, double) { return std::strtod(s, end); }
inline long double parse_number(const char* s, char** end, long double) { return std::strtold(s, end); }

// A time given on the command line, read exactly in T: the whole text must be one finite number >= 0.
template <class T>
Result<T> parse_time(const std::string& text, const char* what) {
  char* end = nullptr;
  errno = 0;
  const T v = parse_number(text.c_str(), &end, T{});
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(double(v)) || errno == ERANGE)
    return Error{std::string(what) + " '" + text + "' is not a number (a time such as 0.5 or 1e-3)"};
  if (v < T(0)) return Error{std::string(what) + " '" + text + "' is negative"};
  return v;
}

// Bitwise equality of two scalars (long double: its 10 significant bytes, not the padding).
template <class T>
bool same_bits(T a, T b) {
  constexpr std::size_t width = std::is_same_v<T, long double> ? 10 : sizeof(T);
  return std::memcmp(&a, &b, width) == 0;
}

inline const char* kind_word(EventKind k) {
  switch (k) {
    case EventKind::Pair: return "pair";
    case EventKind::Wall: return "wall";
    case EventKind::Wrap: return "wrap";
    case EventKind::Action: return "action";
    default: return to_string(k);
  }
}

inline bool has_disk(EventKind k) { return k == EventKind::Pair || k == EventKind::Wall || k == EventKind::Wrap; }
inline bool has_vi(EventKind k) { return k == EventKind::Pair || k == EventKind::Wall; }

constexpr const char* kEventsCsvHeader = "index,time,kind,i,j,vix,viy,vjx,vjy\n";

// One row of the events CSV; the columns an event kind does not have are left empty.
template <class T>
std::string event_csv_row(const ReplayedEvent<T>& e) {
  const auto pair_of = [](const std::string& a, const std::string& b) { return a + "," + b; };
  return std::to_string(e.index) + "," + exact(e.time) + "," + kind_word(e.kind) + "," +
         (has_disk(e.kind) ? pair_of(std::to_string(e.i), std::to_string(e.j)) : ",") + "," +
         (has_vi(e.kind) ? pair_of(exact(e.vix), exact(e.viy)) : ",") + "," +
         (e.kind == EventKind::Pair ? pair_of(exact(e.vjx), exact(e.vjy)) : ",") + "\n";
}

// An event in words, for reports: "t = 0.25, pair 3 17, v_i = (1, 2), v_j = (3, 4)".
template <class T>
std::string describe(const ReplayedEvent<T>& e) {
  static const char* const walls[] = {"left", "right", "bottom", "top"};
  static const char* const wraps[] = {"right", "left", "top", "bottom"};
  std::string s = "t = " + exact(e.time) + ", " + kind_word(e.kind);
  const bool known_j = e.j >= 0 && e.j < 4;
  switch (e.kind) {
    case EventKind::Pair: s += " of disks " + std::to_string(e.i) + " and " + std::to_string(e.j); break;
    case EventKind::Wall:
      s += " of disk " + std::to_string(e.i) + " on the " + (known_j ? walls[e.j] : std::to_string(e.j)) + " wall";
      break;
    case EventKind::Wrap:
      s += " of disk " + std::to_string(e.i) + " across the " + (known_j ? wraps[e.j] : std::to_string(e.j)) + " edge";
      break;
    default: break;
  }
  if (has_vi(e.kind)) s += ", v_i = (" + exact(e.vix) + ", " + exact(e.viy) + ")";
  if (e.kind == EventKind::Pair) s += ", v_j = (" + exact(e.vjx) + ", " + exact(e.vjy) + ")";
  return s;
}

// The first field in which two events differ ("" if they are identical): time, kind and disks, then
// the post-event velocities the kind has, bitwise.
template <class T>
std::string first_difference(const ReplayedEvent<T>& a, const ReplayedEvent<T>& b) {
  if (!same_bits(a.time, b.time)) return "time";
  if (a.kind != b.kind) return "kind";
  if (a.i != b.i) return "disk i";
  if (a.j != b.j) return a.kind == EventKind::Pair ? "disk j" : a.kind == EventKind::Wall ? "wall" : "direction";
  if (has_vi(a.kind) && !same_bits(a.vix, b.vix)) return "vix";
  if (has_vi(a.kind) && !same_bits(a.viy, b.viy)) return "viy";
  if (a.kind == EventKind::Pair && !same_bits(a.vjx, b.vjx)) return "vjx";
  if (a.kind == EventKind::Pair && !same_bits(a.vjy, b.vjy)) return "vjy";
  return "";
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

}  // namespace ede::replay_tool
