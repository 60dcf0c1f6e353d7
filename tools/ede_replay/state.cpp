// ede-replay state: the state at a time (or after a number of events, or right after a number of
// collisions per disk) as exact CSV.
//
// The time is read in the log's own scalar type, so `--at 0.5` in a float log means the float nearest 0.5,
// exactly what a float engine stopping at stop.time = 0.5 reaches; `--at end` is the time the run reached.
// The CSV is written by the same function as ede-sim --final-state, so the two are byte-identical at the
// same time.
#include <optional>

#include "output_file.hpp"
#include "replay_tool.hpp"

namespace ede::replay_tool {

namespace {

struct StateOptions {
  std::string log, at, output;
  std::optional<std::uint64_t> event;
  std::optional<double> collisions;
  bool csv = false;  // CSV is the only format; the flag is accepted for scripts that spell it out
};

Result<State> state_of(const Log& log, const StateOptions& opt) {
  if (opt.event) return log.state_at_event(*opt.event);
  if (opt.collisions) {
    auto n = log.events_after_collisions({*opt.collisions});
    if (!n) return n.error();
    return log.state_at_event(n.value()[0]);
  }
  auto t = tools::read_time(log, opt.at, "--at");
  if (!t) return t.error();
  return t.value().end ? log.state_at_end() : log.state_at(t.value().t);
}

int run_state(const StateOptions& opt) {
  if (int(!opt.at.empty()) + int(opt.event.has_value()) + int(opt.collisions.has_value()) != 1)
    return usage_error("state: give one of --at T (or --at end), --event N and --collisions-per-disk C");
  auto log = open_log(opt.log);
  if (!log) return fail(log.error().message);
  auto state = state_of(log.value(), opt);
  if (!state) return fail(state.error().message);
  tools::Output out(opt.output);  // a temporary renamed into place once complete; stdout without -o
  if (!out.file()) return fail(out.error());
  write_state_csv(out.file(), state.value());
  if (Status s = out.close(); !s) return fail(s.error().message);
  return 0;
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
  auto* collisions = cmd->add_option("--collisions-per-disk", opt->collisions,
                                     "the state right after the pair collision that brings the count to ceil(C N / 2), "
                                     "as [[actions]] collisions_per_disk counts")
                         ->check(CLI::NonNegativeNumber);
  at->excludes(event), at->excludes(collisions), event->excludes(collisions);
  cmd->add_flag("--csv", opt->csv, "write CSV: id,species,x,y,vx,vy,radius,mass (the default and only format)");
  cmd->add_option("-o,--output", opt->output, "write to this file instead of stdout");
  return [opt] { return run_state(*opt); };
}

}  // namespace ede::replay_tool
