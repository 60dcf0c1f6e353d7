// stress_integral (ede/viscosity.hpp) and its walk (stress_walk.hpp). Between events the integrand
// sum_i m_i c_ia c_ib is constant; it is kept as running sums S_ab = sum m v_a v_b and P = sum m v, and
// S_ab - P_a P_b / M is the same sum taken relative to the centre-of-mass velocity u = P / M (expand
// m (v - u)_a (v - u)_b). Each event adds its impulse term r_ij,a dp_i,b to the bin holding it (an event on
// a bin edge belongs to the bin it opens) and changes the sums by its participants' velocities. Sums are
// long double: the impulse terms of a bin nearly cancel in the off-diagonal components.
// A sheared box (Lees-Edwards) changes two things here and nothing else: the streaming velocity becomes
// u(y) = (gamma y, 0), so the kinetic integrand gains - gamma sum m y_i(t) v_iy, linear in t between events
// (a running sum of m v_iy y_i and of m v_iy^2 integrates it exactly), and `separation` takes the sliding
// image's offset. Rejected: summing m c_a c_b over every disk at every event (O(N) per event).
#include "analysis/stress_walk.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/transport_stream.hpp"
#include "ede/number_text.hpp"

namespace ede::stress {

namespace {

// The nearest-image separation r_i - r_j of a pair at contact (periodic box; a contact is far closer than
// half a box length, so the nearest image is the pair's).
void separation(long double& dx, long double& dy, long double lx, long double ly) {
  dx -= lx * std::nearbyint(dx / lx);
  dy -= ly * std::nearbyint(dy / ly);
}

class StressWalk {
 public:
  StressWalk(const State& s, double from, double width, std::size_t bins, StressIntegral& out)
      : from_(from), width_(width), bins_(bins), out_(out), t_prev_(from) {
    out_.xx.assign(bins, 0), out_.yy.assign(bins, 0), out_.xy.assign(bins, 0), out_.yx.assign(bins, 0);
    xx_.assign(bins, 0), yy_.assign(bins, 0), xy_.assign(bins, 0), yx_.assign(bins, 0);
    lx_ = s.lx, ly_ = s.ly;
    const std::size_t n = s.size();
    mass_.resize(n), vx_.resize(n), vy_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      mass_[i] = s.mass.exact(i);
      total_mass_ += mass_[i];
      vx_[i] = 0, vy_[i] = 0;
      set_velocity(i, s.vx.exact(i), s.vy.exact(i));
    }
  }

  // Adds the kinetic integral up to t, bin by bin.
  void integrate_to(long double t) {
    const long double kxx = sxx_ - px_ * px_ / total_mass_, kyy = syy_ - py_ * py_ / total_mass_;
    const long double kxy = sxy_ - px_ * py_ / total_mass_;
    while (bin_ + 1 < bins_ && edge(bin_ + 1) <= t) {
      add_kinetic(kxx, kyy, kxy, edge(bin_ + 1) - t_prev_);
      t_prev_ = edge(++bin_);
    }
    add_kinetic(kxx, kyy, kxy, t - t_prev_);
    t_prev_ = t;
  }

  // A pair or step event: the impulse term, then the new velocities.
  void pair(const transport::StreamEvent& e) {
    const auto i = std::size_t(e.i), j = std::size_t(e.j);
    long double dx = (long double)e.xi - e.xj, dy = (long double)e.yi - e.yj;
    separation(dx, dy, lx_, ly_);
    const long double dpx = mass_[i] * ((long double)e.vix - vx_[i]);
    const long double dpy = mass_[i] * ((long double)e.viy - vy_[i]);
    xx_[bin_] += dx * dpx, yy_[bin_] += dy * dpy, xy_[bin_] += dx * dpy, yx_[bin_] += dy * dpx;
    out_.impulse_xx += dx * dpx, out_.impulse_yy += dy * dpy, out_.impulse_xy += dx * dpy, out_.impulse_yx += dy * dpx;
    set_velocity(i, e.vix, e.viy);
    set_velocity(j, e.vjx, e.vjy);
  }

  void finish(long double end) {
    integrate_to(end);
    for (std::size_t k = 0; k < bins_; ++k) {
      out_.xx[k] = double(xx_[k]), out_.yy[k] = double(yy_[k]);
      out_.xy[k] = double(xy_[k]), out_.yx[k] = double(yx_[k]);
    }
  }

 private:
  long double edge(std::size_t k) const { return (long double)from_ + (long double)width_ * (long double)k; }

  void add_kinetic(long double kxx, long double kyy, long double kxy, long double dt) {
    xx_[bin_] += kxx * dt, yy_[bin_] += kyy * dt, xy_[bin_] += kxy * dt, yx_[bin_] += kxy * dt;
    out_.kinetic_xx += kxx * dt, out_.kinetic_yy += kyy * dt, out_.kinetic_xy += kxy * dt;
  }

  void set_velocity(std::size_t i, long double vx, long double vy) {
    const long double m = mass_[i], ox = vx_[i], oy = vy_[i];
    sxx_ += m * (vx * vx - ox * ox), syy_ += m * (vy * vy - oy * oy), sxy_ += m * (vx * vy - ox * oy);
    px_ += m * (vx - ox), py_ += m * (vy - oy);
    vx_[i] = vx, vy_[i] = vy;
  }

  const double from_, width_;
  const std::size_t bins_;
  StressIntegral& out_;
  long double lx_ = 1, ly_ = 1;
  std::vector<long double> mass_, vx_, vy_;  // velocities before the event at hand
  std::vector<long double> xx_, yy_, xy_, yx_;
  long double sxx_ = 0, syy_ = 0, sxy_ = 0, px_ = 0, py_ = 0, total_mass_ = 0;
  std::size_t bin_ = 0;
  long double t_prev_;
};

}  // namespace

std::string refusal(const Log& log) {
  const LogInfo& info = log.info();
  if (info.boundary != BoundaryKind::Periodic)
    return "the box has walls, which exchange momentum with the gas, so its stress fluctuations do not give "
           "the bulk viscosity; run the gas in a periodic box (box.boundary = \"periodic\")";
  if (info.gx != 0 || info.gy != 0) return "the run is under gravity: no homogeneous equilibrium; run without gravity";
  if (info.lees_edwards)
    return "the box is sheared (Lees-Edwards): the kinetic stress needs the flow subtracted and the impulses the "
           "sliding image, which this analysis does not do yet; measure the viscosity of an equilibrium run in a "
           "periodic box";
  if (info.rotates)
    return "the disks are rough or spin: their stress has an antisymmetric part coupled to the spins, which this "
           "analysis does not treat; use smooth disks";
  // A log made without a scene (the library's tests write some) is judged by its events alone: the walk
  // refuses a thermostat's redraw when it meets one.
  auto scene = log.scene();
  if (!scene) return "";
  if (!scene.value().physics.elastic())
    return "collisions are inelastic (restitution below 1): the gas cools and is not in equilibrium; set "
           "physics.restitution = 1";
  if (scene.value().thermostatted())
    return "the Andersen thermostat redraws velocities, which destroys momentum and with it the stress "
           "correlations (the result would be a thermostat-dependent number, not the viscosity); equilibrate with "
           "the thermostat, then continue without it ([start] from the thermostatted log) and analyse that log";
  return "";
}

Result<StressIntegral> integrate(const Log& log, double from, double bin_width, std::size_t bins) {
  const std::string where = log.info().path + ": stress integral: ";
  auto s = log.state_at(from);
  if (!s) return s.error();
  // The last edge, or the log's end where the rounding of bins * bin_width passes it.
  const long double end = std::min((long double)from + (long double)bin_width * (long double)bins, log.info().end_time);
  transport::Window w;
  w.from = from;
  w.to = double(end);
  if ((long double)w.to > end) w.to = std::nextafter(w.to, from);  // no event after the last edge
  w.start = std::move(s).value();
  StressIntegral out;
  out.from = from, out.bin_width = bin_width, out.area = w.start.lx * w.start.ly, out.disks = w.start.size();
  StressWalk walk(w.start, from, bin_width, bins, out);
  std::string refused;
  Status walked = transport::for_each_window_event(log, w, true, [&](const transport::StreamEvent& e) {
    if (!refused.empty()) return;
    walk.integrate_to(e.time);
    switch (e.kind) {
      case EventKind::Pair: ++out.pair_events, walk.pair(e); break;
      case EventKind::Step: ++out.step_events, walk.pair(e); break;  // its impulse is along the line of centres too
      case EventKind::Wrap: break;                                   // a move by one box length: no velocity changes
      default:
        refused = std::string("a ") + to_string(e.kind) + " event at t = " + brief(e.time) +
                  (e.kind == EventKind::Action
                       ? " reverses every velocity inside the window; choose a window before or after it"
                       : " changes a velocity from outside the gas; this analysis needs a closed, periodic gas");
    }
  });
  if (!walked) return walked.error();
  if (!refused.empty()) return Error{where + refused};
  walk.finish(end);
  return out;
}

}  // namespace ede::stress
