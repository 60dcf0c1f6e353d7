// EventOutcome: what the engine tells its sinks about each event (the kinds are in ede/events.hpp).
//
// An outcome carries what replay needs and nothing it must recompute: the time, the participants and the
// post-event velocities. Positions are never stored: after an event a disk's state is (x, v, t) with x
// from the shared drift function, and replay computes the same x from the same inputs. It also carries the
// records of its disks as they were just before it: what the log's predictors read (format version 2,
// log/event_predictions.hpp), so that the log writer codes each event from what the engine hands it, with
// no copy of the state of its own (issue 33: the copy's cache misses were most of the log's cost).
#pragma once

#include <cstdint>

#include "ede/events.hpp"

namespace ede {

// A disk's record just before an event: position at its time t, velocity since then, and radius.
template <class T>
struct RecordBefore {
  T x{}, y{}, vx{}, vy{}, t{}, r{};
};

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
  T wi{}, wj{};             // rough engines, Pair and Wall: angular velocity of i (and j) after the event
  T wi0{}, wj0{};           // rough engines, Pair and Wall: angular velocity of i (and j) before the event
  // Pair, Wall, Segment, Wrap: the records of i (and j) before it (an event of one disk repeats i's as j's).
  RecordBefore<T> before_i{}, before_j{};
  // What the engine vouches for to the log (engine_core.hpp, "what the engine vouches for"): format version
  // 2's predictors, run on the records before the event, give exactly its time (a pair), and exactly its
  // velocities and spins (a collision). The writer then codes a residual of 0 without computing them.
  bool v2_time_exact = false;
  bool v2_velocities_exact = false;
};

// The record of a disk (any type with x, y, vx, vy, t, r) as a RecordBefore.
template <class D>
inline auto record_before(const D& d) {
  return RecordBefore<decltype(d.x)>{d.x, d.y, d.vx, d.vy, d.t, d.r};
}

}  // namespace ede
