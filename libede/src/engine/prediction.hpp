// One disk's current prediction: its earliest collision (pair, wall or segment) and its cell crossing's
// direction, kept apart so a crossing can update the collision part with the new neighbours only. The
// crossing's time is not kept: it only chooses the queue key, right when it is computed (the key holds
// whichever time won). 16 bytes in double (32 before issue 15's memory round: docs/performance.md).
// `who` = partner (29 bits: disk id, WallId or segment number; all ones for none) | kind code << 29 |
// fresh << 31; `check` = the partner's counter when predicted (its low 30 bits) << 2 | crossing direction.
// A pair prediction is stale when the partner's counter moved since: 30 bits wrap only after 2^30
// collisions of the partner while this prediction stands, as 32 bits did after 2^32 (never, in any run so
// far). `fresh`: the collision was predicted at the time of this disk's own record, which has not changed
// since (a wrap clears it): what lets the engine vouch for a pair's time to the log (room_pair.hpp).
// Rejected: separate fields (24 B with the padding).
#pragma once

#include <cstdint>

#include "engine/candidate.hpp"
#include "engine/event_queue.hpp"
#include "engine/predict_crossing.hpp"

namespace ede {

template <class T>
struct Prediction {
  static constexpr std::uint32_t kPartnerBits = kTagDiskBits, kPartnerMask = (1u << kPartnerBits) - 1;
  static constexpr std::uint32_t kCounterMask = (1u << 30) - 1;
  static constexpr std::uint32_t kFreshBit = 1u << 31;
  T t_coll;
  std::uint32_t who;
  std::uint32_t check;

  static Prediction none() { return {kNever<T>, kPartnerMask, 0}; }
  std::int32_t partner() const {
    const std::uint32_t p = who & kPartnerMask;
    return p == kPartnerMask ? -1 : std::int32_t(p);
  }
  EventKind coll_kind() const {
    static constexpr EventKind kOf[] = {EventKind::Pair, EventKind::Wall, EventKind::Segment, EventKind::Step};
    return kOf[(who >> kPartnerBits) & 3u];
  }
  // The partner of a pending (finite) event: never none.
  std::int32_t partner_id() const { return std::int32_t(who & kPartnerMask); }
  CrossDir cross_dir() const { return CrossDir(check & 3u); }
  bool partner_moved(std::uint32_t counter_now) const { return ((counter_now ^ (check >> 2)) & kCounterMask) != 0; }
  bool fresh() const { return (who & kFreshBit) != 0; }
  void clear_fresh() { who &= ~kFreshBit; }
  // The whole prediction at once (predict_disk); set_coll and set_cross update one part (cross_cell).
  void set(const Candidate<T>& c, std::uint32_t counter, CrossDir dir, bool is_fresh) {
    t_coll = c.time;
    who = code_of(c) | (is_fresh ? kFreshBit : 0u);
    check = (counter & kCounterMask) << 2 | std::uint32_t(dir);
  }
  void set_coll(const Candidate<T>& c, std::uint32_t counter, bool is_fresh) {
    t_coll = c.time;
    who = code_of(c) | (is_fresh ? kFreshBit : 0u);
    check = (counter & kCounterMask) << 2 | (check & 3u);
  }
  // Partner -1 (none) becomes all ones in 29 bits by the mask; the kind code is 0 Pair, 1 Wall, 2 Segment,
  // 3 Step: a nibble table indexed by the kind (kinds 6 and 7 to 2 and 3, the others to themselves), a
  // shift and a mask whatever the kind (a second comparison for Step cost the hard-disk engines 0.1 % of
  // their instructions, and CellGrid::move its inlining in cross_cell).
  static std::uint32_t code_of(const Candidate<T>& c) {
    const std::uint32_t code = (0x32543210u >> (4 * std::uint32_t(c.kind))) & 0xFu;
    return (std::uint32_t(c.partner) & kPartnerMask) | code << kPartnerBits;
  }
  void set_cross(CrossDir dir) { check = (check & ~3u) | std::uint32_t(dir); }
};

}  // namespace ede
