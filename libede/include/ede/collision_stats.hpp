// Collision statistics per event: for every pair collision the impact parameter, the relative speed and
// its normal and tangential parts before the collision, and the impulse; for every wall or segment
// collision the impulse and the normal speed; and over a range of a log, the distributions of the impact
// parameter and of the relative speed against their equilibrium laws (docs/analysis.md, "Collision
// statistics").
//
// Conventions, pair (i, j), i the lower id: r = x_i - x_j at contact (periodic: the nearest image),
// g = v_i - v_j just before, n = r / |r|, t = (-n_y, n_x). The approach speed g_n = -g.n (> 0 for a
// collision), the tangential speed g_t = g.t (signed), and the signed impact parameter b = (r x g) / |g|,
// the component of r perpendicular to g, reported as b / (r_i + r_j) in [-1, 1] (|b| / (r_i + r_j) = |g_t| / |g|
// up to rounding: sin of the angle between -g and n). The impulse is the one on disk i, exact from the
// logged velocities: J = m_i (v_i' - v_i) (on j it is -J up to the rounding of the post-collision
// velocities); a wall or segment event's impulse is m_i (v_i' - v_i) too, its normal speed |v_i . n| before
// (n: the wall's normal; a segment's: the impulse's direction, as for smooth walls). Arithmetic in long double from the
// log's exact values, results rounded to double.
// Built on Log::for_each_event (the public event record already carries positions at the event and
// velocities before and after): no state of its own but each disk's radius and mass, so it streams over
// logs of any length. Rejected: new log columns (everything here is derived from what the log stores) and
// computing these inside the replay decoder (another engineer's room, and each front end wants a subset).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "ede/distributions.hpp"
#include "ede/error.hpp"
#include "ede/log.hpp"

namespace ede {

// What a record needs besides the event: every disk's radius and mass, and the box (nearest images).
struct CollisionDisks {
  std::vector<long double> radius, mass;  // by disk id, exact in the log's scalar type
  double lx = 1, ly = 1;
  bool periodic = false;
};
// The disks of a log (from its initial state: radii and masses never change during a run).
Result<CollisionDisks> collision_disks(const Log& log);

struct CollisionRecord {
  bool pair = false;          // a pair collision: every field set
  bool wall = false;          // a wall or segment collision: impulse, normal_speed, relative_speed = |v_i| before
  double impulse_x = 0, impulse_y = 0, impulse = 0;  // on disk i, m_i (v_i' - v_i), and its length
  double impact_parameter = 0;  // b / (r_i + r_j), signed, in [-1, 1] up to rounding
  double relative_speed = 0;    // |g| before
  double normal_speed = 0;      // pair: g_n = -g.n before (approach speed); wall: |v_i . n| before
  double tangential_speed = 0;  // pair: g_t = g.t before, signed
  double reduced_mass = 0;      // pair: m_i m_j / (m_i + m_j)
};

// The record of one logged event (all zero but the flags for wraps and actions).
CollisionRecord collision_record(const Event& e, const CollisionDisks& disks);

// Every event of the range with its record; f returns false to stop early.
Status for_each_collision(const Log& log, const EventRange& range,
                          const std::function<bool(const Event&, const CollisionRecord&)>& f);

// ==== Distributions over a range =================================================================
// In equilibrium (Maxwellian velocities independent of positions, exact for hard disks at any density
// in the canonical ensemble, O(1/N) off in a finite microcanonical run) the collision rate of pairs with
// relative velocity g and impact parameter b is proportional to |g| f(g) db: so
//   |b| / (r_i + r_j) is uniform on [0, 1], and
//   the relative speed at collision has the flux-weighted density p(g) = 4 a^(3/2) g^2 exp(-a g^2) / sqrt(pi),
//   a = mu / 2kT (mu the pair's reduced mass), i.e. u = a g^2 is Gamma(3/2): P(u) = erf(sqrt u) - 2 sqrt(u/pi) e^-u.
// The KS tests run on |b| / sigma against U(0, 1) and on u (which pools pairs of different reduced masses).
// kT is that of the state at the start of the range (kinetic_theory.hpp temperature_of: centre-of-mass frame,
// N - 1 disks, in a periodic box). The samples are taken as independent (a disk's successive collisions are
// nearly so in a gas); the KS p-value assumes it.
struct ImpactRequest {
  EventRange range;                       // default: the whole log
  std::size_t bins = 20;                  // for both histograms (>= 1)
  std::size_t max_collisions = 20'000'000;  // pair collisions kept for histograms and tests (24 bytes each)
};

struct ImpactStatistics {
  std::uint64_t pair_collisions = 0, wall_collisions = 0;  // in the range
  double kT = 0;                            // at the start of the range
  Histogram impact;                         // |b| / sigma on [0, 1]
  std::vector<double> impact_density;       // densities(impact); the law is 1
  Histogram speed;                          // g on [0, the largest g]
  std::vector<double> speed_density, speed_law;  // measured, and the law's mean density per bin
  KsResult impact_ks, speed_ks;             // |b| / sigma against U(0, 1); u = mu g^2 / 2kT against Gamma(3/2)
  double mean_impact = 0;                   // <|b| / sigma> (law: 1/2)
  double mean_speed = 0;                    // <g>
  double mean_impulse = 0;                  // <|J|> over pair collisions
  double mean_wall_impulse = 0;             // <|J|> over wall and segment collisions
  bool truncated = false;                   // more than max_collisions pairs: histograms and tests use the first ones
};

// Fails for an empty range of pair collisions, bins = 0, or a state at rest (kT = 0).
Result<ImpactStatistics> impact_statistics(const Log& log, const ImpactRequest& request = {});

// The law of u = mu g^2 / 2kT at collision: Gamma(3/2) CDF, and the flux-weighted relative-speed density
// and CDF for one reduced mass.
double collision_u_cdf(double u);
double collision_speed_density(double g, double reduced_mass, double kT);
double collision_speed_cdf(double g, double reduced_mass, double kT);

}  // namespace ede
