// The accuracy study, the chaos part: round-off amplified by the dynamics, per setting and scene.
//
// Time reversal: a probe run finds the time t_c at which the disks have had c collisions each (stop at c
// collisions per particle); a second run from the same start reverses every velocity at t_c
// (ActionKind::ReverseVelocities, the engine's own action) and stops at 2 t_c, where exact arithmetic
// would be back at the start. Reported: the RMS distance from the initial positions in diameters (minimum
// image in a periodic box), and the fraction of disks back within one diameter.
// One ulp apart: two runs start from ResumePoints at t = 0 holding the initial disks in the run's own
// type, one of them with disk N/2's x one ulp higher (one_ulp_up). Both run with samples every
// divergence_step collisions per disk (mean free time tau from a probe run); at each sample the positions
// are compared. Two horizons, in collisions per disk of the unperturbed run at the first sample where some
// disk is farther from its twin than
//   a mean free path l = v_rms tau: the twins' collision sequences are then unrelated; reached in any phase;
//   its diameter: the criterion of a fluid, never reached in a crystal, where every disk stays in its cage.
// Both twins start from resume points so that the only difference between them is the ulp. Rejected: perturbing the double InitialState (one double
// ulp is no change at all in a float run, and cannot express a long double ulp).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "study/accuracy_parts.hpp"
#include "study/measurement.hpp"

namespace ede::study {

namespace {

double distance(const StudyScene& s, double dx, double dy) {
  const bool periodic = s.options.boundary == BoundaryKind::Periodic;
  return std::hypot(image_distance(dx, s.initial.lx, periodic), image_distance(dy, s.initial.ly, periodic));
}

template <class T>
int reversal_child(const StudyScene& s, const StudyPlan& plan, std::string& out) {
  std::ostringstream o;
  o.precision(17);
  for (std::size_t k = 0; k < plan.reversal_collisions.size(); ++k) {
    const Result<double> t_rev = time_at_collisions<T>(s, plan.reversal_collisions[k]);
    if (!t_rev) return out = t_rev.error().message, 1;
    EngineOptions opt = s.options;
    opt.stop = StopSpec{};
    opt.stop.time = 2 * t_rev.value();
    opt.actions = {ActionSpec{t_rev.value(), ActionKind::ReverseVelocities}};
    auto made = s.engine<T>(opt);
    if (!made) return out = made.error().message, 1;
    EngineApi<T>& e = *made.value();
    const std::vector<Disk<T>> start = e.particles().disk;
    if (e.run() == RunStatus::Stalled) return out = e.stall_message(), 1;
    const Particles<T>& p = e.particles();
    double sum2 = 0, back = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double diameter = 2 * s.initial.radius[i];
      const double d = distance(s, double(p.x_at(i, e.time()) - start[i].x), double(p.y_at(i, e.time()) - start[i].y));
      sum2 += (d / diameter) * (d / diameter);
      back += d < diameter ? 1 : 0;
    }
    const double n = double(p.size());
    o << " rms_" << k << "=" << std::sqrt(sum2 / n) << " returned_" << k << "=" << back / n;
  }
  out = o.str();
  return 0;
}

// Runs e until it has taken one more sample; false when it stopped first.
template <class T>
bool next_sample(EngineApi<T>& e) {
  const std::uint64_t taken = e.counts().of(EventKind::Sample);
  while (e.counts().of(EventKind::Sample) == taken)
    if (e.run(1) != RunStatus::Running) return false;
  return true;
}

// The largest distance between a disk and its twin: absolute, and in diameters.
template <class T>
std::pair<double, double> largest_separation(const StudyScene& s, const EngineApi<T>& a, const EngineApi<T>& b) {
  double worst = 0, worst_diameters = 0;
  const T t = a.time();
  for (std::size_t i = 0; i < a.particles().size(); ++i) {
    const double dx = double(a.particles().x_at(i, t) - b.particles().x_at(i, t));
    const double dy = double(a.particles().y_at(i, t) - b.particles().y_at(i, t));
    const double d = distance(s, dx, dy);
    worst = std::max(worst, d);
    worst_diameters = std::max(worst_diameters, d / (2 * s.initial.radius[i]));
  }
  return {worst, worst_diameters};
}

double rms_speed(const InitialState& s) {
  double e2 = 0, m = 0;
  for (std::size_t i = 0; i < s.size(); ++i) e2 += s.mass[i] * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]), m += s.mass[i];
  return std::sqrt(e2 / m);
}

template <class T>
int divergence_child(const StudyScene& s, const StudyPlan& plan, std::string& out) {
  const Result<double> t2 = time_at_collisions<T>(s, 2);
  if (!t2) return out = t2.error().message, 1;
  const double tau = t2.value() / 2;  // time per collision per disk
  EngineOptions opt = s.options;
  opt.stop = StopSpec{};
  opt.stop.time = 4 * tau * plan.divergence_cap;  // a bound only: the loop stops at divergence_cap
  opt.sample_interval = tau * plan.divergence_step;
  auto probe = s.engine<T>(opt);
  if (!probe) return out = probe.error().message, 1;
  ResumePoint<T> ra;
  ra.disks = probe.value()->particles().disk;
  ResumePoint<T> rb = ra;
  Disk<T>& moved = rb.disks[rb.disks.size() / 2];
  moved.x = one_ulp_up(moved.x);
  auto a = s.engine<T>(opt, &ra);
  auto b = s.engine<T>(opt, &rb);
  if (!a || !b) return out = (a ? b.error() : a.error()).message, 1;
  const double n = double(s.initial.size()), path = rms_speed(s.initial) * tau;
  double by_path = -1, by_diameter = -1;
  while (by_diameter < 0 && next_sample(*a.value()) && next_sample(*b.value())) {
    const double collisions = 2 * double(a.value()->counts().of(EventKind::Pair)) / n;
    const auto [worst, worst_diameters] = largest_separation(s, *a.value(), *b.value());
    if (by_path < 0 && worst > path) by_path = collisions;
    if (worst_diameters > 1) by_diameter = collisions;
    if (collisions >= plan.divergence_cap) break;
  }
  std::ostringstream o;
  o.precision(17);
  o << "path=" << path << " by_path=" << by_path << " by_diameter=" << by_diameter;
  out = o.str();
  return 0;
}

}  // namespace

void measure_chaos(const StudyPlan& plan, EngineRow& row) {
  const ChildMeasurement rev = in_child(plan, row, [&]<class T>(const StudyScene& s, std::string& out) {
    return reversal_child<T>(s, plan, out);
  });
  if (!rev.ok) {
    row.failure = "time reversal: " + rev.failure;
    return;
  }
  for (std::size_t k = 0; k < plan.reversal_collisions.size(); ++k) {
    row.reversal_rms.push_back(get(rev.values, "rms_" + std::to_string(k)));
    row.reversal_returned.push_back(get(rev.values, "returned_" + std::to_string(k)));
  }
  const ChildMeasurement div = in_child(plan, row, [&]<class T>(const StudyScene& s, std::string& out) {
    return divergence_child<T>(s, plan, out);
  });
  if (!div.ok) {
    row.failure = "one-ulp divergence: " + div.failure;
    return;
  }
  row.free_path = get(div.values, "path");
  row.divergence_path = get(div.values, "by_path");
  row.divergence_diameter = get(div.values, "by_diameter");
  std::fprintf(stderr, "  %-8s %-26s reversal rms %s, divergence %s (path), %s (diameter)\n", row.scene.c_str(),
               row.setting.label().c_str(), row.reversal_rms.empty() ? "-" : fmt(row.reversal_rms.back()).c_str(),
               fmt(row.divergence_path).c_str(), fmt(row.divergence_diameter).c_str());
}

}  // namespace ede::study
