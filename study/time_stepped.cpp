// TimeStepped: the fixed-dt baseline of the accuracy study (see time_stepped.hpp for what it is for).
//
// A step: move everyone by v dt; bounce the disks past a wall (or wrap them, periodic); rebuild the cell
// list (the engine's grid shape); resolve every overlapping pair once: disks in index order, each against
// the later disks of its own cell and every disk of a half stencil of neighbouring cells, each pair with
// the positions left by the pairs before it. The cells are not updated for pushes: a pair a push makes
// overlap across non-neighbouring cells is found at the next step. Collision rules are the engine's
// (collide.hpp), so the only difference the study measures is *when* and *where* a collision is seen.
// Rejected: walking the grid cell by cell (at ~4 cells per disk most are empty: a third slower, measured)
// and coarser cells than the engine's (more candidate pairs: slower too).
// Walls: a disk moving outwards is mirrored about the wall, its overshoot scaled by the restitution: that
// is where it would be had it bounced at the crossing (exactly so for xi_w = 1), so a lone wall bounce
// costs nothing and the study's errors come from pairs. The tangential drift of the overshoot is not
// corrected. A disk past a wall but moving inwards (pushed there by a pair) is only clamped to touch it.
// Rejected: clamping every bounce to contact, which shortens each flight by the overshoot and biases the
// wall collision rate and pressure by O(v dt) for no gain in simplicity.
// Pairs: pushed apart along the line of centres to contact, each by the other's share of the mass, so the
// centre of mass stays put and velocities (hence energy) are untouched. Rejected: moving each disk half
// the overlap (moves the centre of mass for unequal masses), and backing the pair up along its velocities
// to the contact time (that is event-driven resolution done badly: it is not what the baseline stands for).
#include "study/time_stepped.hpp"

#include <algorithm>
#include <cmath>

#include "ede/internal/engine_template.hpp"
#include "ede/internal/physics.hpp"
#include "ede/internal/setup.hpp"
#include "ede/number_text.hpp"

namespace ede {

namespace {

constexpr std::int32_t kNone = -1;
constexpr const char* kSource = "time-stepped run";
// Neighbour cells visited from a disk's cell: with the cell itself, every cell pair of a 3 x 3 block once.
constexpr std::int32_t kHalfStencil[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};

Error refused(const std::string& why) { return Error{std::string(kSource) + ": " + why}; }

Status check_options(const TimeSteppedOptions& o) {
  if (!std::isfinite(o.dt) || o.dt <= 0)
    return refused("the time step dt = " + brief(o.dt) + " must be finite and > 0");
  if (!(o.restitution >= 0 && o.restitution <= 1))
    return refused("the pair restitution " + brief(o.restitution) + " must lie in [0, 1]");
  if (!(o.wall_restitution >= 0 && o.wall_restitution <= 1))
    return refused("the wall restitution " + brief(o.wall_restitution) + " must lie in [0, 1]");
  return Ok{};
}

Status check_periodic_box(const InitialState& s, double max_radius) {
  const double least = 3 * 2 * max_radius * (1 + 1e-6);
  if (s.lx >= least && s.ly >= least) return Ok{};
  return refused("a periodic box must be at least three largest diameters wide on each side (largest diameter " +
                 brief(2 * max_radius) + ", box " + brief(s.lx) + " x " + brief(s.ly) +
                 "); enlarge the box or use walls");
}

// Into [0, l): one box is a subtraction; more (a huge dt) takes floor. A tiny negative x rounds to l when
// shifted: 0 is its image within round-off.
double wrapped(double x, double l) {
  if (x >= 0 && x < l) return x;
  x = x - l * std::floor(x / l);
  return x < l ? x : 0.0;
}

double minimum_image(double d, double l) {
  if (d > 0.5 * l) return d - l;
  if (d < -0.5 * l) return d + l;
  return d;
}

// Scaled by the inverse cell width: a product is cheaper than a quotient, and a disk put one ulp into the
// next cell is still within the cell's margin over a diameter.
std::int32_t clamped_index(double x, double inverse_width, std::int32_t n) {
  const double f = std::floor(x * inverse_width);
  if (!(f >= 0)) return 0;
  if (f >= double(n - 1)) return n - 1;
  return std::int32_t(f);
}

// Which wall (if any) the disk's edge is past along one axis: -1 the low one, +1 the high one.
int past_wall(double p, double r, double l) {
  if (p - r < 0) return -1;
  if (p + r > l) return 1;
  return 0;
}

}  // namespace

Result<TimeStepped> TimeStepped::create(const InitialState& initial, const TimeSteppedOptions& options) {
  if (Status st = check_options(options); !st) return st.error();
  if (Status st = check_initial_state(initial, options.boundary, kSource); !st)
    return st.error();
  const double max_radius = *std::max_element(initial.radius.begin(), initial.radius.end());
  const bool periodic = options.boundary == BoundaryKind::Periodic;
  if (periodic) {
    if (Status st = check_periodic_box(initial, max_radius); !st) return st.error();
  }
  TimeStepped ts;
  ts.options_ = options;
  ts.lx_ = initial.lx;
  ts.ly_ = initial.ly;
  ts.x_ = initial.x;
  ts.y_ = initial.y;
  ts.vx_ = initial.vx;
  ts.vy_ = initial.vy;
  ts.r_ = initial.radius;
  ts.m_ = initial.mass;
  const GridShape g = grid_shape_for(initial.lx, initial.ly, max_radius, initial.size(), periodic, Algorithm::Cells);
  ts.nx_ = g.nx;
  ts.ny_ = g.ny;
  ts.cell_ix_ = double(g.nx) / initial.lx;
  ts.cell_iy_ = double(g.ny) / initial.ly;
  ts.next_in_cell_.assign(initial.size(), kNone);
  ts.cell_x_.assign(initial.size(), 0);
  ts.cell_y_.assign(initial.size(), 0);
  return ts;
}

void TimeStepped::run_until(double t) {
  if (!std::isfinite(t)) return;
  const double dt = options_.dt;
  while (anchor_time_ + double(whole_steps_ + 1) * dt <= t) {
    step(dt);
    ++whole_steps_;
    time_ = anchor_time_ + double(whole_steps_) * dt;
  }
  if (time_ < t) {
    step(t - time_);
    time_ = anchor_time_ = t;
    whole_steps_ = 0;
  }
}

double TimeStepped::kinetic_energy() const {
  long double e = 0;
  for (std::size_t i = 0; i < x_.size(); ++i)
    e += 0.5L * (long double)m_[i] * ((long double)vx_[i] * vx_[i] + (long double)vy_[i] * vy_[i]);
  return double(e);
}

void TimeStepped::step(double dt) {
  move(dt);
  if (options_.boundary == BoundaryKind::Walls)
    resolve_walls();
  else
    wrap_all();
  build_cells();
  resolve_pairs();
  ++counts_.steps;
}

void TimeStepped::move(double dt) {
  for (std::size_t i = 0; i < x_.size(); ++i) {
    x_[i] = x_[i] + vx_[i] * dt;
    y_[i] = y_[i] + vy_[i] * dt;
  }
}

void TimeStepped::wrap_all() {
  for (std::size_t i = 0; i < x_.size(); ++i) {
    x_[i] = wrapped(x_[i], lx_);
    y_[i] = wrapped(y_[i], ly_);
  }
}

// Per axis, vertical walls first: a disk in a corner bounces off both (two wall collisions).
void TimeStepped::resolve_walls() {
  const double xi = options_.wall_restitution;
  for (std::size_t i = 0; i < x_.size(); ++i) {
    for (const bool vertical : {true, false}) {
      double& p = vertical ? x_[i] : y_[i];
      const double l = vertical ? lx_ : ly_, r = r_[i];
      const int side = past_wall(p, r, l);
      if (side == 0) continue;
      const double contact = side < 0 ? r : l - r;
      double back = 0;  // how far inside contact the disk ends
      if (double(side) * (vertical ? vx_[i] : vy_[i]) > 0) {
        if (xi == 1.0)
          collide_wall_elastic(vertical, vx_[i], vy_[i]);
        else
          collide_wall(vertical, xi, vx_[i], vy_[i]);
        ++counts_.wall_collisions;
        back = xi * std::abs(p - contact);
      }
      p = side < 0 ? contact + back : contact - back;
      p = std::clamp(p, r, l - r);
    }
  }
}

// Disks pushed in lower indices first, so each cell's list runs in increasing index.
void TimeStepped::build_cells() {
  cell_head_.assign(std::size_t(nx_) * std::size_t(ny_), kNone);
  for (std::size_t k = x_.size(); k-- > 0;) {
    const std::int32_t cx = clamped_index(x_[k], cell_ix_, nx_), cy = clamped_index(y_[k], cell_iy_, ny_);
    const std::int32_t c = cy * nx_ + cx;
    cell_x_[k] = cx;
    cell_y_[k] = cy;
    next_in_cell_[k] = cell_head_[std::size_t(c)];
    cell_head_[std::size_t(c)] = std::int32_t(k);
  }
}

void TimeStepped::resolve_pairs() {
  const bool periodic = options_.boundary == BoundaryKind::Periodic;
  // The overlap test inline (nearly every candidate fails it), the resolution out of line.
  const auto visit = [&](std::size_t i, std::size_t j) {
    double dx = x_[j] - x_[i], dy = y_[j] - y_[i];
    if (periodic) {
      dx = minimum_image(dx, lx_);
      dy = minimum_image(dy, ly_);
    }
    const double s = r_[i] + r_[j];
    if (dx * dx + dy * dy < s * s) resolve_overlap(i, j, dx, dy);
  };
  for (std::size_t i = 0; i < x_.size(); ++i) {
    for (std::int32_t j = next_in_cell_[i]; j != kNone; j = next_in_cell_[std::size_t(j)]) visit(i, std::size_t(j));
    for (const auto& d : kHalfStencil) {
      std::int32_t ox = cell_x_[i] + d[0], oy = cell_y_[i] + d[1];
      if (periodic) {
        ox = ox == nx_ ? 0 : ox < 0 ? nx_ - 1 : ox;
        oy = oy == ny_ ? 0 : oy;
      } else if (ox < 0 || ox >= nx_ || oy >= ny_) {
        continue;
      }
      for (std::int32_t j = cell_head_[std::size_t(oy * nx_ + ox)]; j != kNone; j = next_in_cell_[std::size_t(j)])
        visit(i, std::size_t(j));
    }
  }
}

// Overlap recorded, the engine's rule if approaching, then the push to contact. Coincident centres have
// no line of centres: such a pair is left alone (the next step separates them unless they move together).
void TimeStepped::resolve_overlap(std::size_t i, std::size_t j, double dx, double dy) {
  const double s = r_[i] + r_[j];
  const double dist = std::sqrt(dx * dx + dy * dy);
  if (dist == 0) return;
  largest_overlap_ = std::max(largest_overlap_, (s - dist) / s);
  if ((vx_[j] - vx_[i]) * dx + (vy_[j] - vy_[i]) * dy < 0) {
    collide_pair(dx, dy, m_[i], m_[j], 1.0 + options_.restitution, vx_[i], vy_[i], vx_[j], vy_[j]);
    ++counts_.pair_collisions;
  }
  const double depth = (s - dist) / dist;  // per unit of (dx, dy)
  const double total = m_[i] + m_[j];
  const double ki = depth * (m_[j] / total), kj = depth * (m_[i] / total);
  x_[i] = x_[i] - ki * dx;
  y_[i] = y_[i] - ki * dy;
  x_[j] = x_[j] + kj * dx;
  y_[j] = y_[j] + kj * dy;
  if (options_.boundary == BoundaryKind::Periodic) {
    x_[i] = wrapped(x_[i], lx_);
    y_[i] = wrapped(y_[i], ly_);
    x_[j] = wrapped(x_[j], lx_);
    y_[j] = wrapped(y_[j], ly_);
  }
}

}  // namespace ede
