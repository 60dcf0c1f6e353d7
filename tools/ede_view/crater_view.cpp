// The crater view; see crater_view.hpp.
#include "crater_view.hpp"

#include <nlohmann/json.hpp>

namespace ede::view {
namespace {

DiskPositions positions(const State& s) { return {s.x.to_doubles(), s.y.to_doubles(), s.radius.to_doubles()}; }

}  // namespace

std::optional<CraterBase> crater_base(const Log& log) {
  auto bed = select_bed(log, "");
  if (!bed) return std::nullopt;
  const LogInfo& info = log.info();
  bool named = false, projectile = false;
  for (const std::string& s : bed.value().species) named = named || s == "bed";
  auto start = log.state_at_event(0);
  if (!start) return std::nullopt;
  const State& s = start.value();
  std::vector<std::size_t> count(s.species_names.size(), 0);
  for (std::int32_t k : s.species) ++count[std::size_t(k)];
  for (std::size_t k = 0; k < count.size(); ++k) projectile = projectile || count[k] == 1;
  if (!named && !projectile) return std::nullopt;
  CraterBase base;
  base.bed = std::move(bed).value();
  base.before = positions(s);
  base.before_time = double(s.time);
  base.box = {info.lx, info.ly, info.boundary == BoundaryKind::Periodic};
  return base;
}

Result<CraterBase> with_before(const CraterBase& base, const Log& log, Time before) {
  auto state = log.state_at(before);
  if (!state) return state.error();
  CraterBase b = base;
  b.before = positions(state.value());
  b.before_time = double(state.value().time);
  return b;
}

std::string crater_field(const CraterBase& base, const State& state) {
  auto report = analyze_crater(base.before, positions(state), base.bed.is_bed, base.box, CraterSettings{});
  if (!report) return ",\"crater\":" + nlohmann::json{{"error", report.error().message}}.dump();
  const CraterReport& r = report.value();
  const CraterMetrics& m = r.metrics;
  return ",\"crater\":" + nlohmann::json{{"before_time", base.before_time},
                                         {"bin_width", r.after.bin_width},
                                         {"before", r.before.height},
                                         {"after", r.after.height},
                                         {"depth", m.depth},
                                         {"deepest_x", m.deepest_x},
                                         {"has_crater", m.has_crater},
                                         {"left", m.left},
                                         {"right", m.right},
                                         {"width", m.width},
                                         {"area", m.area},
                                         {"displaced", r.displaced.size()},
                                         {"bed_disks", r.bed_disks},
                                         {"detached", r.after.detached},
                                         {"bed_radius", r.lengths.bed_radius}}
                                  .dump();
}

std::string crater_info_field(const std::optional<CraterBase>& base) {
  if (!base) return "";
  return ",\"crater\":" + nlohmann::json{{"bed", base->bed.species}, {"reason", base->bed.reason}}.dump();
}

}  // namespace ede::view
