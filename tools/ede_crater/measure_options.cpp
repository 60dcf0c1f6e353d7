// The measuring options shared by `ede-crater LOG` and `ede-crater scan`, and the one function that
// measures a log with them.
//
// Lengths are typed as "0.002" (box units) or "0.5r" (bed radii), so a default that scales with the grain
// size and an absolute value read the same way on the command line. --at and --before are read in the
// log's scalar type (time_option.hpp, as every tool reads times), so --at 0.25 means exactly the value of
// T a run stopping at stop.time = 0.25 reaches.
// Rejected: separate --threshold-radii options, which double every option for one unit.
#include <memory>
#include <optional>

#include "crater_tool.hpp"
#include "open_log.hpp"
#include "time_option.hpp"

namespace ede::crater_tool {

namespace {

Result<CraterLength> parse_length(const std::string& text, const char* option) {
  std::string number = text;
  CraterLength l;
  if (!number.empty() && (number.back() == 'r' || number.back() == 'R')) {
    l.in_bed_radii = true;
    number.pop_back();
  }
  const Result<Time> value = parse_exact(number, ScalarKind::Double);
  if (!value || value.value() < 0)
    return Error{std::string(option) + " '" + text +
                 "' is not a length: give a number >= 0 in box units (0.002) or in bed radii (0.5r)"};
  l.value = double(value.value());
  return l;
}

}  // namespace

void add_measure_options(CLI::App& app, MeasureOptions& o) {
  auto* at = app.add_option("--at", o.at, "measure at this time (exact in the log's scalar type), or 'end'");
  auto* fraction = app.add_option("--energy-fraction", o.energy_fraction,
                                  "measure when this fraction of the initial kinetic energy remains "
                                  "(default 0.1; the log's end if it never does)");
  fraction->check(CLI::Range(0.0, 1.0));
  at->excludes(fraction);
  app.add_option("--before", o.before,
                 "compare with the bed at this time instead of the start (under gravity: after the bed has "
                 "settled, before the impact)");
  app.add_option("--species", o.species,
                 "the bed's species (default: 'bed', else every species of more than one disk)");
  app.add_option("--threshold", o.threshold,
                 "displaced = moved by more than this; box units (0.002) or bed radii (0.5r; the default)");
  app.add_option("--drop-threshold", o.drop_threshold,
                 "the crater is where the surface fell by more than this (default 1r)");
  app.add_option("--bin-width", o.bin_width, "width of the surface profile's bins (default 2r)");
  app.add_option("--link-gap", o.link_gap,
                 "bed disks whose rims are at most this far apart are linked (default 2r); disks not linked "
                 "to the bed's bottom are ejecta and do not make the surface");
  app.add_flag("--keep-detached", o.keep_detached, "every bed disk makes the surface, ejecta too");
  app.add_option("--curve-points", o.points, "points of the energy curve (default 501)")->check(CLI::Range(2, 1000000));
}

Result<CraterSettings> settings_from(const MeasureOptions& o) {
  CraterSettings s;
  const std::pair<const std::string*, std::pair<CraterLength*, const char*>> lengths[] = {
      {&o.threshold, {&s.displacement_threshold, "--threshold"}},
      {&o.drop_threshold, {&s.drop_threshold, "--drop-threshold"}},
      {&o.bin_width, {&s.bin_width, "--bin-width"}},
      {&o.link_gap, {&s.link_gap, "--link-gap"}},
  };
  for (const auto& [text, target] : lengths) {
    auto l = parse_length(*text, target.second);
    if (!l) return l.error();
    *target.first = l.value();
  }
  if (s.bin_width.value == 0) return Error{"--bin-width must be > 0"};
  s.exclude_detached = !o.keep_detached;
  return s;
}

namespace {

// The request the options make for this log: times read in its scalar type.
Result<CraterRequest> request_for(const Log& log, const MeasureOptions& o) {
  auto settings = settings_from(o);
  if (!settings) return settings.error();
  CraterRequest req;
  req.energy_fraction = o.energy_fraction;
  req.bed_species = o.species;
  req.settings = settings.value();
  req.curve_points = o.points;
  if (!o.at.empty()) {
    auto at = tools::read_time(log, o.at, "--at");
    if (!at) return at.error();
    req.at_end = at.value().end;
    if (!req.at_end) req.at = at.value().t;
  }
  if (!o.before.empty()) {
    auto before = tools::read_time(log, o.before, "--before", false);
    if (!before) return before.error();
    req.before = before.value().t;
  }
  return req;
}

}  // namespace

Result<MeasuredLog> measure_log(const std::string& path, const MeasureOptions& o) {
  auto log = tools::open_log_warning("ede-crater", path);
  if (!log) return log.error();
  auto request = request_for(log.value(), o);
  if (!request) return request.error();
  auto crater = measure_crater(log.value(), request.value());
  if (!crater) return crater.error();
  const LogInfo& info = log.value().info();
  return MeasuredLog{std::move(crater).value(),
                     info.complete ? info.final_status : "incomplete: " + info.incomplete_reason, info.disks,
                     to_string(info.scalar)};
}

}  // namespace ede::crater_tool
