// The exact VACF (transport.hpp). A disk's velocity is a sequence of constant segments [a, b) between its
// events, clipped to the window [t_a, t_b]. For two segments s1 = [a1, b1), s2 = [a2, b2) (s2 the same or
// later), the measure of origins t0 with t0 in s1 and t0 + tau in s2 is
//   f(tau) = max(0, min(b1, b2 - tau) - max(a1, a2 - tau)),
// a trapezoid in tau, so sum over pairs of (v1 . v2) f(tau_k) is the exact integral at each lag tau_k.
// Clipping the segments to the window makes the origins run over [t_a, t_b - tau], hence the division by
// N (T - tau). Each disk keeps only the segments that can still pair with a future one (those ending
// within max_lag of now). Cost: O(1) per pair of segments within max_lag of each other (Correlator).
// Rejected: sampling v on a grid (an error of order dt times the collision rate at every lag).
#include <algorithm>
#include <cmath>
#include <deque>

#include "analysis/transport_stream.hpp"
#include "ede/transport.hpp"

namespace ede {

namespace {

struct Segment {
  double a, b, vx, vy;
};

struct DiskHistory {
  double a = 0, vx = 0, vy = 0;  // the open segment
  std::deque<Segment> closed;    // recent closed segments, oldest first
};

// The trapezoid f(tau) of two segments is a sum of four ramps R(tau - x) = max(0, tau - x) with corners
// x = a2 - b1 (+), a2 - a1 (-), b2 - b1 (-), b2 - a1 (+) (a box convolved with a box). A ramp of weight c
// adds c (tau_k - x) at every lag tau_k >= x: kept as c and -c x added at the first such lag and summed at
// the end, so a pair of segments costs O(1) whatever the number of lags (long double sums: the ramps of a
// pair cancel beyond its trapezoid, and the cancellation stays below 1e-15 relative).
class Correlator {
 public:
  Correlator(double dt, std::size_t lags, std::size_t groups)
      : dt_(dt), lags_(lags), max_lag_(dt * double(lags - 1)), slope_(groups, std::vector<long double>(lags, 0)),
        offset_(groups, std::vector<long double>(lags, 0)) {}

  // Closes d's open segment at t, correlates it with itself and the recent ones, opens [t, ...) with v.
  void change(DiskHistory& d, std::size_t group, double t, double vx, double vy) {
    if (t > d.a) {
      const Segment s2{d.a, t, d.vx, d.vy};
      add(s2, s2, group);
      for (auto it = d.closed.rbegin(); it != d.closed.rend(); ++it) add(*it, s2, group);
      d.closed.push_back(s2);
      while (!d.closed.empty() && t - d.closed.front().b > max_lag_) d.closed.pop_front();
    }
    d.a = t, d.vx = vx, d.vy = vy;
  }
  // The sum over pairs of (v1 . v2) f(tau_k), per group and lag.
  std::vector<std::vector<double>> sums() const {
    std::vector<std::vector<double>> out(slope_.size(), std::vector<double>(lags_, 0));
    for (std::size_t g = 0; g < slope_.size(); ++g) {
      long double a = 0, b = 0;
      for (std::size_t k = 0; k < lags_; ++k) {
        a += slope_[g][k], b += offset_[g][k];
        out[g][k] = double((long double)(dt_ * double(k)) * a + b);
      }
    }
    return out;
  }

 private:
  void ramp(double x, long double c, std::size_t g) {
    const double first = std::ceil(x / dt_);
    if (first > double(lags_ - 1)) return;
    const std::size_t k = first <= 0 ? 0 : std::size_t(first);
    slope_[g][k] += c;
    offset_[g][k] -= c * (long double)x;
  }
  void add(const Segment& s1, const Segment& s2, std::size_t g) {
    const long double dot = (long double)s1.vx * s2.vx + (long double)s1.vy * s2.vy;
    if (s2.a - s1.b > max_lag_) return;
    ramp(s2.a - s1.b, dot, g);
    ramp(s2.a - s1.a, -dot, g);
    ramp(s2.b - s1.b, -dot, g);
    ramp(s2.b - s1.a, dot, g);
  }
  double dt_;
  std::size_t lags_;
  double max_lag_;
  std::vector<std::vector<long double>> slope_, offset_;
};

}  // namespace

Result<VelocityAutocorrelation> velocity_autocorrelation(const Log& log, const TransportOptions& o) {
  auto opened = transport::open_window(log, o, "VACF");
  if (!opened) return opened.error();
  const transport::Window& w = opened.value();
  const State& s0 = w.start;
  std::size_t n = 0;
  const std::vector<std::int32_t> local = transport::select_disks(s0, o.species, n);
  if (n == 0) return Error{log.info().path + ": VACF: no disk of the species asked for"};
  const std::size_t lags = std::size_t(std::floor(o.max_lag / o.lag_step + 1e-9)) + 1;
  const std::size_t groups = std::min(o.groups, n);
  Correlator c(o.lag_step, lags, groups);
  std::vector<DiskHistory> h(n);
  for (std::size_t i = 0; i < s0.size(); ++i)
    if (local[i] >= 0) h[local[i]] = {w.from, s0.vx[i], s0.vy[i], {}};
  const auto change = [&](std::int32_t id, double t, double vx, double vy) {
    if (id < 0 || std::size_t(id) >= local.size() || local[id] < 0) return;
    c.change(h[local[id]], std::size_t(local[id]) % groups, t, vx, vy);
  };
  Status walked = transport::for_each_window_event(log, w, false, [&](const transport::StreamEvent& e) {
    switch (e.kind) {
      case EventKind::Pair:
      case EventKind::Step:  // a step changes both velocities, like a collision
        change(e.i, e.time, e.vix, e.viy);
        change(e.j, e.time, e.vjx, e.vjy);
        break;
      case EventKind::Wall:
      case EventKind::Segment:
      case EventKind::Thermostat: change(e.i, e.time, e.vix, e.viy); break;
      case EventKind::Action:
        for (std::size_t d = 0; d < n; ++d) c.change(h[d], d % groups, e.time, -h[d].vx, -h[d].vy);
        break;
      default: break;  // a wrap changes no velocity
    }
  });
  if (!walked) return walked.error();
  for (std::size_t d = 0; d < n; ++d) c.change(h[d], d % groups, w.to, 0, 0);

  VelocityAutocorrelation out;
  out.disks = n;
  out.lag.resize(lags);
  out.c.assign(lags, 0);
  out.error.assign(lags, 0);
  out.green_kubo.assign(lags, 0);
  std::vector<std::size_t> group_size(groups, 0);
  for (std::size_t d = 0; d < n; ++d) ++group_size[d % groups];
  const double span = w.to - w.from;
  const std::vector<std::vector<double>> sums = c.sums();
  for (std::size_t k = 0; k < lags; ++k) {
    out.lag[k] = o.lag_step * double(k);
    const double origins = span - out.lag[k];
    std::vector<double> g(groups);
    double total = 0;
    for (std::size_t q = 0; q < groups; ++q) {
      total += sums[q][k];
      g[q] = sums[q][k] / (double(group_size[q]) * origins);
    }
    out.c[k] = total / (double(n) * origins);
    out.error[k] = transport::standard_error(g);
    if (k > 0) out.green_kubo[k] = out.green_kubo[k - 1] + 0.25 * o.lag_step * (out.c[k - 1] + out.c[k]);
  }
  return out;
}

}  // namespace ede
