// EventOutcome: what the engine tells its sinks about each event (the kinds are in ede/events.hpp).
//
// An outcome carries what replay needs and nothing it must recompute: the time, the participants and the
// post-event velocities. Positions are never stored: after an event a disk's state is (x, v, t) with x
// from the shared drift function, and replay computes the same x from the same inputs.
#pragma once

#include <cstdint>

#include "ede/events.hpp"

namespace ede {

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
};

}  // namespace ede
