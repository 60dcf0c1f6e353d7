// Mean-square displacement with exactly unwrapped coordinates (transport.hpp). Each selected disk keeps the
// position, velocity and time of its last event and an image count per axis (a wrap event says which edge
// it crossed); its unwrapped position at any t is x_e + images L + v (t - t_e), evaluated at the
// measurement times t_o + k dt of every origin t_o. Memory: the disks' last events plus one position per
// disk for each origin whose lags are still open. Errors: the disks are split into `groups` by id modulo,
// each group gives its own MSD and D, and the error is the standard error over the groups.
// Rejected: accumulating v dt per event (rounding grows with the number of events; here it does not).
#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/transport_stream.hpp"
#include "ede/transport.hpp"

namespace ede {

namespace {

struct Track {
  double x = 0, y = 0, vx = 0, vy = 0, t = 0;
  double ix = 0, iy = 0;  // images crossed (+1: across the right / top edge)
};

struct Measure {
  double t;
  std::size_t origin, lag;
};

// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k], my += y[k];
  mx /= double(x.size()), my /= double(x.size());
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < x.size(); ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  return sxx > 0 ? sxy / sxx : 0;
}

}  // namespace

Result<MeanSquareDisplacement> mean_square_displacement(const Log& log, const TransportOptions& o) {
  auto opened = transport::open_window(log, o, "MSD");
  if (!opened) return opened.error();
  const transport::Window& w = opened.value();
  const State& s0 = w.start;
  std::size_t n = 0;
  const std::vector<std::int32_t> local = transport::select_disks(s0, o.species, n);
  if (n == 0) return Error{log.info().path + ": MSD: no disk of the species asked for"};
  const std::size_t lags = std::size_t(std::floor(o.max_lag / o.lag_step + 1e-9)) + 1;
  const std::size_t origins = o.origins ? o.origins : 20;
  const std::size_t groups = std::min(o.groups, n);
  const double last_origin = w.to - o.lag_step * double(lags - 1);
  std::vector<Measure> plan;
  for (std::size_t a = 0; a < origins; ++a) {
    const double t0 = origins == 1 ? w.from : w.from + (last_origin - w.from) * double(a) / double(origins - 1);
    for (std::size_t k = 0; k < lags; ++k) plan.push_back({std::min(w.to, t0 + o.lag_step * double(k)), a, k});
  }
  std::stable_sort(plan.begin(), plan.end(), [](const Measure& a, const Measure& b) { return a.t < b.t; });

  std::vector<Track> track(n);
  for (std::size_t i = 0; i < s0.size(); ++i)
    if (local[i] >= 0) track[local[i]] = {s0.x[i], s0.y[i], s0.vx[i], s0.vy[i], w.from, 0, 0};
  const double lx = s0.lx, ly = s0.ly;
  const auto unwrapped = [&](const Track& d, double t, double& x, double& y) {
    x = d.x + d.ix * lx + d.vx * (t - d.t);
    y = d.y + d.iy * ly + d.vy * (t - d.t);
  };
  std::map<std::size_t, std::vector<double>> open;  // origin -> unwrapped x, y per disk at t0
  std::vector<std::vector<double>> sum(groups, std::vector<double>(lags, 0));
  std::vector<std::size_t> group_size(groups, 0), samples(lags, 0);
  for (std::size_t d = 0; d < n; ++d) ++group_size[d % groups];
  std::size_t next = 0;
  const auto measure_until = [&](double t) {
    for (; next < plan.size() && plan[next].t <= t; ++next) {
      const Measure& m = plan[next];
      std::vector<double>& ref = open[m.origin];
      if (m.lag == 0) ref.resize(2 * n);
      for (std::size_t d = 0; d < n; ++d) {
        double x, y;
        unwrapped(track[d], m.t, x, y);
        if (m.lag == 0) {
          ref[2 * d] = x, ref[2 * d + 1] = y;
        } else {
          const double dx = x - ref[2 * d], dy = y - ref[2 * d + 1];
          sum[d % groups][m.lag] += dx * dx + dy * dy;
        }
      }
      ++samples[m.lag];
      if (m.lag + 1 == lags) open.erase(m.origin);
    }
  };
  const auto moved = [&](std::int32_t id, double t, double x, double y, double vx, double vy) {
    if (id < 0 || std::size_t(id) >= local.size() || local[id] < 0) return;
    Track& d = track[local[id]];
    d.x = x, d.y = y, d.vx = vx, d.vy = vy, d.t = t;
  };
  Status walked = transport::for_each_window_event(log, w, true, [&](const transport::StreamEvent& e) {
    measure_until(e.time);
    switch (e.kind) {
      case EventKind::Pair:
      case EventKind::Step:  // a step changes both velocities, like a collision
        moved(e.i, e.time, e.xi, e.yi, e.vix, e.viy);
        moved(e.j, e.time, e.xj, e.yj, e.vjx, e.vjy);
        break;
      case EventKind::Wall:
      case EventKind::Segment:
      case EventKind::Thermostat: moved(e.i, e.time, e.xi, e.yi, e.vix, e.viy); break;
      case EventKind::Wrap:
        if (e.i >= 0 && std::size_t(e.i) < local.size() && local[e.i] >= 0) {
          Track& d = track[local[e.i]];
          d.ix += e.j == kWrapRight ? 1 : e.j == kWrapLeft ? -1 : 0;
          d.iy += e.j == kWrapTop ? 1 : e.j == kWrapBottom ? -1 : 0;
          d.x = e.xi, d.y = e.yi, d.t = e.time;
        }
        break;
      case EventKind::Action:  // every velocity reversed
        for (Track& d : track) {
          d.x += d.vx * (e.time - d.t), d.y += d.vy * (e.time - d.t), d.t = e.time;
          d.vx = -d.vx, d.vy = -d.vy;
        }
        break;
      default: break;
    }
  });
  if (!walked) return walked.error();
  measure_until(w.to);

  MeanSquareDisplacement out;
  out.disks = n;
  out.origins = origins;
  out.lag.resize(lags);
  out.msd.assign(lags, 0);
  out.error.assign(lags, 0);
  std::vector<std::vector<double>> per_group(groups, std::vector<double>(lags, 0));
  for (std::size_t k = 0; k < lags; ++k) {
    out.lag[k] = o.lag_step * double(k);
    std::vector<double> g(groups);
    double total = 0;
    for (std::size_t q = 0; q < groups; ++q) {
      total += sum[q][k];
      per_group[q][k] = g[q] = samples[k] ? sum[q][k] / (double(samples[k]) * double(group_size[q])) : 0;
    }
    out.msd[k] = samples[k] ? total / (double(samples[k]) * double(n)) : 0;
    out.error[k] = transport::standard_error(g);
  }
  // D from the slope over the last half of the lags.
  const std::size_t first = lags / 2;
  const std::vector<double> x(out.lag.begin() + std::ptrdiff_t(first), out.lag.end());
  if (x.size() >= 2) {
    out.diffusion = slope(x, std::vector<double>(out.msd.begin() + std::ptrdiff_t(first), out.msd.end())) / 4;
    std::vector<double> d(groups);
    for (std::size_t q = 0; q < groups; ++q)
      d[q] = slope(x, std::vector<double>(per_group[q].begin() + std::ptrdiff_t(first), per_group[q].end())) / 4;
    out.diffusion_error = transport::standard_error(d);
  }
  return out;
}

}  // namespace ede
