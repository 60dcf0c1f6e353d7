// stress_integral (ede/viscosity.hpp) and its walk (stress_walk.hpp). Between events the integrand
// sum_i m_i c_ia c_ib is a polynomial in time, kept as running sums over the disks, so each event costs O(1)
// whatever N; each event adds its impulse term r_ij,a dp_i,b to the bin holding it (an event on a bin edge
// belongs to the bin it opens) and changes the sums by its participants' velocities. Sums are long double:
// the impulse terms of a bin nearly cancel in the off-diagonal components.
//
// The peculiar velocity c = v - u(y) - U is taken relative to the streaming velocity u(y) = (gamma y, 0)
// (gamma the shear rate; 0 in an equilibrium run) and to the mean U of v - u over the disks. With tau the
// time since the walk's reference time and, per disk, a = v_x - gamma Y, Y = y(tau) - v_y tau (constant
// between the disk's events: the height it would have had at tau = 0),
//   c_x + U_x = a - gamma v_y tau,   c_y + U_y = v_y,
// so with the sums M = sum m, P = sum m a, Q = sum m v_y, S_aa = sum m a^2, S_av = sum m a v_y,
// S_vv = sum m v_y^2 and the centre-of-mass forms k_xx = S_aa - P^2 / M, k_xy = S_av - P Q / M,
// k_yy = S_vv - Q^2 / M (expand m (c + U)_a (c + U)_b and subtract M U_a U_b):
//   K_yy = k_yy,   K_xy(tau) = k_xy - gamma tau k_yy,   K_xx(tau) = k_xx - 2 gamma tau k_xy + gamma^2 tau^2 k_yy,
// integrated exactly over each stretch between events. A crossing of a sliding edge (a shear event) moves
// y by -+ly and v_x by -+gamma ly: a, and so c, do not change; a pair across the edge meets the image of
// its partner shifted by the images' offset (`separation`). The reference time moves to the latest event
// every N events (the sums are then recomputed from the disks), so tau, and the cancellation in K_xx,
// stay small in a long window. With gamma = 0 every term in gamma vanishes and this is the equilibrium
// walk: S_ab and P_a P_b / M over the velocities.
// Rejected: summing m c_a c_b over every disk at every event (O(N) per event).
#include "analysis/stress_walk.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/transport_stream.hpp"
#include "core/sliding_images.hpp"
#include "ede/number_text.hpp"

namespace ede::stress {

namespace {

// The sliding boundary: the shear rate and the box, for the peculiar velocity and the separation of a pair
// across the sliding edge (an equilibrium run: rate 0, plain periodic images).
struct Flow {
  long double rate = 0, lx = 1, ly = 1;
  // The images' offset at t (core/sliding_images.hpp), in long double: the run's own type's rounding of it
  // is far below what the separation of a pair at contact needs.
  long double offset(long double t) const { return images_offset(image_slide(double(rate), ly), t, lx); }
  // The separation r_i - r_j of a pair at contact at time t: the nearest image, through the sliding one
  // when the pair is across the top or bottom edge (a contact is far closer than half a box).
  void separation(long double& dx, long double& dy, long double t) const {
    const long double rows = std::nearbyint(dy / ly);  // +1: j's image above i's row is the one met
    dy -= ly * rows;
    if (rows != 0 && rate != 0) dx -= rows * offset(t);
    dx -= lx * std::nearbyint(dx / lx);
  }
};

class StressWalk {
 public:
  StressWalk(const State& s, const Flow& flow, double from, double width, std::size_t bins, StressIntegral& out)
      : flow_(flow), from_(from), width_(width), bins_(bins), out_(out), t_prev_(from), t_ref_(from) {
    out_.xx.assign(bins, 0), out_.yy.assign(bins, 0), out_.xy.assign(bins, 0), out_.yx.assign(bins, 0);
    out_.kinetic.assign(bins, 0);
    xx_.assign(bins, 0), yy_.assign(bins, 0), xy_.assign(bins, 0), yx_.assign(bins, 0), kin_.assign(bins, 0);
    const std::size_t n = s.size();
    mass_.resize(n), vx_.resize(n), vy_.resize(n), y0_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      mass_[i] = s.mass.exact(i);
      vx_[i] = s.vx.exact(i), vy_[i] = s.vy.exact(i), y0_[i] = s.y.exact(i);
    }
    rebase_every_ = std::max<std::size_t>(n, 1024);
    resum();
  }

  // Adds the kinetic integral up to t, bin by bin.
  void integrate_to(long double t) {
    while (bin_ + 1 < bins_ && edge(bin_ + 1) <= t) {
      add_kinetic(edge(bin_ + 1));
      t_prev_ = edge(++bin_);
    }
    add_kinetic(t);
    t_prev_ = t;
  }

  // A pair or step event at e.time: the impulse term, then the new velocities.
  void pair(const transport::StreamEvent& e) {
    const auto i = std::size_t(e.i), j = std::size_t(e.j);
    long double dx = (long double)e.xi - e.xj, dy = (long double)e.yi - e.yj;
    flow_.separation(dx, dy, e.time);
    const long double dpx = mass_[i] * ((long double)e.vix - vx_[i]);
    const long double dpy = mass_[i] * ((long double)e.viy - vy_[i]);
    xx_[bin_] += dx * dpx, yy_[bin_] += dy * dpy, xy_[bin_] += dx * dpy, yx_[bin_] += dy * dpx;
    out_.impulse_xx += dx * dpx, out_.impulse_yy += dy * dpy, out_.impulse_xy += dx * dpy, out_.impulse_yx += dy * dpx;
    set_disk(i, e.time, e.yi, e.vix, e.viy);
    set_disk(j, e.time, e.yj, e.vjx, e.vjy);
    count_event(e.time);
  }

  // A disk whose velocity changes without a partner (a shear crossing: position and velocity shifted
  // together; a thermostat's redraw: no impulse between disks, so no stress term).
  void single(const transport::StreamEvent& e) {
    set_disk(std::size_t(e.i), e.time, e.yi, e.vix, e.viy);
    count_event(e.time);
  }

  void finish(long double end) {
    integrate_to(end);
    for (std::size_t k = 0; k < bins_; ++k) {
      out_.xx[k] = double(xx_[k]), out_.yy[k] = double(yy_[k]);
      out_.xy[k] = double(xy_[k]), out_.yx[k] = double(yx_[k]);
      out_.kinetic[k] = double(kin_[k]);
    }
  }

 private:
  long double edge(std::size_t k) const { return (long double)from_ + (long double)width_ * (long double)k; }

  // The kinetic integral from t_prev_ to t into the current bin (tau measured from t_ref_).
  void add_kinetic(long double t) {
    const long double dt = t - t_prev_;
    if (dt == 0) return;
    const long double k_xx = saa_ - p_ * p_ / total_mass_, k_xy = sav_ - p_ * q_ / total_mass_;
    const long double k_yy = svv_ - q_ * q_ / total_mass_, g = flow_.rate;
    // Integrals of 1, tau and tau^2 over [tau0, tau1] (the differences factored to keep them accurate).
    const long double a = t_prev_ - t_ref_, b = t - t_ref_;
    const long double i1 = dt * (a + b) / 2, i2 = dt * (a * a + a * b + b * b) / 3;
    const long double kxx = k_xx * dt - 2 * g * k_xy * i1 + g * g * k_yy * i2;
    const long double kxy = k_xy * dt - g * k_yy * i1, kyy = k_yy * dt;
    xx_[bin_] += kxx, yy_[bin_] += kyy, xy_[bin_] += kxy, yx_[bin_] += kxy, kin_[bin_] += kxx + kyy;
    out_.kinetic_xx += kxx, out_.kinetic_yy += kyy, out_.kinetic_xy += kxy;
  }

  // a = v_x - gamma Y for disk i, Y its height at the reference time.
  long double a_of(std::size_t i) const { return vx_[i] - flow_.rate * y0_[i]; }

  // Disk i's new velocity at time t at height y (the walk has integrated up to t).
  void set_disk(std::size_t i, long double t, long double y, long double vx, long double vy) {
    remove(i);
    vx_[i] = vx, vy_[i] = vy, y0_[i] = y - vy * (t - t_ref_);
    add(i);
  }
  void add(std::size_t i) {
    const long double m = mass_[i], a = a_of(i), v = vy_[i];
    p_ += m * a, q_ += m * v, saa_ += m * a * a, sav_ += m * a * v, svv_ += m * v * v;
  }
  void remove(std::size_t i) {
    const long double m = mass_[i], a = a_of(i), v = vy_[i];
    p_ -= m * a, q_ -= m * v, saa_ -= m * a * a, sav_ -= m * a * v, svv_ -= m * v * v;
  }
  // The sums afresh from the disks (no rounding carried over from earlier events).
  void resum() {
    total_mass_ = p_ = q_ = saa_ = sav_ = svv_ = 0;
    for (std::size_t i = 0; i < mass_.size(); ++i) total_mass_ += mass_[i], add(i);
  }
  // In a sheared box, every rebase_every_ events the reference time moves to t: each Y moves to the
  // disk's height at t, and the sums are taken afresh.
  void count_event(long double t) {
    if (flow_.rate == 0 || ++since_rebase_ < rebase_every_) return;
    for (std::size_t i = 0; i < mass_.size(); ++i) y0_[i] += vy_[i] * (t - t_ref_);
    t_ref_ = t, since_rebase_ = 0;
    resum();
  }

  const Flow flow_;
  const double from_, width_;
  const std::size_t bins_;
  StressIntegral& out_;
  std::vector<long double> mass_, vx_, vy_, y0_;  // velocities before the event at hand; Y at t_ref_
  std::vector<long double> xx_, yy_, xy_, yx_, kin_;
  long double total_mass_ = 0, p_ = 0, q_ = 0, saa_ = 0, sav_ = 0, svv_ = 0;
  std::size_t bin_ = 0, since_rebase_ = 0, rebase_every_ = 1024;
  long double t_prev_, t_ref_;
};

}  // namespace

std::string refusal(const Log& log) {
  const LogInfo& info = log.info();
  if (info.boundary != BoundaryKind::Periodic)
    return "the box has walls, which exchange momentum with the gas, so its stress fluctuations do not give "
           "the bulk viscosity; run the gas in a periodic box (box.boundary = \"periodic\")";
  if (info.gx != 0 || info.gy != 0) return "the run is under gravity: no homogeneous equilibrium; run without gravity";
  if (info.lees_edwards)
    return "the box is sheared (Lees-Edwards): its viscosity is the mean stress over the shear rate, not the "
           "equilibrium fluctuations; use sheared_viscosity (ede-stats viscosity reads a sheared log that way)";
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

std::string sheared_stress_refusal(const Log& log) {
  if (log.info().rotates) return "the disks are rough or spin, which this analysis does not treat";
  if (!log.scene()) return "the log carries no scene, so its shear rate is unknown; write it with ede-sim";
  return "";
}

Result<StressIntegral> integrate(const Log& log, double from, double bin_width, std::size_t bins) {
  const std::string where = log.info().path + ": stress integral: ";
  Flow flow;
  flow.lx = log.info().lx, flow.ly = log.info().ly;
  flow.rate = log.info().lees_edwards ? log.info().shear_rate : 0;  // from the scene, read at open
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
  out.shear_rate = double(flow.rate);
  StressWalk walk(w.start, flow, from, bin_width, bins, out);
  std::string refused;
  const bool sheared = log.info().lees_edwards;
  Status walked = transport::for_each_window_event(log, w, true, [&](const transport::StreamEvent& e) {
    if (!refused.empty()) return;
    walk.integrate_to(e.time);
    switch (e.kind) {
      case EventKind::Pair: ++out.pair_events, walk.pair(e); break;
      case EventKind::Step: ++out.step_events, walk.pair(e); break;  // its impulse is along the line of centres too
      case EventKind::Wrap: break;                                   // a move by one box length: no velocity changes
      case EventKind::Shear: walk.single(e); break;                  // c unchanged; a and Y follow the new y
      case EventKind::Thermostat:
        if (sheared) {  // the thermostat about the flow: a redraw, no impulse between disks
          ++out.thermostat_events, walk.single(e);
          break;
        }
        [[fallthrough]];
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
