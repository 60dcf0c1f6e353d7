// Quantities per run (see quantities.hpp): one parse of each name into (family, field, time), then one
// library call per family that needs the log (log_series, measure_crater, measure_pressure), each made
// at most once per time (sheared_viscosity once per window start).
#include "quantities.hpp"

#include <algorithm>
#include <complex>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace ede::sweep {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<std::string> kSummary = {"events",      "pair_collisions", "wall_collisions", "collisions_per_particle",
                                           "sim_time",    "energy_initial",  "energy_final",    "energy_ratio"};
const std::vector<std::string> kPressure = {"z_virial", "z_wall",          "z_henderson", "z_kolafa_rottner",
                                            "virial",   "wall",            "kT",          "packing_fraction"};
const std::vector<std::string> kStructure = {"psi6"};
// sheared_viscosity's numbers (a Lees-Edwards run); @T starts the window at T (default: the log's start).
const std::vector<std::string> kViscosity = {"eta", "eta_reduced", "rate_reduced", "kT", "shear_stress",
                                             "enskog", "enskog_reduced", "packing_fraction"};

struct Name {
  std::string family;  // summary, energy, collisions, crater, pressure
  std::string field;
  std::optional<double> time;
};

bool known(const std::vector<std::string>& list, const std::string& s) {
  return std::find(list.begin(), list.end(), s) != list.end();
}

Result<Name> parse(const std::string& text) {
  Name n;
  std::string head = text;
  if (const auto at = text.find('@'); at != std::string::npos) {
    head = text.substr(0, at);
    try {
      std::size_t used = 0;
      n.time = std::stod(text.substr(at + 1), &used);
      if (used != text.size() - at - 1) throw std::invalid_argument("");
    } catch (const std::exception&) {
      return Error{"collect: '" + text + "': the time after @ is not a number. Fix: e.g. energy@0.5"};
    }
  }
  const auto dot = head.find('.');
  n.family = dot == std::string::npos ? head : head.substr(0, dot);
  n.field = dot == std::string::npos ? "" : head.substr(dot + 1);
  std::string base = n.field;
  if (base.size() > 6 && base.compare(base.size() - 6, 6, "_error") == 0) base.resize(base.size() - 6);
  const bool ok = (dot == std::string::npos && known(kSummary, head) && !n.time && (n.family = "summary", n.field = head, true)) ||
                  ((n.family == "energy" || n.family == "collisions") && n.field.empty() && n.time) ||
                  (n.family == "crater" && known(crater_metric_names(), n.field)) ||
                  (n.family == "pressure" && known(kPressure, base) && !n.time) ||
                  (n.family == "structure" && known(kStructure, n.field)) ||
                  (n.family == "viscosity" && known(kViscosity, base));
  if (ok) return n;
  std::string names;
  for (const auto& s : kSummary) names += s + ", ";
  names += "energy@T, collisions@T, crater.M[@T] (M: ";
  for (const auto& s : crater_metric_names()) names += s + " ";
  names += "), pressure.P[_error] (P: z_virial z_wall z_henderson z_kolafa_rottner virial wall kT packing_fraction)";
  names += ", structure.psi6[@T], viscosity.V[_error][@T0] (sheared runs; V: eta eta_reduced rate_reduced kT "
           "shear_stress enskog enskog_reduced packing_fraction; T0: the window's start)";
  return Error{"collect: '" + text + "' is not a quantity. Known: " + names};
}

double summary_field(const RunSummary& s, const std::string& f) {
  if (f == "events") return double(s.counts.events());
  if (f == "pair_collisions") return double(s.counts.of(EventKind::Pair));
  if (f == "wall_collisions") return double(s.counts.of(EventKind::Wall));
  if (f == "collisions_per_particle") return s.collisions_per_particle;
  if (f == "sim_time") return s.sim_time;
  if (f == "energy_initial") return s.energy_initial;
  if (f == "energy_final") return s.energy_final;
  if (f == "energy_ratio") return s.energy_initial != 0 ? s.energy_final / s.energy_initial : kNaN;
  return kNaN;
}

double pressure_field(const PressureReport& r, const std::string& field) {
  const bool error = field.size() > 6 && field.compare(field.size() - 6, 6, "_error") == 0;
  const std::string f = error ? field.substr(0, field.size() - 6) : field;
  if (f == "packing_fraction") return error ? 0.0 : r.packing_fraction;
  if (f == "z_henderson") return error ? 0.0 : henderson_z(r.packing_fraction);
  if (f == "z_kolafa_rottner") return error ? 0.0 : kolafa_rottner_z(r.packing_fraction);  // NaN above 0.707
  const PressureSeries* s = f == "z_virial" ? &r.z_virial : f == "virial" ? &r.virial : f == "kT" ? &r.kT
                            : f == "z_wall"  ? &r.z_wall
                                             : &r.wall_mean;
  if ((f == "z_wall" || f == "wall") && !r.has_walls()) return kNaN;
  return error ? s->stats.error : s->stats.mean;
}

double viscosity_field(const ShearedViscosity& v, const std::string& field) {
  const bool error = field.size() > 6 && field.compare(field.size() - 6, 6, "_error") == 0;
  const std::string f = error ? field.substr(0, field.size() - 6) : field;
  if (f == "eta") return error ? v.viscosity_error : v.viscosity;
  if (f == "eta_reduced") return error ? v.reduced_viscosity_error : v.reduced_viscosity;
  if (f == "kT") return error ? v.kT_error : v.kT;
  if (f == "shear_stress") return error ? v.shear_stress_error : v.shear_stress;
  if (error) return 0.0;  // the rest are not measured with an error
  if (f == "rate_reduced") return v.reduced_rate;
  if (f == "enskog") return v.enskog;
  if (f == "enskog_reduced") return v.enskog_reduced;
  return v.packing_fraction;
}

}  // namespace

Status check_quantities(const std::vector<std::string>& names) {
  for (const std::string& n : names)
    if (auto p = parse(n); !p) return p.error();
  return Ok{};
}

Result<std::vector<double>> collect_quantities(const std::vector<std::string>& names, const RunSummary& summary,
                                               const Log& log) {
  std::vector<Name> parsed;
  std::vector<double> series_times;
  for (const std::string& n : names) {
    auto p = parse(n);
    if (!p) return p.error();
    if (p.value().family == "energy" || p.value().family == "collisions") series_times.push_back(*p.value().time);
    parsed.push_back(p.value());
  }
  std::optional<LogSeries> series;
  if (!series_times.empty()) {
    std::vector<double> sorted = series_times;
    std::sort(sorted.begin(), sorted.end());
    auto s = log_series(log, sorted);
    if (!s) return s.error();
    series = std::move(s).value();
  }
  std::map<std::optional<double>, CraterMeasurement> craters;
  std::optional<PressureReport> pressure;
  std::map<std::optional<double>, ShearedViscosity> viscosities;
  std::vector<double> out;
  for (const Name& n : parsed) {
    if (n.family == "summary") {
      out.push_back(summary_field(summary, n.field));
    } else if (n.family == "energy" || n.family == "collisions") {
      const auto k = std::size_t(std::find(series->time.begin(), series->time.end(), *n.time) - series->time.begin());
      out.push_back(n.family == "energy" ? series->mean_kinetic_energy(k) : series->collisions_per_particle(k));
    } else if (n.family == "crater") {
      if (!craters.count(n.time)) {
        CraterRequest request;
        request.at = n.time;
        auto m = measure_crater(log, request);
        if (!m) return m.error();
        craters.emplace(n.time, std::move(m).value());
      }
      const auto& names_list = crater_metric_names();
      const auto k = std::size_t(std::find(names_list.begin(), names_list.end(), n.field) - names_list.begin());
      out.push_back(crater_metric_values(craters.at(n.time))[k]);
    } else if (n.family == "structure") {  // psi6: the global bond order |<psi6_j>| at T (default: the end)
      auto state = n.time ? log.state_at(*n.time) : log.state_at_end();
      if (!state) return state.error();
      const std::vector<std::complex<double>> p = psi6(state.value());
      std::complex<double> sum = 0;
      for (const auto& v : p) sum += v;
      out.push_back(p.empty() ? kNaN : std::abs(sum) / double(p.size()));
    } else if (n.family == "viscosity") {
      if (!viscosities.count(n.time)) {
        ShearedOptions o;
        o.from = n.time;
        auto v = sheared_viscosity(log, o);
        if (!v) return v.error();
        viscosities.emplace(n.time, std::move(v).value());
      }
      out.push_back(viscosity_field(viscosities.at(n.time), n.field));
    } else {
      if (!pressure) {
        auto r = measure_pressure(log);
        if (!r) return r.error();
        pressure = std::move(r).value();
      }
      out.push_back(pressure_field(*pressure, n.field));
    }
  }
  return out;
}

}  // namespace ede::sweep
