// Building and formatting RunSummary (ede/simulation.hpp, run/run_summary.hpp). JSON is written by hand:
// keys are fixed identifiers, strings are escaped, non-finite numbers become null.
#include "run/run_summary.hpp"

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/number_text.hpp"

namespace ede {

namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += char(c);
    }
  }
  return out + "\"";
}

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
  o << "events           " << c.events() << " (pair " << c.of(EventKind::Pair) << ", wall " << c.of(EventKind::Wall)
    << ", cell " << c.of(EventKind::Cell) << ", wrap " << c.of(EventKind::Wrap) << ", action "
    << c.of(EventKind::Action) << "); samples " << c.of(EventKind::Sample) << ", stale predictions " << c.stale
    << ", TC-elastic " << c.tc_elastic << "\n"
    << "collisions/disk  " << short_number(s.collisions_per_particle) << "\n"
    << "simulated time   " << short_number(s.sim_time) << "\n"
    << "wall time        " << short_number(s.wall_seconds) << " s (setup " << short_number(s.setup_seconds) << " s)"
    << (s.events_before ? " in this process, which resumed the run after event " + std::to_string(s.events_before)
                        : std::string())
    << "\n"
    << "speed            " << short_number(s.events_per_second() / 1e6) << " M events/s, "
    << short_number(s.collisions_per_second() / 1e6) << " M collisions/s\n"
    << "kinetic energy   " << short_number(s.energy_initial) << " -> " << short_number(s.energy_final) << " (ratio "
    << short_number(s.energy_initial > 0 ? s.energy_final / s.energy_initial : 0) << ")\n"
    << "momentum         (" << short_number(s.momentum_initial[0]) << ", " << short_number(s.momentum_initial[1])
    << ") -> (" << short_number(s.momentum_final[0]) << ", " << short_number(s.momentum_final[1]) << ")\n"
    << "memory           engine " << short_number(double(s.engine_bytes) / 1048576) << " MiB ("
    << short_number(s.disks ? double(s.engine_bytes) / double(s.disks) : 0) << " B/disk), peak RSS "
    << short_number(double(s.peak_rss_bytes) / 1048576) << " MiB\n";
  return o.str();
}

std::string to_json(const RunSummary& s) {
  std::ostringstream o;
  const auto& c = s.counts;
  o << "{\"scene\": " << quoted(s.scene) << ", \"seed\": " << s.seed << ", \"disks\": " << s.disks
    << ", \"scalar\": " << quoted(s.scalar) << ", \"effects\": " << quoted(s.effects)
    << ", \"status\": " << quoted(s.status) << ", \"stall_message\": " << quoted(s.stall_message)
    << ", \"events\": " << c.events() << ", \"events_by_kind\": {\"pair\": " << c.of(EventKind::Pair)
    << ", \"wall\": " << c.of(EventKind::Wall) << ", \"cell\": " << c.of(EventKind::Cell)
    << ", \"wrap\": " << c.of(EventKind::Wrap) << ", \"action\": " << c.of(EventKind::Action) << "}"
    << ", \"samples\": " << c.of(EventKind::Sample) << ", \"stale_predictions\": " << c.stale
    << ", \"tc_elastic\": " << c.tc_elastic << ", \"collisions\": " << c.collisions()
    << ", \"collisions_per_particle\": " << number(s.collisions_per_particle)
    << ", \"sim_time\": " << number(s.sim_time) << ", \"wall_seconds\": " << number(s.wall_seconds)
    << ", \"setup_seconds\": " << number(s.setup_seconds) << ", \"events_before\": " << s.events_before
    << ", \"events_per_second\": " << number(s.events_per_second())
    << ", \"collisions_per_second\": " << number(s.collisions_per_second())
    << ", \"energy_initial\": " << number(s.energy_initial) << ", \"energy_final\": " << number(s.energy_final)
    << ", \"momentum_initial\": [" << number(s.momentum_initial[0]) << ", " << number(s.momentum_initial[1]) << "]"
    << ", \"momentum_final\": [" << number(s.momentum_final[0]) << ", " << number(s.momentum_final[1]) << "]"
    << ", \"engine_bytes\": " << s.engine_bytes << ", \"peak_rss_bytes\": " << s.peak_rss_bytes << "}";
  return o.str();
}

}  // namespace ede
