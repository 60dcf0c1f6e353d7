// accumulate_pressure; see pressure_pass.hpp. Replay gives each event after applying it: the replayed
// state then holds the post-event velocities and the participants' positions at the event time (apply
// brings them there); the mirror holds the velocities before it. The kinetic energy and momentum are
// running sums updated by each event's change, in long double; an action (reversing every velocity)
// resynchronises everything from the replayed state.
// Rejected: taking the pre-event velocities from a second Replay one event behind (twice the decoding)
// or recomputing K from all N disks at every event (O(N) per event).
#include "analysis/pressure_pass.hpp"

#include <cmath>

#include "replay/replay.hpp"

namespace ede {

namespace {

template <class T>
class PressurePass {
 public:
  PressurePass(const Replay<T>& replay, bool periodic, long double lx, long double ly, long double t0,
               long double t1, std::size_t bins, PressureBins& out)
      : replay_(replay), periodic_(periodic), lx_(lx), ly_(ly), t0_(t0), t1_(t1), bins_(bins), out_(out),
        t_prev_(t0) {
    out_.t0 = t0, out_.t1 = t1;
    out_.wall_impulse.assign(bins, {});
    out_.virial.assign(bins, 0);
    out_.kinetic.assign(bins, 0);
    out_.pairs.assign(bins, 0);
    out_.walls.assign(bins, 0);
    resync();
    out_.kinetic_start = kinetic();
  }

  // Takes one event (already applied by the replay); false once the event is after the window.
  bool on_event(const ReplayedEvent<T>& e) {
    if ((long double)e.time > t1_) return false;
    integrate_to(e.time);
    switch (e.kind) {
      case EventKind::Pair:
      case EventKind::Step: pair(e); break;  // a step's impulse acts along the line of centres too
      case EventKind::Wall: wall(e); break;
      case EventKind::Action: resync(); break;
      case EventKind::Thermostat: set_velocity(std::size_t(e.i), e.vix, e.viy); break;  // a redraw: no impulse term
      default: break;  // wraps move a disk by a box length: no velocity change
    }
    return true;
  }

  void finish() {
    integrate_to(t1_);
    out_.kinetic_end = kinetic();
  }

 private:
  long double edge(std::size_t k) const { return t0_ + (t1_ - t0_) * (long double)k / (long double)bins_; }

  // Adds K dt from the last time reached to t, bin by bin.
  void integrate_to(long double t) {
    const long double k = kinetic();
    while (bin_ + 1 < bins_ && edge(bin_ + 1) <= t) {
      out_.kinetic[bin_] += k * (edge(bin_ + 1) - t_prev_);
      t_prev_ = edge(++bin_);
    }
    out_.kinetic[bin_] += k * (t - t_prev_);
    t_prev_ = t;
  }

  long double kinetic() const {
    if (!periodic_) return kin_;
    return kin_ - (px_ * px_ + py_ * py_) / (2 * mass_);
  }

  void set_velocity(std::size_t i, T vx, T vy) {
    const long double m = replay_.particles().mass(i);
    const long double ox = vx_[i], oy = vy_[i], nx = vx, ny = vy;
    kin_ += m * (nx * nx + ny * ny - ox * ox - oy * oy) / 2;
    px_ += m * (nx - ox);
    py_ += m * (ny - oy);
    vx_[i] = vx, vy_[i] = vy;
  }

  void pair(const ReplayedEvent<T>& e) {
    const Particles<T>& p = replay_.particles();
    const std::size_t i = std::size_t(e.i), j = std::size_t(e.j);
    long double dx = (long double)p.disk[i].x - p.disk[j].x;  // r_ij = r_i - r_j, at the event time
    long double dy = (long double)p.disk[i].y - p.disk[j].y;
    if (periodic_) {
      dx -= lx_ * std::nearbyint(dx / lx_);
      dy -= ly_ * std::nearbyint(dy / ly_);
    }
    const long double m = p.mass(i);
    const long double dpx = m * ((long double)e.vix - vx_[i]), dpy = m * ((long double)e.viy - vy_[i]);
    out_.virial[bin_] += dx * dpx + dy * dpy;
    if (e.kind == EventKind::Pair) ++out_.pairs[bin_];
    set_velocity(i, e.vix, e.viy);
    set_velocity(j, e.vjx, e.vjy);
  }

  void wall(const ReplayedEvent<T>& e) {
    const std::size_t i = std::size_t(e.i);
    const bool vertical = e.j == kWallLeft || e.j == kWallRight;
    const long double m = replay_.particles().mass(i);
    const long double dv = vertical ? (long double)e.vix - vx_[i] : (long double)e.viy - vy_[i];
    if (e.j >= 0 && e.j < 4) out_.wall_impulse[bin_][std::size_t(e.j)] += m * std::fabs(dv);
    ++out_.walls[bin_];
    set_velocity(i, e.vix, e.viy);
  }

  // Mirror, kinetic energy and momentum from the replayed state.
  void resync() {
    const Particles<T>& p = replay_.particles();
    vx_.resize(p.size()), vy_.resize(p.size());
    kin_ = px_ = py_ = mass_ = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      vx_[i] = p.disk[i].vx, vy_[i] = p.disk[i].vy;
      const long double m = p.mass(i), vx = vx_[i], vy = vy_[i];
      kin_ += m * (vx * vx + vy * vy) / 2;
      px_ += m * vx, py_ += m * vy, mass_ += m;
    }
  }

  const Replay<T>& replay_;
  const bool periodic_;
  const long double lx_, ly_, t0_, t1_;
  const std::size_t bins_;
  PressureBins& out_;
  std::vector<T> vx_, vy_;  // velocities before the event at hand
  long double kin_ = 0, px_ = 0, py_ = 0, mass_ = 0;
  std::size_t bin_ = 0;
  long double t_prev_;
};

template <class T>
Result<PressureBins> accumulate(const std::shared_ptr<const LogReader>& log, double t0d, double t1d,
                                std::size_t bins) {
  auto made = Replay<T>::create(log);
  if (!made) return made.error();
  Replay<T>& replay = *made.value();
  const T t0 = T(t0d), t1 = T(t1d);
  if (!(t0 < t1)) return Error{"the window is empty in the log's precision"};
  if (Status s = replay.seek_time(t0); !s) return s.error();
  const LogHeaderInfo& h = log->header();
  PressureBins out;
  PressurePass<T> pass(replay, h.boundary == BoundaryKind::Periodic, h.lx, h.ly, t0, t1, bins, out);
  const auto take = [&](const ReplayedEvent<T>& e) { return pass.on_event(e); };
  if (Status s = replay.for_each_event(replay.events_applied(), log->total_events(), take); !s) return s.error();
  pass.finish();
  return out;
}

template <class T>
Result<LogDisks> disks_of(const std::shared_ptr<const LogReader>& log) {
  auto made = Replay<T>::create(log);
  if (!made) return made.error();
  const Replay<T>& replay = *made.value();
  LogDisks out;
  out.count = replay.particles().size();
  long double radius = 0, area = 0;
  for (const Disk<T>& d : replay.particles().disk) {
    radius += d.r;
    area += std::acos(-1.0L) * (long double)d.r * d.r;
  }
  out.radius_sum = double(radius), out.disk_area = double(area);
  const long double end = replay.final_time();
  double e = double(end);
  if ((long double)e > end) e = std::nextafter(e, 0.0);
  out.end_time = e;
  return out;
}

}  // namespace

Result<LogDisks> log_disks(const std::shared_ptr<const LogReader>& log) {
  switch (log->header().scalar) {
    case ScalarKind::Float: return disks_of<float>(log);
    case ScalarKind::LongDouble: return disks_of<long double>(log);
    case ScalarKind::Double: break;
    case ScalarKind::Float128: break;  // never in a log (LogHeaderInfo::scalar)
  }
  return disks_of<double>(log);
}

Result<PressureBins> accumulate_pressure(const std::shared_ptr<const LogReader>& log, double t0, double t1,
                                         std::size_t bins) {
  if (bins == 0) return Error{"no bins"};
  switch (log->header().scalar) {
    case ScalarKind::Float: return accumulate<float>(log, t0, t1, bins);
    case ScalarKind::LongDouble: return accumulate<long double>(log, t0, t1, bins);
    case ScalarKind::Double: break;
    case ScalarKind::Float128: break;  // never in a log (LogHeaderInfo::scalar)
  }
  return accumulate<double>(log, t0, t1, bins);
}

}  // namespace ede
