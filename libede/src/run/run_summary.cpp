// Building and formatting RunSummary (ede/simulation.hpp, run/run_summary.hpp). JSON is written with
// nlohmann-json (an ordered_json keeps the keys in the order below, which scripts and people read): it
// escapes strings, replaces bytes that are not UTF-8 (a file name may hold any), writes non-finite numbers
// as null and doubles in the shortest form that reads back to the same double. Rejected: the JSON written
// by hand here before (its own escaping and number rules to keep right).
#include "run/run_summary.hpp"

#include <sys/resource.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "ede/number_text.hpp"

namespace ede {

namespace {

template <class T>
const char* scalar_name() {
  if constexpr (std::is_same_v<T, float>) return "float";
  if constexpr (std::is_same_v<T, double>) return "double";
  if constexpr (std::is_same_v<T, long double>) return "long double";
  return "float128";
}

}  // namespace

double RunSummary::events_per_second() const {
  return wall_seconds > 0 ? double(counts.events() - events_before) / wall_seconds : 0;
}
double RunSummary::collisions_per_second() const {
  return wall_seconds > 0 ? double(counts.collisions() - collisions_before) / wall_seconds : 0;
}

std::uint64_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return std::uint64_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

template <class T>
RunSummary summarize(const EngineApi<T>& engine, double momentum_initial_x, double momentum_initial_y) {
  RunSummary s;
  s.scalar = scalar_name<T>();
  s.effects = engine.effects();
  s.stall_message = engine.stall_message();
  s.disks = engine.particles().size();
  s.counts = engine.counts();
  s.collisions_per_particle = s.disks ? 2.0 * double(s.counts.of(EventKind::Pair)) / double(s.disks) : 0;
  s.sim_time = double(engine.time());
  s.energy_initial = engine.initial_kinetic_energy();
  s.energy_final = kinetic_energy(engine.particles(), engine.time());
  s.potential_final = engine.potential_energy();
  s.momentum_initial[0] = momentum_initial_x;
  s.momentum_initial[1] = momentum_initial_y;
  momentum(engine.particles(), engine.time(), s.momentum_final[0], s.momentum_final[1]);
  s.engine_bytes = engine.memory_bytes();
  s.peak_rss_bytes = peak_rss_bytes();
  return s;
}

template RunSummary summarize<float>(const EngineApi<float>&, double, double);
template RunSummary summarize<double>(const EngineApi<double>&, double, double);
template RunSummary summarize<long double>(const EngineApi<long double>&, double, double);
#if EDE_HAVE_FLOAT128
template RunSummary summarize<__float128>(const EngineApi<__float128>&, double, double);
#endif

std::string to_text(const RunSummary& s) {
  std::ostringstream o;
  const auto& c = s.counts;
  o << "scene            " << s.scene << " (seed " << s.seed << ", " << s.disks << " disks, " << s.scalar << ")\n"
    << "effects          " << s.effects << "\n"
    << "ended            " << s.status << "\n";
  if (!s.stall_message.empty()) o << "                 " << s.stall_message << "\n";
  if (!s.setup_note.empty()) o << "setup            " << s.setup_note << "\n";
  o << "events           " << c.events() << " (pair " << c.of(EventKind::Pair) << ", wall " << c.of(EventKind::Wall)
    << ", cell " << c.of(EventKind::Cell) << ", wrap " << c.of(EventKind::Wrap) << ", action "
    << c.of(EventKind::Action)
    << (c.of(EventKind::Segment) ? ", segment " + std::to_string(c.of(EventKind::Segment)) : std::string())
    << (c.of(EventKind::Step) ? ", step " + std::to_string(c.of(EventKind::Step)) : std::string())
    << (c.of(EventKind::Thermostat) ? ", thermostat " + std::to_string(c.of(EventKind::Thermostat)) : std::string())
    << (c.of(EventKind::Shear) ? ", shear " + std::to_string(c.of(EventKind::Shear)) : std::string())
    << "); samples " << c.of(EventKind::Sample) << ", stale predictions " << c.stale
    << ", TC-elastic " << c.tc_elastic << "\n"
    << "collisions/disk  " << brief(s.collisions_per_particle) << "\n"
    << "simulated time   " << brief(s.sim_time) << "\n"
    << "wall time        " << brief(s.wall_seconds) << " s (setup " << brief(s.setup_seconds) << " s)"
    << (s.events_before ? " in this process, which resumed the run after event " + std::to_string(s.events_before)
                        : std::string())
    << "\n"
    << "speed            " << brief(s.events_per_second() / 1e6) << " M events/s, "
    << brief(s.collisions_per_second() / 1e6) << " M collisions/s\n"
    << "kinetic energy   " << brief(s.energy_initial) << " -> " << brief(s.energy_final) << " (ratio "
    << brief(s.energy_initial > 0 ? s.energy_final / s.energy_initial : 0) << ")\n";
  if (s.stepped)
    o << "potential energy " << brief(s.potential_final) << " at the end (total " << brief(s.energy_final + s.potential_final)
      << ")\n";
  o
    << "momentum         (" << brief(s.momentum_initial[0]) << ", " << brief(s.momentum_initial[1])
    << ") -> (" << brief(s.momentum_final[0]) << ", " << brief(s.momentum_final[1]) << ")\n"
    << "memory           engine " << brief(double(s.engine_bytes) / 1048576) << " MiB ("
    << brief(s.disks ? double(s.engine_bytes) / double(s.disks) : 0) << " B/disk), peak RSS "
    << brief(double(s.peak_rss_bytes) / 1048576) << " MiB\n";
  return o.str();
}

std::string to_json(const RunSummary& s) {
  using Json = nlohmann::ordered_json;
  const auto& c = s.counts;
  Json j;
  j["scene"] = s.scene;
  j["seed"] = s.seed;
  j["disks"] = s.disks;
  j["scalar"] = s.scalar;
  j["effects"] = s.effects;
  j["status"] = s.status;
  j["stall_message"] = s.stall_message;
  j["events"] = c.events();
  j["events_by_kind"] = {{"pair", c.of(EventKind::Pair)},
                         {"wall", c.of(EventKind::Wall)},
                         {"cell", c.of(EventKind::Cell)},
                         {"wrap", c.of(EventKind::Wrap)},
                         {"action", c.of(EventKind::Action)}};
  if (c.of(EventKind::Segment)) j["events_by_kind"]["segment"] = c.of(EventKind::Segment);
  if (c.of(EventKind::Thermostat)) j["events_by_kind"]["thermostat"] = c.of(EventKind::Thermostat);
  if (c.of(EventKind::Shear)) j["events_by_kind"]["shear"] = c.of(EventKind::Shear);
  j["samples"] = c.of(EventKind::Sample);
  j["stale_predictions"] = c.stale;
  j["tc_elastic"] = c.tc_elastic;
  j["collisions"] = c.collisions();
  j["collisions_per_particle"] = s.collisions_per_particle;
  j["sim_time"] = s.sim_time;
  j["wall_seconds"] = s.wall_seconds;
  j["setup_seconds"] = s.setup_seconds;
  if (!s.setup_note.empty()) j["setup_note"] = s.setup_note;
  j["events_before"] = s.events_before;
  j["events_per_second"] = s.events_per_second();
  j["collisions_per_second"] = s.collisions_per_second();
  j["energy_initial"] = s.energy_initial;
  j["energy_final"] = s.energy_final;
  if (s.stepped) j["potential_final"] = s.potential_final;
  j["momentum_initial"] = Json::array({s.momentum_initial[0], s.momentum_initial[1]});
  j["momentum_final"] = Json::array({s.momentum_final[0], s.momentum_final[1]});
  j["engine_bytes"] = s.engine_bytes;
  j["peak_rss_bytes"] = s.peak_rss_bytes;
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace ede
