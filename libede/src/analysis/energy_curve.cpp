// energy_curve (ede/analysis.hpp): the kinetic energy of a log on a grid, and Haff's cooling time.
//
// The grid is built here (every, points, or the default of 1/20 of the mean free time) and the series is
// log_series's single walk over the events. E(0) must be the energy at t = 0 even when the range starts
// later, so a grid that does not start at 0 is walked with 0 in front, which is then dropped: one walk,
// no second pass. Haff's tau uses the same points (see the header). Rejected: fitting (1 + t/tau)^-2 to
// the curve, whose answer would depend on the range and the grid, where reading omega0 off the collision
// count at one point is exact within the model.
#include <algorithm>
#include <cmath>
#include <string>

#include "ede/number_text.hpp"
#include "ede/analysis.hpp"
#include "ede/kinetic_theory.hpp"

namespace ede {

namespace {

Result<std::vector<double>> grid_of(const EnergyCurveRequest& req, double from, double to, EnergyCurve& c) {
  std::vector<double> grid;
  if (req.points) {
    const std::size_t k = std::max<std::size_t>(*req.points, 2);
    if (k > req.max_points)
      return Error{"a grid of " + std::to_string(k) + " points is more than " + std::to_string(req.max_points)};
    for (std::size_t i = 0; i < k; ++i)
      grid.push_back(i + 1 == k ? to : from + (to - from) * (double(i) / double(k - 1)));
    return grid;
  }
  if (req.every && !(*req.every > 0)) return Error{"the grid's spacing must be > 0, not " + brief(*req.every)};
  const double tau = c.mean_free_time;
  double dt = req.every.value_or(std::isfinite(tau) ? tau / 20 : (to - from) / 1000);
  if (!(dt > 0)) dt = 1;  // a range of length 0: the grid is {from}
  c.spacing = dt;
  c.default_spacing = !req.every;
  grid = time_grid_to(from, to, dt, req.max_points);
  if (grid.empty())
    return Error{"the grid of spacing " + brief(dt) + " has more than " + std::to_string(req.max_points) +
                 " points; give a larger spacing or fewer points"};
  return grid;
}

void haff_time(EnergyCurve& c) {
  const double a = 1 - c.restitution * c.restitution;
  const LogSeries& s = c.series;
  if (!(a > 0) || s.time.size() < 2) return;
  std::size_t k = 1;
  while (k + 1 < s.time.size() && s.collisions_per_particle(k) < 2) ++k;
  const double c1 = s.collisions_per_particle(k), t1 = s.time[k];
  if (!(c1 > 0) || !(t1 > 0)) return;
  const double omega0 = 4 * std::expm1(a * c1 / 4) / (a * t1);
  c.haff_tau = 4 / (a * omega0);
  c.haff_calibration = c1;
}

void drop_first(LogSeries& s) {
  s.time.erase(s.time.begin());
  s.kinetic_energy.erase(s.kinetic_energy.begin());
  for (std::vector<double>& e : s.species_energy) e.erase(e.begin());
  s.pair_collisions.erase(s.pair_collisions.begin());
  s.wall_collisions.erase(s.wall_collisions.begin());
}

}  // namespace

double EnergyCurve::ratio(std::size_t k) const {
  return initial_energy > 0 ? series.kinetic_energy[k] / initial_energy : std::nan("");
}

double EnergyCurve::haff_ratio(std::size_t k) const {
  const double x = 1 + series.time[k] / (std::isfinite(enskog_tau) ? enskog_tau : haff_tau);
  return 1 / (x * x);
}

double EnergyCurve::max_drift() const {
  double drift = 0;
  for (const double e : series.kinetic_energy)
    drift = std::max(drift, initial_energy > 0 ? std::abs(e / initial_energy - 1) : 0.0);
  return drift;
}

Result<EnergyCurve> energy_curve(const Log& log, const EnergyCurveRequest& request) {
  auto overview = log_overview(log);
  if (!overview) return overview.error();
  const LogOverview& o = overview.value();
  const std::string& path = log.info().path;
  EnergyCurve c;
  c.mean_free_time = o.mean_free_time();
  bool driven = false;  // the Andersen thermostat feeds energy in: no free cooling to compare with
  if (auto scene = log.scene()) c.restitution = scene.value().physics.restitution, driven = scene.value().thermostatted();
  const double from = request.from.value_or(0), to = request.to.value_or(o.end_time);
  if (!(from >= 0) || !(to >= from) || to > o.end_time)
    return Error{path + ": the range " + brief(from) + " to " + brief(to) +
                 " is not within the log (t = 0 to " + brief(o.end_time) + ")"};
  auto grid = grid_of(request, from, to, c);
  if (!grid) return Error{path + ": " + grid.error().message};
  std::vector<double> times = std::move(grid).value();
  const bool from_zero = times.front() == 0;
  if (!from_zero) times.insert(times.begin(), 0.0);
  auto series = log_series(log, times);
  if (!series) return series.error();
  c.series = std::move(series).value();
  c.initial_energy = c.series.kinetic_energy.front();
  if (driven) {
    c.enskog_note = "the Andersen thermostat drives this gas, so it does not cool freely (Haff's law); its steady "
                    "temperature: docs/physics.md, \"Andersen thermostat\"";
  } else {
    haff_time(c);
  }
  if (c.restitution < 1 && !driven) {
    auto e = enskog_at(log, 0);
    if (!e) return e.error();
    if (e.value().applicable && e.value().rate > 0) {
      c.enskog_rate0 = e.value().rate;
      c.enskog_tau = haff_tau(c.restitution, c.enskog_rate0);
      c.enskog_tau_error = kHaffTauRelativeUncertainty * c.enskog_tau;
    } else {
      c.enskog_note = e.value().applicable ? "the disks are at rest at t = 0" : e.value().why_not;
    }
  }
  if (!from_zero) drop_first(c.series);
  return c;
}

}  // namespace ede
