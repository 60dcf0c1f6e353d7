// The analyses as functions of a Log returning plain data with numpy arrays: the same library functions
// the CLI tools call (ede-stats hist/species/energy/collisions/pressure, ede-crater measure), so Python
// and the tools give the same numbers by construction; tests compare them with the tools' --json.
// Each binding converts one report struct field by field; nothing is computed here.
#include <cmath>

#include "bindings.hpp"
#include "shared_log.hpp"
#include "ede/collision_stats.hpp"

namespace ede::python {

namespace {

template <class T>
py::array_t<T> arr(const std::vector<T>& v) {
  return py::array_t<T>({v.size()}, {sizeof(T)}, v.data());  // copies (the report is a temporary)
}

py::dict ks_dict(const KsResult& k) {
  py::dict d;
  d["statistic"] = k.statistic, d["p_value"] = k.p_value, d["n"] = k.n;
  return d;
}

py::dict series_dict(const LogSeries& s) {
  py::dict d;
  d["time"] = arr(s.time);
  d["kinetic_energy"] = arr(s.kinetic_energy);
  py::dict per;
  for (std::size_t k = 0; k < s.species_names.size(); ++k) per[py::str(s.species_names[k])] = arr(s.species_energy[k]);
  d["species_energy"] = per;
  d["species_count"] = s.species_count;
  d["pair_collisions"] = arr(s.pair_collisions), d["wall_collisions"] = arr(s.wall_collisions);
  return d;
}

py::dict block_dict(const PressureSeries& p) {
  py::dict d;
  d["mean"] = p.stats.mean, d["error"] = p.stats.error, d["lag1"] = p.stats.lag1;
  d["blocks"] = arr(p.block);
  d["blocking_error"] = p.blocking.error, d["blocking_converged"] = p.blocking.converged;
  return d;
}

std::int32_t species_index(const SharedLog& log, const py::object& species) {
  if (species.is_none()) return kAllSpecies;
  const auto& names = log.info().species_names;
  const std::string name = py::str(species);
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return std::int32_t(k);
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
  throw Exception(Error{log.info().path + ": no species \"" + name + "\" (the log has: " + known + ")"});
}

std::vector<double> double_times(const py::object& times) {
  return py::cast<std::vector<double>>(py::module_::import("numpy").attr("atleast_1d")(times).attr("astype")("float64").attr("tolist")());
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("distribution",
        [](SharedLog& log, py::object times, py::object species, const std::string& quantity, std::size_t bins) {
          DistributionRequest r;
          r.times = double_times(times);
          r.species = species_index(log, species);
          if (quantity != "speed" && quantity != "energy")
            throw py::value_error("quantity: expected \"speed\" or \"energy\", got \"" + quantity + "\"");
          r.quantity = quantity == "speed" ? Quantity::Speed : Quantity::Energy;
          r.bins = bins;
          const DistributionReport rep = log.read("distribution()", [&](const Log& l) { return measure_distribution(l, r); });
          py::dict d;
          d["disks"] = rep.disks, d["samples"] = rep.samples, d["kT"] = rep.kT;
          d["ks"] = ks_dict(rep.ks);
          d["initial_kT"] = rep.initial_kT, d["initial_ks"] = ks_dict(rep.initial_ks);
          d["edges"] = arr(rep.histogram.edges), d["count"] = arr(rep.histogram.count);
          d["outside"] = rep.histogram.outside;
          d["density"] = arr(rep.density), d["initial_density"] = arr(rep.initial_density);
          d["initial_count"] = arr(rep.initial.count);
          d["law_density"] = arr(rep.law_density);
          d["curve_x"] = arr(rep.curve_x), d["curve_density"] = arr(rep.curve_density);
          return d;
        });
  m.def("energy_curve", [](SharedLog& log, py::object from, py::object to, py::object every, py::object points) {
    EnergyCurveRequest r;
    if (!from.is_none()) r.from = from.cast<double>();
    if (!to.is_none()) r.to = to.cast<double>();
    if (!every.is_none()) r.every = every.cast<double>();
    if (!points.is_none()) r.points = points.cast<std::size_t>();
    const EnergyCurve c = log.read("energy_curve()", [&](const Log& l) { return energy_curve(l, r); });
    py::dict d = series_dict(c.series);
    d["restitution"] = c.restitution, d["spacing"] = c.spacing, d["mean_free_time"] = c.mean_free_time;
    d["initial_energy"] = c.initial_energy, d["haff_tau"] = c.haff_tau;
    d["haff_calibration"] = c.haff_calibration, d["max_drift"] = c.max_drift();
    d["enskog_tau"] = c.enskog_tau, d["enskog_tau_error"] = c.enskog_tau_error, d["enskog_rate0"] = c.enskog_rate0;
    std::vector<double> haff(c.series.time.size());
    for (std::size_t k = 0; k < haff.size(); ++k) haff[k] = c.haff_ratio(k);
    d["haff_ratio"] = arr(haff);
    return d;
  });
  m.def("collision_series", [](SharedLog& log, py::object times) {
    const std::vector<double> t = double_times(times);
    const CollisionSeries c = log.read("collision_series()", [&](const Log& l) { return collision_series(l, t); });
    py::dict d = series_dict(c.series);
    d["reference_speed"] = c.reference_speed;
    d["rate"] = arr(c.rate), d["mean_free_time"] = arr(c.mean_free_time);
    d["enskog_rate"] = arr(c.enskog_rate);
    std::vector<double> slow, medium, fast;
    for (const SpeedClasses& k : c.classes)
      slow.push_back(k.slow_percent), medium.push_back(k.medium_percent), fast.push_back(k.fast_percent);
    d["slow_percent"] = arr(slow), d["medium_percent"] = arr(medium), d["fast_percent"] = arr(fast);
    return d;
  });
  m.def("impacts", [](SharedLog& log, py::object from, py::object to, std::size_t bins) {
    ImpactRequest r;
    if (!from.is_none()) r.range.from_time = from.cast<double>();
    if (!to.is_none()) r.range.to_time = to.cast<double>();
    r.bins = bins;
    const ImpactStatistics s = log.read("impacts()", [&](const Log& l) { return impact_statistics(l, r); });
    py::dict d;
    d["pair_collisions"] = s.pair_collisions, d["wall_collisions"] = s.wall_collisions, d["kT"] = s.kT;
    d["impact_edges"] = arr(s.impact.edges), d["impact_count"] = arr(s.impact.count);
    d["impact_density"] = arr(s.impact_density);
    d["speed_edges"] = arr(s.speed.edges), d["speed_count"] = arr(s.speed.count);
    d["speed_density"] = arr(s.speed_density), d["speed_law"] = arr(s.speed_law);
    d["impact_ks"] = ks_dict(s.impact_ks), d["speed_ks"] = ks_dict(s.speed_ks);
    d["mean_impact"] = s.mean_impact, d["mean_speed"] = s.mean_speed;
    d["mean_impulse"] = s.mean_impulse, d["mean_wall_impulse"] = s.mean_wall_impulse, d["truncated"] = s.truncated;
    return d;
  });
  m.def("species_stats", [](SharedLog& log, py::object times) {
    const std::vector<double> t = double_times(times);
    py::list out;
    for (const SpeciesTable& table : log.read("species_stats()", [&](const Log& l) { return species_tables(l, t); })) {
      for (const SpeciesStats& s : table.rows) {
        py::dict d;
        d["time"] = table.time, d["species"] = s.name, d["n"] = s.n;
        d["mass_min"] = s.mass_min, d["mass_max"] = s.mass_max;
        d["mean_speed"] = s.mean_speed, d["mean_speed_error"] = s.mean_speed_error;
        d["mean_kinetic_energy"] = s.mean_kinetic_energy, d["mean_kinetic_energy_error"] = s.mean_kinetic_energy_error;
        d["kT"] = s.kT;
        out.append(d);
      }
    }
    return out;
  });
  m.def("pressure", [](SharedLog& log, py::object from, py::object to, std::size_t blocks) {
    PressureOptions o;
    if (!from.is_none()) o.from = from.cast<double>();
    if (!to.is_none()) o.to = to.cast<double>();
    o.blocks = blocks;
    const PressureReport p = log.read("pressure()", [&](const Log& l) { return measure_pressure(l, o); });
    py::dict d;
    d["disks"] = p.disks, d["boundary"] = to_string(p.boundary), d["area"] = p.area;
    d["virial_area"] = p.virial_area, d["packing_fraction"] = p.packing_fraction;
    d["t0"] = p.t0, d["t1"] = p.t1, d["mean_free_time"] = p.mean_free_time;
    d["kT"] = block_dict(p.kT), d["virial"] = block_dict(p.virial), d["z_virial"] = block_dict(p.z_virial);
    if (p.has_walls()) {
      d["wall"] = block_dict(p.wall_mean), d["z_wall"] = block_dict(p.z_wall);
      d["wall_minus_virial"] = block_dict(p.wall_minus_virial);
    }
    d["ideal"] = p.ideal(), d["henderson"] = p.henderson();
    d["warnings"] = p.warnings;
    return d;
  });
  m.def("crater", [](SharedLog& log, py::object at, double energy_fraction, const std::string& bed) {
    CraterRequest r;
    if (!at.is_none()) r.at = time_argument(at, log.info().scalar, "crater(at)");
    r.energy_fraction = energy_fraction;
    r.bed_species = bed;
    const CraterMeasurement c = log.read("crater()", [&](const Log& l) { return measure_crater(l, r); });
    py::dict d;
    const auto& names = crater_metric_names();
    const std::vector<double> values = crater_metric_values(c);
    for (std::size_t k = 0; k < names.size(); ++k) d[py::str(names[k])] = values[k];
    d["time"] = c.time, d["before_time"] = c.before_time, d["events"] = c.events;
    d["energy_fraction"] = c.energy_fraction, d["when"] = c.when, d["source"] = to_string(c.source);
    d["has_crater"] = c.report.metrics.has_crater, d["left"] = c.report.metrics.left;
    d["right"] = c.report.metrics.right;
    d["profile_x"] = [&] {
      std::vector<double> x(c.report.after.height.size());
      for (std::size_t k = 0; k < x.size(); ++k) x[k] = c.report.after.centre(k);
      return arr(x);
    }();
    d["height_before"] = arr(c.report.before.height), d["height_after"] = arr(c.report.after.height);
    d["energy_t"] = arr(c.energy.t), d["energy_f"] = arr(c.energy.f);
    return d;
  });
}

}  // namespace ede::python
