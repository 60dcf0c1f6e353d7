// Events: the one list of kinds, and the outcome every sink sees.
//
// An outcome carries what replay needs and nothing it must recompute: the time, the participants and the
// post-event velocities. Positions are never stored: after an event a disk's state is (x, v, t) with x
// from the shared drift function, and replay computes the same x from the same inputs.
#pragma once

#include <cstdint>

namespace ede {

// Order matters: at equal times the queue processes the lower kind first (total order time, kind, ids).
enum class EventKind : std::uint8_t {
  Pair = 0,      // two disks collide
  Wall = 1,      // a disk hits a wall (walls boundary)
  Cell = 2,      // a disk crosses into another cell: bookkeeping only, no state change, not logged
  Wrap = 3,      // a disk crosses a periodic edge: its stored position moves by one box length
  Action = 4,    // a scheduled action (reverse every velocity)
  Sample = 5,    // an observer's sampling time: no state change
};
constexpr int kEventKindCount = 6;
const char* to_string(EventKind);

// Wall ids (EventOutcome::j for Wall events).
enum WallId : std::int32_t { kWallLeft = 0, kWallRight = 1, kWallBottom = 2, kWallTop = 3 };
// Wrap directions (EventOutcome::j for Wrap events): which edge was crossed.
enum WrapDir : std::int32_t { kWrapRight = 0, kWrapLeft = 1, kWrapTop = 2, kWrapBottom = 3 };

template <class T>
struct EventOutcome {
  T time{};
  EventKind kind{};
  bool tc_elastic = false;  // the TC model made this collision elastic
  std::int32_t i = -1;      // the disk (Pair, Wall, Cell, Wrap); -1 for Action and Sample
  std::int32_t j = -1;      // Pair: the other disk; Wall: WallId; Wrap: WrapDir; Cell: new cell; else -1
  T vix{}, viy{};           // Pair, Wall: post-event velocity of i
  T vjx{}, vjy{};           // Pair: post-event velocity of j
  T vix0{}, viy0{};         // Pair, Wall: velocity of i before the event (the log codes against it)
  T vjx0{}, vjy0{};         // Pair: velocity of j before the event
};

}  // namespace ede
