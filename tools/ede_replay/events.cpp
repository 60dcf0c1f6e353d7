// ede-replay events: the logged events in a time or index range, as CSV.
//
//   index,time,kind,i,j,vix,viy,vjx,vjy
// kind is pair, wall, wrap, action, segment, thermostat (i: the disk whose velocity was redrawn, j -1) or
// shear (i crossed the sliding edge of a Lees-Edwards box, j 2 top or 3 bottom; vix, viy its new velocity);
// j is the partner (pair), the wall (0 left, 1 right, 2 bottom,
// 3 top) or the wrap direction (0 right, 1 left, 2 top, 3 bottom: the edge crossed); the velocities are
// the post-event ones (pair: both disks; wall: disk i). Columns a kind does not have are empty. Numbers
// are exact (float 9, double 17, long double 21 digits). --full adds the positions at the event and the
// velocities before it: xi,yi,xj,yj,vix_before,viy_before,vjx_before,vjy_before, then the collision's
// statistics (ede/collision_stats.hpp, in double, 17 digits): impulse_x,impulse_y,impulse (on disk i,
// m_i (v_i' - v_i); pair, wall, segment), impact_parameter (b / (r_i + r_j), signed; pair), relative_speed
// (|v_i - v_j| before; wall, segment: |v_i|), normal_speed (approach speed; wall, segment: |v_i . n|),
// tangential_speed (signed; pair). A log of rotating (rough) disks adds, last, the angular velocities after
// the event, omega_i,omega_j, and with --full those before it, omega_i_before,omega_j_before (pair: both
// disks; wall, segment, wrap: disk i). Rejected: a separate --collisions flag, one more flag for what --full
// already means (everything known about an event).
// A time range [T0, T1] seeks to the state just before T0 from the nearest keyframe, then reads events
// until one is later than T1: the cost is the range, not the log.
#include <optional>

#include "ede/collision_stats.hpp"

#include "ede/number_text.hpp"
#include "output_file.hpp"
#include "replay_tool.hpp"

namespace ede::replay_tool {

namespace {

struct EventsOptions {
  std::string log, from, to, output;
  std::optional<std::uint64_t> from_event, to_event;
  bool full = false;
};

bool has_disk(EventKind k) {
  return k == EventKind::Pair || k == EventKind::Wall || k == EventKind::Wrap || k == EventKind::Segment ||
         k == EventKind::Step || k == EventKind::Thermostat || k == EventKind::Shear;
}
bool has_vi(EventKind k) {
  return k == EventKind::Pair || k == EventKind::Wall || k == EventKind::Segment || k == EventKind::Step ||
         k == EventKind::Thermostat || k == EventKind::Shear;
}

// One row; the columns an event kind does not have are left empty.
// The collision's statistics (empty for wraps and actions; pair-only fields empty for walls).
std::string statistics(const CollisionRecord& c) {
  const auto d = [](double v) { return exact_double(v); };
  if (!c.pair && !c.wall) return ",,,,,,";
  return d(c.impulse_x) + "," + d(c.impulse_y) + "," + d(c.impulse) + "," + (c.pair ? d(c.impact_parameter) : "") + "," +
         d(c.relative_speed) + "," + d(c.normal_speed) + "," + (c.pair ? d(c.tangential_speed) : "");
}

std::string row(const Log& log, const Event& e, const CollisionDisks* disks, bool spins) {
  const bool full = disks != nullptr;
  const auto x = [&](Time v) { return exact(log, v); };
  const auto two = [](const std::string& a, const std::string& b) { return a + "," + b; };
  const bool pair = e.kind == EventKind::Pair || e.kind == EventKind::Step;  // both disks' columns
  std::string s = std::to_string(e.index) + "," + x(e.time) + "," + to_string(e.kind) + "," +
                  (has_disk(e.kind) ? two(std::to_string(e.i), std::to_string(e.j)) : ",") + "," +
                  (has_vi(e.kind) ? two(x(e.vix), x(e.viy)) : ",") + "," + (pair ? two(x(e.vjx), x(e.vjy)) : ",");
  if (full)
    s += "," + (has_disk(e.kind) ? two(x(e.xi), x(e.yi)) : ",") + "," + (pair ? two(x(e.xj), x(e.yj)) : ",") + "," +
         (has_disk(e.kind) ? two(x(e.vix_before), x(e.viy_before)) : ",") + "," +
         (pair ? two(x(e.vjx_before), x(e.vjy_before)) : ",") + "," + statistics(collision_record(e, *disks));
  if (spins) {
    s += "," + (has_disk(e.kind) ? x(e.omega_i) : "") + "," + (pair ? x(e.omega_j) : "");
    if (full) s += "," + (has_disk(e.kind) ? x(e.omega_i_before) : "") + "," + (pair ? x(e.omega_j_before) : "");
  }
  return s + "\n";
}

Result<EventRange> range_of(const Log& log, const EventsOptions& opt) {
  EventRange range;
  if (opt.from_event || opt.to_event) {
    range.from_event = opt.from_event.value_or(0);
    if (opt.to_event) range.to_event = *opt.to_event + 1;  // --to-event is inclusive
    return range;
  }
  for (const auto& [text, slot, name] : {std::tuple{&opt.from, &range.from_time, "--from"},
                                         std::tuple{&opt.to, &range.to_time, "--to"}}) {
    if (text->empty() || *text == "end") continue;
    auto t = parse_time(log, *text, name);
    if (!t) return t.error();
    *slot = t.value();
  }
  return range;
}

int run_events(const EventsOptions& opt) {
  if (opt.from_event && opt.to_event && *opt.to_event < *opt.from_event)
    return usage_error("events: --to-event is before --from-event");
  auto log = open_log(opt.log);
  if (!log) return fail(log.error().message);
  auto range = range_of(log.value(), opt);
  if (!range) return fail(range.error().message);
  if (range.value().from_time && range.value().to_time && *range.value().to_time < *range.value().from_time)
    return usage_error("events: --to " + opt.to + " is before --from " + opt.from);
  tools::Output output(opt.output);  // a temporary renamed into place once complete; stdout without -o
  std::FILE* out = output.file();
  if (!out) return fail(output.error());
  std::optional<CollisionDisks> disks;
  if (opt.full) {
    auto d = collision_disks(log.value());
    if (!d) return fail(d.error().message);
    disks = std::move(d).value();
  }
  const bool spins = log.value().info().rotates;
  std::string header = opt.full ? "index,time,kind,i,j,vix,viy,vjx,vjy,xi,yi,xj,yj,vix_before,viy_before,vjx_before,"
                                  "vjy_before,impulse_x,impulse_y,impulse,impact_parameter,relative_speed,normal_speed,"
                                  "tangential_speed"
                                : "index,time,kind,i,j,vix,viy,vjx,vjy";
  if (spins) header += opt.full ? ",omega_i,omega_j,omega_i_before,omega_j_before" : ",omega_i,omega_j";
  std::fputs((header + "\n").c_str(), out);
  const Status s = log.value().for_each_event(range.value(), [&](const Event& e) {
    std::fputs(row(log.value(), e, disks ? &*disks : nullptr, spins).c_str(), out);
    return std::ferror(out) == 0;  // a full disk ends the walk; close() names the file
  });
  if (!s) return fail(s.error().message);
  if (Status c = output.close(); !c) return fail(c.error().message);
  return 0;
}

}  // namespace

Command add_events_command(CLI::App& app) {
  auto opt = std::make_shared<EventsOptions>();
  CLI::App* cmd = app.add_subcommand("events",
                                     "the logged events in a range, as CSV: "
                                     "index,time,kind,i,j,vix,viy,vjx,vjy (--full: positions, velocities before, impulse, "
                                     "impact parameter, relative speeds)");
  cmd->add_option("log", opt->log, "event log (any file name)")->required();
  auto* from =
      cmd->add_option("--from", opt->from, "first time T0 (events with T0 <= time), exact in the log's scalar type");
  auto* to = cmd->add_option("--to", opt->to, "last time T1 (events with time <= T1), or 'end'");
  auto* from_event = cmd->add_option("--from-event", opt->from_event, "first event index (0-based)");
  auto* to_event = cmd->add_option("--to-event", opt->to_event, "last event index (included)");
  for (auto* by_time : {from, to})
    for (auto* by_index : {from_event, to_event}) by_time->excludes(by_index);
  cmd->add_flag("--full", opt->full,
                "add the positions at each event, the velocities just before it and the collision's impulse on disk i, "
                "impact parameter b/(r_i+r_j) and relative speeds before (docs/cli.md)");
  cmd->add_option("-o,--output", opt->output, "write to this file instead of stdout");
  return [opt] { return run_events(*opt); };
}

}  // namespace ede::replay_tool
