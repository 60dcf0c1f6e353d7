// The pair room: two disks colliding. Its prediction is the neighbour scan (the earliest contact of a disk
// with the disks of the 3 x 3 cells around it, and with the big disks); its resolution brings both disks to
// the event, applies the collision rule (collide.hpp; restitution, the TC model and the rough rule where
// the engine has them), tells the sinks and re-predicts both.
#pragma once

#include <cstdint>
#include <type_traits>

#include "core/scalar_math.hpp"
#include "engine/collide.hpp"
#include "engine/engine_state.hpp"
#include "engine/neighbours.hpp"
#include "engine/room_step.hpp"

namespace ede {

// A pair that has just collided (each is the other's last partner, no velocity change since) cannot
// meet again through the image they collided in: straight lines cross a circle once on the way in.
// Skipping it keeps round-off from turning their separation into a spurious second collision at once
// (for xi = 0 the post-collision approach speed is zero up to round-off in the velocities, which can
// exceed the position floor of pair_contact_time when both disks move fast).
// In a walled box that is the whole story. In a periodic box the pair can meet again through another
// image after a long flight, and the image they collided in is not recorded: it is the one in which they
// still touch (to kJustCollidedRange), since two images of one disk can never both touch (L >= 3 cells).
// A pair far apart in the collision image is receding there (b > 0), so nothing needs skipping. And a
// pair that touches while approaching faster than round-off (b clearly negative) arrived through another
// image: it is never skipped, so no window is left in which a real collision could be missed.
template <class S>
[[gnu::always_inline]] inline bool just_collided(const S& s, std::int32_t i, std::int32_t k, typename S::Scalar dx,
                                                typename S::Scalar dy) {
  using T = typename S::Scalar;
  if (s.p.disk[i].last_partner != k || s.p.disk[k].last_partner != i) return false;
  if constexpr (S::Effects::kPeriodic) {
    const Disk<T>&di = s.p.disk[i], &dk = s.p.disk[k];
    const T sum = di.r + dk.r;
    if (dx * dx + dy * dy > sum * sum * (T(1) + T(1e-6))) return false;
    const Position2<T> vi = s.vel_at(di), vk = s.vel_at(dk);
    const T b = dx * (vk.x - vi.x) + dy * (vk.y - vi.y);
    const T speeds = ede::abs(vi.x) + ede::abs(vi.y) + ede::abs(vk.x) + ede::abs(vk.y);
    return b >= -T(64) * scalar_limits<T>::epsilon() * sum * speeds;
  }
  return true;
}

// Time at which disks i (at pi with velocity vi, now) and k (image shifted by sx, sy) touch. Under gravity
// their relative motion is still a straight line, from their velocities at now.
template <class S, class T = typename S::Scalar>
T pair_time(const S& s, const Disk<T>& di, Position2<T> pi, Position2<T> vi, const Disk<T>& dk, T sx, T sy) {
  using Contact = typename S::Effects::Contact;
  if constexpr (S::Effects::kGravity) {
    const Position2<T> pk = s.pos_at(dk), vk = s.vel_at(dk);
    return s.now + Contact::time((pk.x + sx) - pi.x, (pk.y + sy) - pi.y, vk.x - vi.x, vk.y - vi.y, di.r + dk.r,
                                 s.b_noise2);
  } else {
    (void)vi;
    return predict_pair<Contact>(di, pi, dk, sx, sy, s.now, s.b_noise2);
  }
}

// Disk i (at pi with velocity vi, now) against disk k's image shifted by (sx, sy): keeps the earlier.
// Straight-line contacts with the library's root are tested without branches on the data up to
// EngineOptions::branch_free_scan_up_to disks (pair_contact_time_select: the same bits).
template <class S, class T = typename S::Scalar>
[[gnu::always_inline]] inline void consider_pair(const S& s, std::int32_t i, Position2<T> pi, Position2<T> vi,
                                                 std::int32_t k, T sx, T sy, Candidate<T>& best) {
  constexpr bool kSelectPairs =
      !S::Effects::kGravity && std::is_same_v<typename S::Effects::Contact, StableContact>;
  const Disk<T>& di = s.p.disk[i];
  const Disk<T>& dk = s.p.disk[k];
  if constexpr (S::Effects::kSteps) {  // the core or a step (room_step.hpp)
    bool skip_core = false;
    if (k == di.last_partner) {
      const Position2<T> pk = s.pos_at(dk);
      skip_core = just_collided(s, i, k, (pk.x + sx) - pi.x, (pk.y + sy) - pi.y);
    }
    return consider_stepped_pair(s, i, pi, vi, k, sx, sy, skip_core, best);
  }
  if (k == di.last_partner) {
    const Position2<T> pk = s.pos_at(dk);
    if (just_collided(s, i, k, (pk.x + sx) - pi.x, (pk.y + sy) - pi.y)) return;
  }
  if (kSelectPairs && s.select_pairs) {
    // Candidate::before spelled out as selects for a pair candidate {t, Pair, k}, so the winner is the same
    // as the branching version's. (Letting disk i itself through, masked here, instead of scan_3x3's test
    // was 7 % slower at 10^4 disks.)
    const T t = predict_pair<StableContactSelect>(di, pi, dk, sx, sy, s.now, s.b_noise2);
    const bool tie_won = (best.kind != EventKind::Pair) | (k < best.partner);
    const bool better = (t < best.time) | ((t == best.time) & tie_won);
    best.time = select_value(better, t, best.time);
    best.partner = better ? k : best.partner;
    best.kind = better ? EventKind::Pair : best.kind;
  } else {
    const T t = pair_time(s, di, pi, vi, dk, sx, sy);
    if (t > best.time) return;
    const Candidate<T> c{t, EventKind::Pair, k};
    if (c.before(best)) best = c;
  }
}

// A Lees-Edwards box (lees_edwards.hpp): disk i (at pi with velocity vi, now) against disk k's image
// shifted by (sx, sy) and moving at k's velocity plus (svx, 0). The root is the stable one of geometry.hpp
// on the relative motion, a straight line (the image slides uniformly); with no shift of the velocity it
// computes what predict_pair does. The pair that has just collided is skipped as just_collided says, in
// the image's own relative velocity.
template <class S, class T = typename S::Scalar>
void consider_sheared_pair(const S& s, std::int32_t i, Position2<T> pi, Position2<T> vi, std::int32_t k, T sx, T sy,
                           T svx, Candidate<T>& best) {
  const Disk<T>& di = s.p.disk[i];
  const Disk<T>& dk = s.p.disk[k];
  const Position2<T> pk = position_at(dk, s.now);
  const T dx = (pk.x + sx) - pi.x, dy = (pk.y + sy) - pi.y;
  const T dvx = (dk.vx + svx) - vi.x, dvy = dk.vy - vi.y;
  const T sum = di.r + dk.r;
  if (k == di.last_partner && dk.last_partner == i && dx * dx + dy * dy <= sum * sum * (T(1) + T(1e-6))) {
    const T speeds = ede::abs(vi.x) + ede::abs(vi.y) + ede::abs(dk.vx + svx) + ede::abs(dk.vy);
    if (dx * dvx + dy * dvy >= -T(64) * scalar_limits<T>::epsilon() * sum * speeds) return;
  }
  const Candidate<T> c{s.now + pair_contact_time(dx, dy, dvx, dvy, sum, s.b_noise2), EventKind::Pair, k};
  if (c.before(best)) best = c;
}

// Best pair candidate of disk i against the disks of cell (cx, cy).
template <class S, class T = typename S::Scalar>
[[gnu::always_inline]] inline void scan_cell(const S& s, std::int32_t i, Position2<T> pi, Position2<T> vi, std::int32_t cx,
                                             std::int32_t cy,
               Candidate<T>& best) {
  visit_cell(s, i, cx, cy, [&](std::int32_t k, T sx, T sy) { consider_pair(s, i, pi, vi, k, sx, sy, best); });
}

// The 3 x 3 cells around (cx, cy), in scan_cell's order (rows from below, columns from the left), with
// the three columns' and rows' wrapping worked out once instead of once per cell: what predict_disk does
// for every small disk, ~40 % of the run. (The order does not change the result: Candidate's order is
// total; it is kept anyway.)
template <class S, class T = typename S::Scalar>
[[gnu::always_inline]] inline void scan_3x3(const S& s, std::int32_t i, Position2<T> pi, Position2<T> vi, std::int32_t cx, std::int32_t cy,
              Candidate<T>& best) {
  if constexpr (S::Effects::kSheared) {
    return for_each_sheared_neighbour(s, i, cx, cy, [&](std::int32_t k, T sx, T sy, T svx) {
      consider_sheared_pair(s, i, pi, vi, k, sx, sy, svx, best);
    });
  }
  std::int32_t col[3], row[3];
  T sx[3], sy[3];
  int ncol = 0, nrow = 0;
  for (std::int32_t d = -1; d <= 1; ++d) {
    std::int32_t c = cx + d;
    T shift = 0;
    if (wrap_index<S>(c, s.grid.nx(), s.lx, shift)) col[ncol] = c, sx[ncol++] = shift;
    c = cy + d;
    shift = 0;
    if (wrap_index<S>(c, s.grid.ny(), s.ly, shift)) row[nrow] = c, sy[nrow++] = shift;
  }
  for (int r = 0; r < nrow; ++r)
    for (int c = 0; c < ncol; ++c)
      for (std::int32_t k = s.grid.head(s.grid.cell_at(col[c], row[r])); k != CellGrid<T>::kNone; k = s.grid.next(k))
        if (k != i) consider_pair(s, i, pi, vi, k, sx[c], sy[r], best);
}

// Disk i against every big disk (but itself). A small disk takes the nearest image, the only one it can
// reach before it next crosses a cell (n >= 2 reach + 3); two big disks try the 3 x 3 images.
template <class S, class T = typename S::Scalar>
void scan_big(const S& s, std::int32_t i, Position2<T> pi, Position2<T> vi, bool i_big, Candidate<T>& best) {
  for (const BigDisk& b : s.big) {
    if (b.id == i) continue;
    if constexpr (S::Effects::kPeriodic) {
      if (i_big) {
        for (int ky = -1; ky <= 1; ++ky)
          for (int kx = -1; kx <= 1; ++kx) consider_pair(s, i, pi, vi, b.id, T(kx) * s.lx, T(ky) * s.ly, best);
        continue;
      }
      const Position2<T> pb = s.pos_at(s.p.disk[b.id]);
      const T dx = pb.x - pi.x, dy = pb.y - pi.y;
      const T sx = dx > s.half_lx ? -s.lx : dx < -s.half_lx ? s.lx : T(0);
      const T sy = dy > s.half_ly ? -s.ly : dy < -s.half_ly ? s.ly : T(0);
      consider_pair(s, i, pi, vi, b.id, sx, sy, best);
    } else {
      (void)i_big;
      consider_pair(s, i, pi, vi, b.id, T(0), T(0), best);
    }
  }
}

// A pair's time as format version 2 predicts it from the two records just before the event is exactly the
// time this engine predicted when: the owner's prediction was made at the time of its own record, which is
// unchanged since (fresh); the partner's record is strictly older (so the format predicts from the owner's
// side, at the same now; an equal time would let the format take the other side); the partner's image is
// the one the format picks (no big disks, whose images are chosen apart; in a periodic box at least five
// cells a side, so a neighbour's image is within a tenth of the box of the nearest one); and the root is
// the format's (StableContact; the select scan gives its bits). pair_times_vouchable holds the conditions
// that hold for the whole run (engine_core.hpp). The log writer then codes the time without predicting it;
// tests/log/test_log_exactness.cpp runs every example scene with the writer checking each such vouch.
template <class S>
bool pair_time_exact_v2(const S& s, std::int32_t owner, const Prediction<typename S::Scalar>& pr) {
  if (!s.pair_times_vouchable || !pr.fresh()) return false;
  return s.p.disk[pr.partner_id()].t < s.p.disk[owner].t;
}

// The pair is resolved in the order (lower id, higher id) whichever disk owned the prediction, so the
// rounding of the result does not depend on who predicted it (cells and all-pairs engines agree).
template <class S>
void resolve_pair(S& s, std::int32_t i, std::int32_t j, bool time_exact_v2) {
  using T = typename S::Scalar;
  using Fx = typename S::Effects;
  if (j < i) std::swap(i, j);
  const RecordBefore<T> before_i = record_before(s.p.disk[i]), before_j = record_before(s.p.disk[j]);
  T wi0 = 0, wj0 = 0;
  if constexpr (Fx::kRough) wi0 = s.p.omega[i], wj0 = s.p.omega[j];
  s.advance(i);
  s.advance(j);
  Disk<T>& a = s.p.disk[i];
  Disk<T>& b = s.p.disk[j];
  const T vix0 = a.vx, viy0 = a.vy, vjx0 = b.vx, vjy0 = b.vy;
  T dx, dy;
  // Across a sliding edge j meets i as its image, moving at vx + svx: the rule acts on that velocity, and
  // the format's predictor, which knows no sliding images, does not give the result (not vouched for).
  [[maybe_unused]] T svx = 0;
  [[maybe_unused]] bool across = false;
  if constexpr (Fx::kSheared)
    across = sheared_separation(s, a, b, dx, dy, svx);
  else
    separation(s, a, b, dx, dy);
  const bool by_tc = s.tc_elastic(i, j);
  if constexpr (Fx::kDissipative) {
    auto& d = s.dissipation;
    const double ke_before = s.disk_energy(i) + s.disk_energy(j);
    if constexpr (Fx::kSheared) {
      T image_vx = across ? b.vx + svx : b.vx;  // (+ 0 would turn -0 into +0, which the format's rule keeps)
      collide_pair(dx, dy, s.p.mass(i), s.p.mass(j), by_tc ? T(2) : d.pair_one_plus_xi(s.p, i, j), a.vx, a.vy,
                   image_vx, b.vy);
      b.vx = across ? image_vx - svx : image_vx;
    } else {
      collide_pair(dx, dy, s.p.mass(i), s.p.mass(j), by_tc ? T(2) : d.pair_one_plus_xi(s.p, i, j), a.vx, a.vy, b.vx,
                   b.vy);
    }
    if constexpr (Fx::kRough)
      collide_pair_tangential(dx, dy, vjx0 - vix0, vjy0 - viy0, s.p.mass(i), s.p.mass(j), a.r, b.r, s.p.inertia[i],
                              s.p.inertia[j], by_tc ? T(0) : s.spin.pair_one_plus_beta(s.p, i, j), a.vx, a.vy, b.vx,
                              b.vy, s.p.omega[i], s.p.omega[j]);
    d.ke += s.disk_energy(i) + s.disk_energy(j) - ke_before;
    if constexpr (!Fx::kGravity) d.note_if_too_slow(s.p, i), d.note_if_too_slow(s.p, j);
    if (d.tc_model) s.p.last_collision[i] = s.p.last_collision[j] = s.now;
  } else {
    collide_pair(dx, dy, s.p.mass(i), s.p.mass(j), T(2), a.vx, a.vy, b.vx, b.vy);
  }
  ++a.counter;
  ++b.counter;
  a.last_partner = j;
  b.last_partner = i;
  ++s.counts.by_kind[int(EventKind::Pair)];
  if (by_tc) ++s.counts.tc_elastic;
  if (!s.sinks.empty()) {
    T wi = 0, wj = 0;
    if constexpr (Fx::kRough) wi = s.p.omega[i], wj = s.p.omega[j];
    // Every field given (an aggregate's missing fields are zeroed: a memset of the whole outcome per event).
    s.emit({s.now, EventKind::Pair, by_tc, i, j, a.vx, a.vy, b.vx, b.vy, vix0, viy0, vjx0, vjy0, wi, wj, wi0, wj0,
            before_i, before_j, time_exact_v2, kRulesAreFormatV2 && !across});
  }
  predict_disk(s, i);
  predict_disk(s, j);
}

}  // namespace ede
