// The state of a Lees-Edwards (sheared) box (effects.hpp, LeesEdwardsBoundary): the images above and below
// the box slide in x with velocity +u and -u, u = shear_rate * ly. An engine without it holds NoShear.
//
// The images' offset at time t is offset(t) = fmod(u * t, lx), in [0, lx): a pure function of the time,
// one rounding (the product; fmod is exact; core/sliding_images.hpp, which the log's readers share). So the
// engine needs no state for it, a resumed run computes what the original did, and its error never accumulates: it is the rounding of u * t, as large as the
// position error of any disk moving at u after a time t (the time itself is known to epsilon * t).
// Rejected: an offset carried along and advanced at every event (its rounding would depend on the events,
// compound over a run, and a resumable keyframe would have to store it).
// The cell grid's scans across the sliding edge cover six columns of the slid row (neighbours.hpp,
// for_each_sheared_neighbour): enough for any alignment between -1 and +2 cells of the one at the scan.
// The images slide on between two events of a disk, so every disk of the top and bottom rows is predicted
// again whenever they have slid half a cell (room_shear.hpp, realign_sliding_rows): the clock here.
// Rejected: one realignment per disk in its prediction (the same work, and a fifth crossing kind in the
// hot path of every periodic engine).
#pragma once

#include <cstdint>

#include "core/geometry.hpp"
#include "core/scalar_math.hpp"
#include "core/sliding_images.hpp"

namespace ede {

struct NoShear {};

template <class T>
struct ShearClock {
  T rate = 0;           // the shear rate: the flow's x-velocity grows by rate per unit height
  T half_height = 0;    // ly / 2, where the flow is at rest
  T slide = 0;          // u: the x-velocity of the image above (the one below moves at -u)
  T cell_width = 1;     // of the grid's columns (lx / nx)
  T period = kNever<T>; // the time in which the images slide half a cell: between two realignments
  T next = kNever<T>;   // the next realignment

  void setup(double shear_rate, T lx, T ly, std::int32_t nx) {
    rate = T(shear_rate);
    half_height = ly / T(2);
    slide = image_slide(shear_rate, ly);
    cell_width = lx / T(nx);
    period = slide > 0 ? cell_width / (T(2) * slide) : kNever<T>;
  }
  // The streaming velocity at height y, rate (y - ly / 2): zero at mid-height, so the flow carries no net
  // momentum, and the image above (y + ly) moves faster by exactly the slide, as the sliding edge demands.
  // The thermostat draws about it (room_thermostat.hpp).
  T flow(T y) const { return rate * (y - half_height); }
  // The image above is shifted by +offset(t) in x, the one below by -offset(t).
  T offset(T t, T lx) const { return images_offset(slide, t, lx); }
  // The column of the grid the offset falls in (0 .. nx - 1).
  std::int32_t column_of(T offset, std::int32_t nx) const {
    const T f = ede::floor(offset / cell_width);
    if (!(f >= T(0))) return 0;
    return f >= T(nx - 1) ? nx - 1 : std::int32_t(f);
  }
};

// x brought back into [0, lx) (up to round-off, as a periodic wrap leaves it) from (-lx, 2 lx).
template <class T>
inline T wrap_into_box(T x, T lx) {
  if (x < T(0)) return x + lx;
  if (x >= lx) return x - lx;
  return x;
}

}  // namespace ede
