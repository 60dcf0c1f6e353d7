// ede-replay events: the logged events in a time or index range, as CSV.
//
//   index,time,kind,i,j,vix,viy,vjx,vjy
// kind is pair, wall, wrap or action; j is the partner (pair), the wall (0 left, 1 right, 2 bottom,
// 3 top) or the wrap direction (0 right, 1 left, 2 top, 3 bottom: the edge crossed); the velocities are
// the post-event ones (pair: both disks; wall: disk i). Columns a kind does not have are empty. Numbers
// are exact (float 9, double 17, long double 21 digits).
// A time range [T0, T1] seeks to the state just before T0 (every event with time < T0 applied) from the
// nearest keyframe, then reads events until one is later than T1: the cost is the range, not the log.
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "replay_tool.hpp"

namespace ede::replay_tool {

namespace {

struct EventsOptions {
  std::string log, from, to, output;
  std::optional<std::uint64_t> from_event, to_event;
};

// Seeks to the first event with time >= t0 and returns its index.
template <class T>
Result<std::uint64_t> seek_before(Replay<T>& replay, T t0) {
  Status s =
      t0 > T(0) ? replay.seek_time(std::nextafter(t0, -std::numeric_limits<T>::infinity())) : replay.seek_event(0);
  if (!s) return s.error();
  return replay.events_applied();
}

template <class T>
int write_events(const EventsOptions& opt, const std::shared_ptr<LogReader>& log) {
  auto made = Replay<T>::create(log);
  if (!made) return fail(made.error().message);
  Replay<T>& replay = *made.value();
  const std::uint64_t total = log->total_events();
  std::uint64_t first = 0, end = total;
  T t1 = std::numeric_limits<T>::infinity();
  if (opt.from_event || opt.to_event) {
    first = opt.from_event.value_or(0);
    if (opt.to_event) end = std::min(total, *opt.to_event + 1);
    if (first > total)
      return fail(log->path() + ": --from-event " + std::to_string(first) + " is beyond the log's " +
                  std::to_string(total) + " events");
  } else {
    T t0 = T(0);
    if (!opt.from.empty()) {
      auto parsed = parse_time<T>(opt.from, "--from");
      if (!parsed) return fail(parsed.error().message);
      t0 = parsed.value();
    }
    if (!opt.to.empty()) {
      auto parsed = parse_time<T>(opt.to, "--to");
      if (!parsed) return fail(parsed.error().message);
      t1 = parsed.value();
    }
    if (t1 < t0) return usage_error("events: --to " + opt.to + " is before --from " + opt.from);
    first = total;  // after the end of the log: no events, only the header
    if (t0 <= replay.final_time()) {
      auto at = seek_before(replay, t0);
      if (!at) return fail(at.error().message);
      first = at.value();
    }
  }
  Output out(opt.output);
  if (!out.file()) return fail(out.error());
  std::fputs(kEventsCsvHeader, out.file());
  if (first < end) {
    const Status s = replay.for_each_event(first, end, [&](const ReplayedEvent<T>& e) {
      if (e.time > t1) return false;
      std::fputs(event_csv_row(e).c_str(), out.file());
      return true;
    });
    if (!s) {
      (void)out.close();
      return fail(s.error().message);
    }
  }
  if (Status s = out.close(); !s) return fail(s.error().message);
  return 0;
}

int run_events(const EventsOptions& opt) {
  if (opt.from_event && opt.to_event && *opt.to_event < *opt.from_event)
    return usage_error("events: --to-event is before --from-event");
  auto log = open_log(opt.log);
  if (!log) return fail(log.error().message);
  return tools::with_scalar(log.value()->header().scalar, [&]<class T>() { return write_events<T>(opt, log.value()); });
}

}  // namespace

Command add_events_command(CLI::App& app) {
  auto opt = std::make_shared<EventsOptions>();
  CLI::App* cmd = app.add_subcommand("events",
                                     "the logged events in a range, as CSV: "
                                     "index,time,kind,i,j,vix,viy,vjx,vjy");
  cmd->add_option("log", opt->log, "event log (any file name)")->required();
  auto* from =
      cmd->add_option("--from", opt->from, "first time T0 (events with T0 <= time), exact in the log's scalar type");
  auto* to = cmd->add_option("--to", opt->to, "last time T1 (events with time <= T1)");
  auto* from_event = cmd->add_option("--from-event", opt->from_event, "first event index (0-based)");
  auto* to_event = cmd->add_option("--to-event", opt->to_event, "last event index (included)");
  for (auto* by_time : {from, to})
    for (auto* by_index : {from_event, to_event}) by_time->excludes(by_index);
  cmd->add_option("-o,--output", opt->output, "write to this file instead of stdout");
  return [opt] { return run_events(*opt); };
}

}  // namespace ede::replay_tool
