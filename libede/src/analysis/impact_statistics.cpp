// Impact statistics over a range of a log (ede/collision_stats.hpp): histograms of |b| / sigma and of the
// relative speed at pair collisions, against the equilibrium laws (uniform; flux-weighted Maxwellian),
// with KS tests. One walk of for_each_collision; the samples are kept (up to max_collisions) because the
// KS statistic needs them sorted. The speed law of a mixture is the mixture, over the pairs' reduced masses
// weighted by how many collisions each had, of the single-mass laws (the KS test on u needs no weights).
// Rejected: chi-square on the histogram (its verdict depends on the bins the user chose).
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "ede/collision_stats.hpp"
#include "ede/kinetic_theory.hpp"
#include "analysis/sheared_guard.hpp"

namespace ede {

double collision_u_cdf(double u) {
  if (!(u > 0)) return 0;
  return std::erf(std::sqrt(u)) - 2 * std::sqrt(u / std::numbers::pi) * std::exp(-u);
}

double collision_speed_density(double g, double mu, double kT) {
  if (!(g > 0)) return 0;
  const double a = mu / (2 * kT);
  return 4 * a * std::sqrt(a) * g * g * std::exp(-a * g * g) / std::sqrt(std::numbers::pi);
}

double collision_speed_cdf(double g, double mu, double kT) { return collision_u_cdf(mu * g * g / (2 * kT)); }

namespace {

Result<State> state_at_start(const Log& log, const EventRange& r) {
  if (r.from_event) return log.state_at_event(*r.from_event);
  if (r.from_time) return log.state_at(*r.from_time);
  return log.state_at_event(0);
}

struct Samples {
  std::vector<double> b, g, u;
  std::map<double, std::uint64_t> reduced_masses;  // mu -> collisions
  long double impact_sum = 0, speed_sum = 0, impulse_sum = 0, wall_impulse_sum = 0;
};

std::vector<double> speed_law(const Histogram& h, const Samples& s, double kT) {
  std::vector<double> law(h.bins(), 0.0);
  std::uint64_t total = 0;
  for (const auto& [mu, n] : s.reduced_masses) total += n;
  for (std::size_t k = 0; k < h.bins(); ++k) {
    long double p = 0;
    for (const auto& [mu, n] : s.reduced_masses)
      p += (long double)(n) * (collision_speed_cdf(h.edges[k + 1], mu, kT) - collision_speed_cdf(h.edges[k], mu, kT));
    law[k] = double(p / (long double)(total) / (h.edges[k + 1] - h.edges[k]));
  }
  return law;
}

}  // namespace

Result<ImpactStatistics> impact_statistics(const Log& log, const ImpactRequest& request) {
  if (std::string why = sheared_refusal(log, "impact statistics"); !why.empty()) return Error{why};
  if (request.bins == 0) return Error{log.info().path + ": impact statistics need at least one bin"};
  auto start = state_at_start(log, request.range);
  if (!start) return start.error();
  ImpactStatistics r;
  r.kT = temperature_of(start.value()).kT;
  if (!(r.kT > 0)) return Error{log.info().path + ": the disks are at rest at the start of the range (kT = 0): no equilibrium law to compare with"};
  Samples s;
  Status walked = for_each_collision(log, request.range, [&](const Event&, const CollisionRecord& c) {
    if (c.wall) ++r.wall_collisions, s.wall_impulse_sum += c.impulse;
    if (!c.pair) return true;
    ++r.pair_collisions;
    const double b = std::fabs(c.impact_parameter);
    s.impact_sum += b, s.speed_sum += c.relative_speed, s.impulse_sum += c.impulse;
    if (s.b.size() >= request.max_collisions) return r.truncated = true, true;
    s.b.push_back(b), s.g.push_back(c.relative_speed);
    s.u.push_back(c.reduced_mass * c.relative_speed * c.relative_speed / (2 * r.kT));
    ++s.reduced_masses[c.reduced_mass];
    return true;
  });
  if (!walked) return walked.error();
  if (r.pair_collisions == 0) return Error{log.info().path + ": no pair collision in the range"};
  const auto n = (long double)(r.pair_collisions);
  r.mean_impact = double(s.impact_sum / n), r.mean_speed = double(s.speed_sum / n), r.mean_impulse = double(s.impulse_sum / n);
  if (r.wall_collisions) r.mean_wall_impulse = double(s.wall_impulse_sum / (long double)(r.wall_collisions));
  r.impact = make_histogram(s.b, uniform_edges(0, 1, request.bins));
  r.impact_density = densities(r.impact);
  const double g_max = *std::max_element(s.g.begin(), s.g.end());
  r.speed = make_histogram(s.g, uniform_edges(0, g_max > 0 ? g_max : 1, request.bins));
  r.speed_density = densities(r.speed);
  r.speed_law = speed_law(r.speed, s, r.kT);
  r.impact_ks = ks_test(std::move(s.b), [](double x) { return std::clamp(x, 0.0, 1.0); });
  r.speed_ks = ks_test(std::move(s.u), collision_u_cdf);
  return r;
}

}  // namespace ede
