// ede-replay state: the state at a time (or after a number of events) as exact CSV.
//
// The time is read in the log's own scalar type, so `--at 0.5` in a float log means the float nearest 0.5,
// exactly what a float engine stopping at stop.time = 0.5 reaches; `--at end` is the time the run reached.
// Replay<T> seeks from the nearest keyframe; the CSV is written by the same function as ede-sim
// --final-state, so the two are byte-identical at the same time.
#include <memory>
#include <optional>
#include <string>

#include "core/state_csv.hpp"
#include "replay_tool.hpp"

namespace ede::replay_tool {

namespace {

struct StateOptions {
  std::string log, at, output;
  std::optional<std::uint64_t> event;
  bool csv = false;  // CSV is the only format; the flag is accepted for scripts that spell it out
};

template <class T>
int write_state(const StateOptions& opt, const std::shared_ptr<LogReader>& log) {
  auto made = Replay<T>::create(log);
  if (!made) return fail(made.error().message);
  Replay<T>& replay = *made.value();
  // The end of a log cut short is its last event: seeking to it by index is exact in every scalar type
  // (Replay::final_time() gives that time rounded to double there, which loses events in long double).
  const bool to_last_event = opt.at == "end" && !log->complete();
  if (opt.event || to_last_event) {
    if (Status s = replay.seek_event(opt.event.value_or(log->total_events())); !s) return fail(s.error().message);
  } else {
    T t = replay.final_time();
    if (opt.at != "end") {
      auto parsed = parse_time<T>(opt.at, "--at");
      if (!parsed) return fail(parsed.error().message);
      t = parsed.value();
    }
    if (t > replay.final_time())
      return fail(log->path() + ": --at " + exact(t) +
                  " is after the end of the log (t = " + exact(replay.final_time()) +
                  (log->complete() ? "" : "; the log is incomplete") + "); --at end gives the last state");
    if (Status s = replay.seek_time(t); !s) return fail(s.error().message);
  }
  Output out(opt.output);
  if (!out.file()) return fail(out.error());
  write_state_csv(out.file(), replay.particles(), replay.time(), log->header().species_names);
  if (Status s = out.close(); !s) return fail(s.error().message);
  return 0;
}

int run_state(const StateOptions& opt) {
  if (opt.at.empty() == !opt.event.has_value())
    return usage_error("state: give either --at T (or --at end) or --event N");
  auto log = open_log(opt.log);
  if (!log) return fail(log.error().message);
  return tools::with_scalar(log.value()->header().scalar, [&]<class T>() { return write_state<T>(opt, log.value()); });
}

}  // namespace

Command add_state_command(CLI::App& app) {
  auto opt = std::make_shared<StateOptions>();
  CLI::App* cmd = app.add_subcommand("state",
                                     "the state at a time or after N events, as exact CSV (the default "
                                     "command: `ede-replay LOG --at T` works too)");
  cmd->add_option("log", opt->log, "event log (any file name)")->required();
  auto* at = cmd->add_option("--at", opt->at, "time T, read exactly in the log's scalar type, or 'end'");
  auto* event = cmd->add_option("--event", opt->event, "the state after the first N events");
  at->excludes(event);
  cmd->add_flag("--csv", opt->csv, "write CSV: id,species,x,y,vx,vy,radius,mass (the default and only format)");
  cmd->add_option("-o,--output", opt->output, "write to this file instead of stdout");
  return [opt] { return run_state(*opt); };
}

}  // namespace ede::replay_tool
