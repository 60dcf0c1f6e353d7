// end_of_run_problem: what the end of a run must show before it may be reported as done, for a run whose
// scales passed the checks before it (run/scale_checks.hpp) and still left its scalar type's contract on
// the way (a stop.events run whose clock went past what the type resolves, say).
//
// Three findings turn a run that ended (a stop condition, "no more events", Simulation::finish) into one
// that stopped with an error (RunStatus::Inexact, exit 4):
//   - "no more events" while a disk still moves (or falls): in a box every moving disk reaches a wall or
//     wraps, so no event at all means every predicted time overflowed the type;
//   - the position resolution eps (L + 2 V t) at the end above 1/64 of the smallest diameter: the clock
//     no longer tells the disks' positions apart (V the fastest disk now);
//   - two disks overlapping by more than kOverlapResolutions times that resolution: more than the
//     round-off of the type can explain (accuracy.md measures ~1.5 of it in float after 10^7 events).
// The scan is a cell list over the final positions (computed with the shared drift functions) with two int
// arrays (4 B per disk and at most two per disk for the cells), and each disk is checked against the disks
// no larger than itself within its own diameter, so one large disk costs its own area in cells, not N^2.
// Depths are computed in long double from the run's own positions. In a Lees-Edwards box a pair across the
// top or bottom edge is measured through the sliding image, as the engine pairs it.
// Rejected: a check in the engine's loop (the engine stays free of run policy, and a check per event costs
// every run), and setup's PlacementGrid (double positions: coarser than a long double run's contract, and
// three double arrays per disk).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ede/number_text.hpp"
#include "core/particles.hpp"
#include "core/sliding_images.hpp"
#include "ede/events.hpp"
#include "ede/scene.hpp"
#include "run/scale_checks.hpp"

namespace ede {

inline constexpr double kOverlapResolutions = 16;

struct EndCheckContext {
  std::string source;
  ScalarKind scalar = ScalarKind::Double;
  double lx = 1, ly = 1;
  bool periodic = false;
  bool gravity = false;
  double shear_rate = 0;  // a Lees-Edwards box's: pairs across its top and bottom edges meet the sliding image
};

namespace end_check_detail {

struct Worst {
  std::size_t pairs = 0, i = 0, j = 0;
  long double depth = 0, contact = 1;
};

// Cells of side w over the box; each disk's cell from its position (wrapped when periodic, clamped when not).
class CellList {
 public:
  CellList(double lx, double ly, double w, bool periodic, std::size_t n)
      : lx_(lx), ly_(ly), w_(w), periodic_(periodic) {
    const double cap = 2.0 * double(n) + 16;  // at most ~2 cells per disk, whatever the radii
    nx_ = std::int64_t(std::clamp(std::floor(lx / w), 1.0, cap));
    ny_ = std::int64_t(std::clamp(std::floor(ly / w), 1.0, std::max(1.0, cap / double(nx_))));
    wx_ = lx / double(nx_), wy_ = ly / double(ny_);
    head_.assign(std::size_t(nx_ * ny_), -1);
    next_.assign(n, -1);
  }
  std::int64_t nx() const { return nx_; }
  std::int64_t ny() const { return ny_; }
  std::int64_t col(long double x) const { return index(x, lx_, wx_, nx_); }
  std::int64_t row(long double y) const { return index(y, ly_, wy_, ny_); }
  double wx() const { return wx_; }
  double wy() const { return wy_; }
  void insert(std::int32_t i, std::int64_t cx, std::int64_t cy) {
    std::int32_t& h = head_[std::size_t(cy * nx_ + cx)];
    next_[std::size_t(i)] = h;
    h = i;
  }
  template <class F>
  void for_each_in(std::int64_t cx, std::int64_t cy, F&& f) const {
    for (std::int32_t j = head_[std::size_t(cy * nx_ + cx)]; j >= 0; j = next_[std::size_t(j)]) f(j);
  }

 private:
  std::int64_t index(long double v, double side, double width, std::int64_t cells) const {
    if (periodic_) v -= side * std::floor(double(v / side));
    const long double c = std::floor(v / width);
    return std::int64_t(std::clamp<long double>(c, 0, (long double)(cells - 1)));
  }
  double lx_, ly_, w_, wx_ = 1, wy_ = 1;
  bool periodic_;
  std::int64_t nx_ = 1, ny_ = 1;
  std::vector<std::int32_t> head_, next_;
};

// The cells [lo, hi] along one axis, wrapped when periodic (each at most once), clamped when not.
template <class F>
void for_each_cell(std::int64_t lo, std::int64_t hi, std::int64_t cells, bool periodic, F&& f) {
  if (!periodic) {
    for (std::int64_t c = std::max<std::int64_t>(lo, 0); c <= std::min(hi, cells - 1); ++c) f(c);
    return;
  }
  if (hi - lo + 1 >= cells) lo = 0, hi = cells - 1;
  for (std::int64_t c = lo; c <= hi; ++c) f(((c % cells) + cells) % cells);
}

template <class T>
Worst scan_overlaps(const Particles<T>& p, T time, const EndCheckContext& ctx, long double tolerance) {
  const std::size_t n = p.size();
  long double radius_sum = 0;
  for (std::size_t i = 0; i < n; ++i) radius_sum += (long double)p.disk[i].r;
  const double side = std::max(ctx.lx, ctx.ly);
  const double w = std::max(double(2 * radius_sum / (long double)n), side / 65536);
  CellList cells(ctx.lx, ctx.ly, w, ctx.periodic, n);
  for (std::size_t i = 0; i < n; ++i)
    cells.insert(std::int32_t(i), cells.col((long double)p.x_at(i, time)), cells.row((long double)p.y_at(i, time)));
  // A Lees-Edwards box: the image above is shifted by the offset the engine has at `time`.
  const long double offset =
      ctx.shear_rate != 0 ? (long double)images_offset(image_slide(ctx.shear_rate, T(ctx.ly)), time, T(ctx.lx)) : 0;
  Worst worst;
  for (std::size_t i = 0; i < n; ++i) {
    const long double xi = (long double)p.x_at(i, time), yi = (long double)p.y_at(i, time);
    const long double ri = (long double)p.disk[i].r, reach = 2 * ri + tolerance;
    const auto visit = [&](std::int32_t j32) {
      const std::size_t j = std::size_t(j32);
      const long double rj = (long double)p.disk[j].r;
      if (j == i || rj > ri || (rj == ri && j < i)) return;  // each pair once, from its larger disk
      long double dx = (long double)p.x_at(j, time) - xi, dy = (long double)p.y_at(j, time) - yi;
      if (ctx.periodic) {
        const long double rows = std::round(double(dy / ctx.ly));  // +1: j's image below is the nearer
        dy -= (long double)ctx.ly * rows;
        dx -= rows * offset;
        dx -= (long double)ctx.lx * std::round(double(dx / ctx.lx));
      }
      const long double contact = ri + rj, depth = contact - std::hypot(dx, dy);
      if (!(depth > tolerance)) return;
      if (worst.pairs++ == 0 || depth / contact > worst.depth / worst.contact)
        worst.i = std::min(i, j), worst.j = std::max(i, j), worst.depth = depth, worst.contact = contact;
    };
    const auto cols = [&](long double x) { return std::int64_t(std::floor(double(x / cells.wx()))); };
    const auto lo_y = std::int64_t(std::floor(double((yi - reach) / cells.wy())));
    const auto hi_y = std::int64_t(std::floor(double((yi + reach) / cells.wy())));
    if (offset == 0) {
      for_each_cell(lo_y, hi_y, cells.ny(), ctx.periodic, [&](std::int64_t cy) {
        for_each_cell(cols(xi - reach), cols(xi + reach), cells.nx(), ctx.periodic,
                      [&](std::int64_t cx) { cells.for_each_in(cx, cy, visit); });
      });
      continue;
    }
    // Rows past the top (bottom) edge are the bottom (top) rows slid by +offset (-offset): their columns
    // are searched around xi -+ offset. When the search spans every row, every column too.
    const std::int64_t ny = cells.ny();
    const bool every_row = hi_y - lo_y + 1 >= ny;
    for (std::int64_t raw = every_row ? 0 : lo_y; raw <= (every_row ? ny - 1 : hi_y); ++raw) {
      const std::int64_t k = raw >= 0 ? raw / ny : -((-raw + ny - 1) / ny), cy = raw - k * ny;
      const long double x = xi - (long double)k * offset;
      const std::int64_t lo_x = every_row ? 0 : cols(x - reach), hi_x = every_row ? cells.nx() - 1 : cols(x + reach);
      for_each_cell(lo_x, hi_x, cells.nx(), true, [&](std::int64_t cx) { cells.for_each_in(cx, cy, visit); });
    }
  }
  return worst;
}

inline std::string brief(long double v) { return general_text(double(v), 3); }

}  // namespace end_check_detail

// Empty when the run may be reported as it ended; else the message of an Inexact stop.
template <class T>
std::string end_of_run_problem(const Particles<T>& p, T time, RunStatus status, const EndCheckContext& ctx) {
  using namespace end_check_detail;
  if (status == RunStatus::Stalled || status == RunStatus::Collapsed || status == RunStatus::NonFinite ||
      status == RunStatus::Running || p.size() == 0)
    return {};
  const std::string type = std::string("engine.scalar = \"") + to_string(ctx.scalar) + "\"";
  const std::string fix = " Fix: use a wider scalar type than " + type +
                          ", or rescale the units so that the box, the radii and the speeds are near 1, or stop "
                          "earlier.";
  long double fastest = 0, smallest = (long double)p.disk[0].r;
  std::size_t moving = p.size();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const long double v = std::hypot((long double)p.vx_at(i, time), (long double)p.vy_at(i, time));
    if (v > fastest) fastest = v;
    if (v > 0 && moving == p.size()) moving = i;
    smallest = std::min(smallest, (long double)p.disk[i].r);
  }
  if (status == RunStatus::NoMoreEvents && (moving < p.size() || ctx.gravity))
    return ctx.source + ": with " + type + ", the run found no event left at t = " + brief((long double)time) +
           " although " + (ctx.gravity ? "gravity acts" : "disk " + std::to_string(moving) + " still moves") +
           ": in a box every moving disk meets a wall, so its next event's time overflowed the type (largest " +
           largest_value_text(ctx.scalar) + "). The run stopped there, not at rest." + fix;
  // Depths are measured in long double: no finer than its eps, whatever the run's type (__float128).
  const long double eps = std::max<long double>(scalar_epsilon(ctx.scalar), std::numeric_limits<long double>::epsilon());
  const long double resolution =
      eps * ((long double)std::max(ctx.lx, ctx.ly) + 2 * fastest * (long double)time);
  if (resolution > kResolvedShareOfDiameter * 2 * smallest)
    return ctx.source + ": with " + type + ", the position resolution at the end, eps (L + 2 V t) = " +
           brief(resolution) + " at t = " + brief((long double)time) + " and speed " + brief(fastest) +
           ", is more than 1/64 of the smallest diameter " + brief(2 * smallest) +
           ": the clock no longer tells the disks' positions apart, so the run is not exact to its type." + fix;
  const Worst w = scan_overlaps(p, time, ctx, kOverlapResolutions * resolution);
  if (w.pairs == 0) return {};
  return ctx.source + ": with " + type + ", disks " + std::to_string(w.i) + " and " + std::to_string(w.j) +
         " overlap at the end (t = " + brief((long double)time) + ") by " + brief(w.depth / w.contact) +
         " of their contact distance" +
         (w.pairs > 1 ? " (" + std::to_string(w.pairs - 1) + " other overlapping pairs too)" : std::string()) +
         ", more than the type's round-off explains (" + brief(kOverlapResolutions * resolution) +
         "): the arithmetic lost the run." + fix;
}

}  // namespace ede
