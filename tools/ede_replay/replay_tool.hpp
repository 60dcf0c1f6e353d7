// What the ede-replay subcommands share: registration, messages, exact numbers, event rows and comparison.
//
// Each subcommand lives in its own file and registers itself on the CLI11 app with add_*_command, which
// returns the function main calls once the command line is parsed. Numbers are printed and times typed
// by a user read exactly in the log's scalar type (exact_text.hpp); comparisons are bitwise.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/event.hpp"
#include "open_log.hpp"
#include "report_error.hpp"
#include "log/log_reader.hpp"
#include "replay/replay.hpp"
#include "exact_text.hpp"
#include "output_file.hpp"
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
  ede::tools::report_error("ede-replay", message);
  return 1;
}

// A command line that parsed but asks for something impossible: exit status 2, like a parse error.
inline int usage_error(const std::string& message) {
  std::fprintf(stderr, "ede-replay: %s (see ede-replay --help)\n", message.c_str());
  return 2;
}

inline Result<std::shared_ptr<LogReader>> open_log(const std::string& path) {
  return tools::open_log_warning("ede-replay", path);
}

using tools::exact;   // the digits that read back to the same value of T (exact_text.hpp)
using tools::Output;  // -o FILE, or stdout (output_file.hpp)

// A time given on the command line, read exactly in T: the whole text must be one finite number >= 0.
template <class T>
Result<T> parse_time(const std::string& text, const char* what) {
  const std::optional<T> v = tools::parse_exact<T>(text);
  if (!v) return Error{std::string(what) + " '" + text + "' is not a number (a time such as 0.5 or 1e-3)"};
  if (*v < T(0)) return Error{std::string(what) + " '" + text + "' is negative"};
  return *v;
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

}  // namespace ede::replay_tool
