// The measuring options shared by `ede-crater LOG` and `ede-crater scan`, and the one function that
// measures a log with them.
//
// Lengths are typed as "0.002" (box units) or "0.5r" (bed radii), so a default that scales with the grain
// size and an absolute value read the same way on the command line. --at is parsed in the log's scalar type
// (exact_text.hpp, as ede-replay does), so --at 0.25 means exactly the value of T a run stopping at
// stop.time = 0.25 reaches.
// Rejected: separate --threshold-radii options, which double every option for one unit.
#include <memory>
#include <optional>

#include "crater_tool.hpp"
#include "open_log.hpp"
#include "log/log_reader.hpp"
#include "core/scalar_dispatch.hpp"

namespace ede::crater_tool {

namespace {

Result<CraterLength> parse_length(const std::string& text, const char* option) {
  std::string number = text;
  CraterLength l;
  if (!number.empty() && (number.back() == 'r' || number.back() == 'R')) {
    l.in_bed_radii = true;
    number.pop_back();
  }
  const std::optional<double> value = tools::parse_exact<double>(number);
  if (!value || *value < 0)
    return Error{std::string(option) + " '" + text +
                 "' is not a length: give a number >= 0 in box units (0.002) or in bed radii (0.5r)"};
  l.value = *value;
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
  app.add_option("--bed-species", o.bed_species,
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

Result<MeasuredLog> measure_log(const std::string& path, const MeasureOptions& o) {
  auto settings = settings_from(o);
  if (!settings) return settings.error();
  auto log = ede::tools::open_log_warning("ede-crater", path);
  if (!log) return log.error();
  std::shared_ptr<const LogReader> reader = log.value();
  auto crater = with_scalar(reader->header().scalar, [&]<class T>() -> Result<CraterMeasurement> {
    CraterRequest req;
    req.energy_fraction = o.energy_fraction;
    req.bed_species = o.bed_species;
    req.settings = settings.value();
    req.curve_points = o.points;
    if (!o.at.empty()) {
      const tools::ReadTime<T> t = tools::read_time<T>(o.at);
      if (t.kind == tools::TimeText::NotANumber || t.kind == tools::TimeText::Negative)
        return Error{"--at '" + o.at + "' is not a time: give a number >= 0 (such as 0.25) or 'end'"};
      req.at_end = t.kind == tools::TimeText::End;
      if (!req.at_end) req.at = t.value;
    }
    if (!o.before.empty()) {
      const tools::ReadTime<T> t = tools::read_time<T>(o.before);
      if (t.kind != tools::TimeText::Number)
        return Error{"--before '" + o.before + "' is not a time: give a number >= 0 (such as 0.4)"};
      req.before = t.value;
    }
    return measure_crater(reader, req);
  });
  if (!crater) return crater.error();
  MeasuredLog m{std::move(crater).value(), {}, reader->header().disks, to_string(reader->header().scalar)};
  m.run_status = reader->complete() ? reader->final_status() : "incomplete: " + reader->incomplete_reason();
  return m;
}

}  // namespace ede::crater_tool
