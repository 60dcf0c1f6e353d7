// The Lubachevsky-Stillinger growth loop (see grow.hpp for the method and why it is its own loop).
//
// State per disk: position at its own time t0 (advanced lazily), velocity, start radius rho, a counter
// bumped whenever its velocity changes, its cell (linked lists), and one pending event: a pair contact
// (valid while the partner's counter is unchanged), a wall or a cell crossing. Cells are at least one
// largest final diameter wide, so a contact is always between disks in neighbouring cells. Every N pair
// collisions the loop brings every disk to the present, measures Z, rescales the velocities to kT = 1 and
// predicts everything afresh. Rejected: rescaling at fixed time intervals (near jamming the collision rate
// diverges and an interval in time would hold ever more events between measurements).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "ede/number_text.hpp"
#include "core/rng.hpp"
#include "setup/grow.hpp"
#include "setup/grow_predict.hpp"
#include "setup/grow_queue.hpp"

namespace ede::setup_detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDefaultJamPressure = 1e6;
constexpr std::uint64_t kVelocityStream = 0x67726f7700000000ull;  // "grow": apart from the species' streams

std::string num(double v) { return general_text(v, 6); }

enum class Kind : std::uint8_t { Pair, Wall, Cell };

double area_sum(const std::vector<double>& r) {
  double a = 0;
  for (double v : r) a += kPi * v * v;
  return a;
}

class Grower {
 public:
  Grower(const GrowInput& in, double a_max) : in_(in), n_(in.x.size()), queue_(et_) {
    x_ = in.x;
    y_ = in.y;
    rho_ = in.r;
    vx_.assign(n_, 0);
    vy_.assign(n_, 0);
    t0_.assign(n_, 0);
    count_.assign(n_, 0);
    et_.assign(n_, kNever);
    partner_.assign(n_, 0);
    pcount_.assign(n_, 0);
    kind_.assign(n_, Kind::Cell);
    dir_.assign(n_, 0);
    double mean = 0, rmax = 0;
    for (double r : rho_) {
      mean += r;
      rmax = std::max(rmax, r);
    }
    mean /= double(n_);
    adot_ = in.rate / (2 * mean);  // d(2 mean rho a)/dt = rate, thermal speed sqrt(kT/m) = 1
    const double width = 2 * rmax * a_max;
    nx_ = std::max(1, int(std::floor(in.lx / width)));
    ny_ = std::max(1, int(std::floor(in.ly / width)));
    wx_ = in.lx / nx_;
    wy_ = in.ly / ny_;
  }

  std::size_t size() const { return n_; }
  double now() const { return now_; }
  double a(double t) const { return 1 + adot_ * t; }
  double adot() const { return adot_; }
  bool grid_too_coarse() const { return in_.periodic && (nx_ < 2 || ny_ < 2); }

  void start(Rng& rng) {
    head_.assign(std::size_t(nx_) * std::size_t(ny_), -1);
    next_.assign(n_, -1);
    prev_.assign(n_, -1);
    cx_.assign(n_, 0);
    cy_.assign(n_, 0);
    for (std::size_t i = 0; i < n_; ++i) {
      double ux = 0, uy = 0;
      rng.unit_vector(ux, uy);
      vx_[i] = std::sqrt(2.0) * ux;  // 1/2 v^2 = kT = 1 (two degrees of freedom)
      vy_[i] = std::sqrt(2.0) * uy;
      cx_[i] = std::clamp(int(std::floor(x_[i] / wx_)), 0, nx_ - 1);
      cy_[i] = std::clamp(int(std::floor(y_[i] / wy_)), 0, ny_ - 1);
      link(i);
    }
    ke_ = kinetic();
    repredict_all();
  }

  // One event; false when the next one lies at or beyond t_end (nothing done then).
  bool step(double t_end) {
    const std::uint32_t i = queue_.top();
    if (!(et_[i] < t_end)) return false;
    now_ = et_[i];
    ++events_;
    switch (kind_[i]) {
      case Kind::Pair: {
        const std::uint32_t j = std::uint32_t(partner_[i]);
        if (count_[j] != pcount_[i]) break;  // stale: the partner moved otherwise since
        collide(i, j);
        predict(j);
        break;
      }
      case Kind::Wall: wall(i); break;
      case Kind::Cell: cross(i); break;
    }
    predict(i);
    return true;
  }

  std::uint64_t pair_collisions() const { return pairs_; }
  std::uint64_t events() const { return events_; }

  // Brings every disk to now, returns Z over the interval since the last call, rescales to kT = 1.
  double measure_and_rescale() {
    sync_all();
    ke_integral_ += ke_ * (now_ - t_ke_);
    t_ke_ = now_;
    const double z = ke_integral_ > 0 ? 1 + virial_ / (2 * ke_integral_) : 0;
    virial_ = 0;
    ke_integral_ = 0;
    const double f = std::sqrt(double(n_) / kinetic());
    for (std::size_t i = 0; i < n_; ++i) {
      vx_[i] *= f;
      vy_[i] *= f;
      ++count_[i];
    }
    ke_ = kinetic();
    repredict_all();
    return z;
  }

  // Every disk at time t (no event may lie before it), radii rho a; positions wrapped or kept off the walls.
  void finish_at(double t, double a_final, GrowResult& out) {
    now_ = t;
    sync_all();
    out.x = x_;
    out.y = y_;
    out.r.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      const double r = rho_[i] * a_final;
      out.r[i] = r;
      if (in_.periodic) {
        out.x[i] = wrap(out.x[i], in_.lx);
        out.y[i] = wrap(out.y[i], in_.ly);
      } else {
        out.x[i] = std::clamp(out.x[i], r, in_.lx - r);
        out.y[i] = std::clamp(out.y[i], r, in_.ly - r);
      }
    }
  }

  // The largest a <= a_now at which no two neighbouring disks overlap and none crosses a wall (round-off
  // near jamming can leave contacts a few ulps inside).
  double largest_free_scale(double a_now) const {
    double a_free = a_now;
    for (std::size_t i = 0; i < n_; ++i) {
      if (!in_.periodic) {
        a_free = std::min({a_free, x_[i] / rho_[i], (in_.lx - x_[i]) / rho_[i], y_[i] / rho_[i],
                           (in_.ly - y_[i]) / rho_[i]});
      }
      for_neighbours(i, [&](std::size_t j) {
        if (j <= i) return;
        double dx = x_[j] - x_[i], dy = y_[j] - y_[i];
        image(dx, dy);
        a_free = std::min(a_free, std::sqrt(dx * dx + dy * dy) / (rho_[i] + rho_[j]));
      });
    }
    return a_free;
  }

 private:
  static double wrap(double v, double l) {
    if (v < 0) v += l;
    if (v >= l) v -= l;
    return v >= l || v < 0 ? 0.0 : v;
  }
  void image(double& dx, double& dy) const {
    if (!in_.periodic) return;
    if (dx > 0.5 * in_.lx) dx -= in_.lx;
    else if (dx < -0.5 * in_.lx) dx += in_.lx;
    if (dy > 0.5 * in_.ly) dy -= in_.ly;
    else if (dy < -0.5 * in_.ly) dy += in_.ly;
  }
  double kinetic() const {
    double k = 0;
    for (std::size_t i = 0; i < n_; ++i) k += 0.5 * (vx_[i] * vx_[i] + vy_[i] * vy_[i]);
    return k;
  }
  void sync(std::size_t i) {
    const double dt = now_ - t0_[i];
    x_[i] += vx_[i] * dt;
    y_[i] += vy_[i] * dt;
    t0_[i] = now_;
  }
  void sync_all() {
    for (std::size_t i = 0; i < n_; ++i) sync(i);
  }
  std::size_t cell_of(std::size_t i) const { return std::size_t(cy_[i]) * std::size_t(nx_) + std::size_t(cx_[i]); }
  void link(std::size_t i) {
    const std::size_t c = cell_of(i);
    prev_[i] = -1;
    next_[i] = head_[c];
    if (head_[c] >= 0) prev_[std::size_t(head_[c])] = std::int32_t(i);
    head_[c] = std::int32_t(i);
  }
  void unlink(std::size_t i) {
    if (prev_[i] >= 0) next_[std::size_t(prev_[i])] = next_[i];
    else head_[cell_of(i)] = next_[i];
    if (next_[i] >= 0) prev_[std::size_t(next_[i])] = prev_[i];
  }
  // Calls f(j) for every disk in the cells around i's (each cell once, also in a grid of 1 or 2 cells).
  template <class F>
  void for_neighbours(std::size_t i, F&& f) const {
    int xs[3], ys[3];
    const int nxs = around(cx_[i], nx_, xs), nys = around(cy_[i], ny_, ys);
    for (int b = 0; b < nys; ++b)
      for (int a = 0; a < nxs; ++a)
        for (std::int32_t j = head_[std::size_t(ys[b]) * std::size_t(nx_) + std::size_t(xs[a])]; j >= 0;
             j = next_[std::size_t(j)])
          if (std::size_t(j) != i) f(std::size_t(j));
  }
  int around(int c, int n, int out[3]) const {
    int k = 0;
    for (int d = -1; d <= 1; ++d) {
      int v = c + d;
      if (in_.periodic) v = (v + n) % n;
      else if (v < 0 || v >= n) continue;
      bool seen = false;
      for (int q = 0; q < k; ++q) seen = seen || out[q] == v;
      if (!seen) out[k++] = v;
    }
    return k;
  }

  void consider(std::size_t i, double t, Kind kind, std::int32_t partner, std::uint8_t dir) {
    const double at = now_ + t;
    if (at < et_[i] || (at == et_[i] && kind == Kind::Pair && kind_[i] == Kind::Pair && partner < partner_[i])) {
      et_[i] = at;
      kind_[i] = kind;
      partner_[i] = partner;
      dir_[i] = dir;
      if (kind == Kind::Pair) pcount_[i] = count_[std::size_t(partner)];
    }
  }

  void predict_events(std::size_t i) {
    sync(i);
    et_[i] = kNever;
    kind_[i] = Kind::Cell;
    partner_[i] = -1;
    const double an = a(now_);
    for_neighbours(i, [&](std::size_t j) {
      const double tj = now_ - t0_[j];
      double dx = (x_[j] + vx_[j] * tj) - x_[i], dy = (y_[j] + vy_[j] * tj) - y_[i];
      image(dx, dy);
      const double rs = rho_[i] + rho_[j];
      consider(i, grow_pair_time(dx, dy, vx_[j] - vx_[i], vy_[j] - vy_[i], rs * an, rs * adot_), Kind::Pair,
               std::int32_t(j), 0);
    });
    const double r = rho_[i] * an, g = rho_[i] * adot_;
    if (!in_.periodic) {
      consider(i, grow_wall_time(x_[i] - r, g - vx_[i]), Kind::Wall, -1, 0);
      consider(i, grow_wall_time(in_.lx - x_[i] - r, g + vx_[i]), Kind::Wall, -1, 1);
      consider(i, grow_wall_time(y_[i] - r, g - vy_[i]), Kind::Wall, -1, 2);
      consider(i, grow_wall_time(in_.ly - y_[i] - r, g + vy_[i]), Kind::Wall, -1, 3);
    }
    consider(i, crossing(x_[i], vx_[i], cx_[i], nx_, wx_), Kind::Cell, -1, vx_[i] > 0 ? 1 : 0);
    consider(i, crossing(y_[i], vy_[i], cy_[i], ny_, wy_), Kind::Cell, -1, vy_[i] > 0 ? 3 : 2);
  }
  double crossing(double p, double v, int c, int n, double w) const {
    if (v > 0 && (in_.periodic || c + 1 < n)) return std::max(0.0, ((c + 1) * w - p) / v);
    if (v < 0 && (in_.periodic || c > 0)) return std::max(0.0, (c * w - p) / v);
    return kNever;
  }
  void predict(std::size_t i) {
    predict_events(i);
    queue_.update(std::uint32_t(i));
  }
  void repredict_all() {
    for (std::size_t i = 0; i < n_; ++i) predict_events(i);
    queue_.build(std::uint32_t(n_));
  }

  void energy_changed(double delta) {
    ke_integral_ += ke_ * (now_ - t_ke_);
    t_ke_ = now_;
    ke_ += delta;
  }

  void collide(std::size_t i, std::size_t j) {
    sync(i);
    sync(j);
    double dx = x_[j] - x_[i], dy = y_[j] - y_[i];
    image(dx, dy);
    const double dist = std::sqrt(dx * dx + dy * dy);
    const double nx = dx / dist, ny = dy / dist;
    const double un = (vx_[j] - vx_[i]) * nx + (vy_[j] - vy_[i]) * ny;
    const double g = (rho_[i] + rho_[j]) * adot_;
    const double J = std::max(0.0, g - un);  // unit masses: u_n -> 2 g - u_n, the gap's speed reversed
    const double before = vx_[i] * vx_[i] + vy_[i] * vy_[i] + vx_[j] * vx_[j] + vy_[j] * vy_[j];
    vx_[i] -= J * nx;
    vy_[i] -= J * ny;
    vx_[j] += J * nx;
    vy_[j] += J * ny;
    const double after = vx_[i] * vx_[i] + vy_[i] * vy_[i] + vx_[j] * vx_[j] + vy_[j] * vy_[j];
    energy_changed(0.5 * (after - before));
    virial_ += dist * J;
    ++count_[i];
    ++count_[j];
    ++pairs_;
  }
  void wall(std::size_t i) {
    sync(i);
    const double g = rho_[i] * adot_;
    const double before = vx_[i] * vx_[i] + vy_[i] * vy_[i];
    switch (dir_[i]) {
      case 0: vx_[i] = 2 * g - vx_[i]; break;
      case 1: vx_[i] = -2 * g - vx_[i]; break;
      case 2: vy_[i] = 2 * g - vy_[i]; break;
      default: vy_[i] = -2 * g - vy_[i]; break;
    }
    energy_changed(0.5 * (vx_[i] * vx_[i] + vy_[i] * vy_[i] - before));
    ++count_[i];
  }
  void cross(std::size_t i) {  // the trajectory is unchanged: partners' predictions stay valid
    sync(i);
    unlink(i);
    switch (dir_[i]) {
      case 0:
        if (--cx_[i] < 0) cx_[i] = nx_ - 1, x_[i] += in_.lx;
        break;
      case 1:
        if (++cx_[i] == nx_) cx_[i] = 0, x_[i] -= in_.lx;
        break;
      case 2:
        if (--cy_[i] < 0) cy_[i] = ny_ - 1, y_[i] += in_.ly;
        break;
      default:
        if (++cy_[i] == ny_) cy_[i] = 0, y_[i] -= in_.ly;
        break;
    }
    link(i);
  }

  const GrowInput& in_;
  std::size_t n_;
  std::vector<double> x_, y_, vx_, vy_, t0_, rho_, et_;
  std::vector<std::uint32_t> count_, pcount_;
  std::vector<std::int32_t> partner_, head_, next_, prev_;
  std::vector<int> cx_, cy_;
  std::vector<Kind> kind_;
  std::vector<std::uint8_t> dir_;
  GrowQueue queue_;
  double adot_ = 0, now_ = 0, wx_ = 1, wy_ = 1;
  int nx_ = 1, ny_ = 1;
  double ke_ = 0, ke_integral_ = 0, t_ke_ = 0, virial_ = 0;
  std::uint64_t pairs_ = 0, events_ = 0;
};

}  // namespace

double grow_start_phi(double target_phi) { return target_phi > 0 ? std::min(0.35, 0.5 * target_phi) : 0.35; }

Result<GrowResult> grow_disks(const GrowInput& in) {
  const auto clock_start = std::chrono::steady_clock::now();
  GrowResult out;
  const double box = in.lx * in.ly;
  out.phi_start = area_sum(in.r) / box;
  // a at the target, or (jamming) at packing fraction 1, which no disks reach: the loop's bound either way.
  const double a_target = in.target_phi > 0 ? std::sqrt(in.target_phi / out.phi_start) : 0;
  const double a_max = a_target > 0 ? a_target : std::sqrt(1 / out.phi_start);
  const double jam_pressure = in.pressure > 0 ? in.pressure : kDefaultJamPressure;
  Grower g(in, a_max);
  if (g.grid_too_coarse())
    return Error{"the periodic box is narrower than two of the largest grown diameters, too small for growth; "
                 "give more, smaller disks (or a larger box)"};
  Rng rng = Rng::for_stream(in.seed, kVelocityStream);
  g.start(rng);
  const double t_end = (a_max - 1) / g.adot();
  const std::uint64_t interval = std::max<std::uint64_t>(g.size(), 16);
  std::uint64_t next_measure = interval;
  // A safety net, never reached by the allowed rates (slowest, 1e-5: ~6e5 events per disk to 0.72).
  const std::uint64_t max_events = 4000000 * std::uint64_t(g.size()) + 100000000;
  bool ended = false;
  while (!ended) {
    if (!g.step(t_end)) break;
    if (g.events() > max_events)
      return Error{"the growth took more than " + std::to_string(max_events) +
                   " events without reaching its end; give a faster grow.rate or a lower grow.pressure"};
    if (g.pair_collisions() >= next_measure) {
      next_measure = g.pair_collisions() + interval;
      out.z = g.measure_and_rescale();
      if (out.z > jam_pressure) {
        out.jammed = true;
        ended = true;
      }
    }
  }
  out.collisions = g.pair_collisions();
  out.events = g.events();
  if (out.jammed) {
    if (in.target_phi > 0 && in.pressure <= 0) {
      const double phi_j = out.phi_start * g.a(g.now()) * g.a(g.now());
      return Error{"the disks jammed (reduced pressure Z = " + num(out.z) + " > 10^6) at packing fraction " +
                   num(phi_j) + ", before reaching grow.packing_fraction = " + num(in.target_phi) +
                   "; give a lower grow.packing_fraction, a slower grow.rate (slow growth jams later), or "
                   "grow.pressure = 1e6 to keep the jammed state"};
    }
    // Contacts a few ulps inside after the last collisions: the radii shrink by that much (relative ~1e-15).
    g.finish_at(g.now(), g.largest_free_scale(g.a(g.now())), out);
  } else if (a_target > 0) {
    g.finish_at(t_end, a_target, out);
  } else {
    return Error{"the disks grew to packing fraction 1 without the pressure passing grow.pressure; "
                 "give a lower grow.pressure"};
  }
  out.phi = area_sum(out.r) / box;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return out;
}

}  // namespace ede::setup_detail
