// Events: the kinds of event, the counts a run keeps, why a run stops, and one event as a log holds it.
//
// A run is a sequence of events; the log stores those that change the state (pair and wall collisions,
// periodic wraps, scheduled actions) with the velocities after them. Cell crossings (bookkeeping of the
// neighbour grid) and samples (an observer's times) are counted but never stored.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>

namespace ede {

// A time, wide enough to carry a time of any log's scalar type (float, double, long double) exactly:
// a double converts to it without rounding, and a time the library returns converts back to the log's
// type exactly. Pass plain doubles; read results as doubles unless you study long double runs.
using Time = long double;

// The kinds of event, as one list from which the enum, kEventKindCount and the names (to_string) are made,
// and the engine's dispatch (engine_core.hpp). Append only: logs store the numbers. Order matters: at
// equal times the queue processes the lower kind first (total order time, kind, ids).
//   Pair     two disks collide
//   Wall     a disk hits a wall (walls boundary)
//   Cell     a disk crosses into another cell: bookkeeping only, no state change, not logged
//   Wrap     a disk crosses a periodic edge: its stored position moves by one box length
//   Action   a scheduled action (reverse every velocity)
//   Sample   an observer's sampling time: no state change, not logged
//   Segment  a disk hits a wall segment (its body or an end point); Event::j is the segment's index
//   Step     two disks reach a step of their stepped potential (a square well or shoulder, outside the
//            hard core): they cross it, trading kinetic for potential energy, or bounce off it
//   Thermostat  the Andersen thermostat redraws one disk's velocity (Event::j is -1)
//   Shear    a disk crosses the sliding (top or bottom) edge of a Lees-Edwards box: y moves by one box
//            height, x by the images' offset, vx by their velocity (Event::j: WrapDir, top or bottom)
#define EDE_EVENT_KINDS(X)    \
  X(Pair, 0, "pair")          \
  X(Wall, 1, "wall")          \
  X(Cell, 2, "cell")          \
  X(Wrap, 3, "wrap")          \
  X(Action, 4, "action")      \
  X(Sample, 5, "sample")      \
  X(Segment, 6, "segment")    \
  X(Step, 7, "step")          \
  X(Thermostat, 8, "thermostat") \
  X(Shear, 9, "shear")

#define EDE_EVENT_KIND_ENUM(name, value, text) name = value,
enum class EventKind : std::uint8_t { EDE_EVENT_KINDS(EDE_EVENT_KIND_ENUM) };
#undef EDE_EVENT_KIND_ENUM
// One more than the largest kind's number (arrays indexed by the kind; a number the list skips stays 0).
#define EDE_EVENT_KIND_BOUND(name, value, text) (value) + 1,
constexpr int kEventKindCount = [] {
  int n = 0;
  for (int bound : {EDE_EVENT_KINDS(EDE_EVENT_KIND_BOUND) 0}) n = bound > n ? bound : n;
  return n;
}();
#undef EDE_EVENT_KIND_BOUND
const char* to_string(EventKind);  // "pair", "wall", ...; "?" for a number the list skips
bool is_event_kind(int value);     // a number of the list

// Event::j of a wall event: which wall. Of a wrap event: which edge the disk crossed.
enum WallId : std::int32_t { kWallLeft = 0, kWallRight = 1, kWallBottom = 2, kWallTop = 3 };
enum WrapDir : std::int32_t { kWrapRight = 0, kWrapLeft = 1, kWrapTop = 2, kWrapBottom = 3 };

struct EventCounts {
  std::uint64_t by_kind[kEventKindCount] = {};
  std::uint64_t stale = 0;       // predictions popped after a participant had changed: discarded
  std::uint64_t tc_elastic = 0;  // collisions made elastic by the TC model

  std::uint64_t of(EventKind k) const { return by_kind[static_cast<int>(k)]; }
  std::uint64_t collisions() const { return of(EventKind::Pair) + of(EventKind::Wall) + of(EventKind::Segment); }
  // Processed events: everything but samples and stale predictions (what stop.events counts).
  std::uint64_t events() const { return events_but_redraws() + of(EventKind::Thermostat) + of(EventKind::Shear); }
  // The same without the thermostat's redraws and the sliding boundary's crossings: what an engine without
  // either counts (one load less in its loop, which asks twice per event).
  std::uint64_t events_but_redraws() const {
    return of(EventKind::Pair) + of(EventKind::Wall) + of(EventKind::Cell) + of(EventKind::Wrap) +
           of(EventKind::Action) + of(EventKind::Segment) + of(EventKind::Step);
  }
};

// Why a run stopped (or that it has not).
enum class RunStatus {
  Running,            // not finished: an event budget was used, a time reached by advance_to, or interrupted
  ReachedTime,        // stop.time reached (the state is reported at exactly that time)
  ReachedEvents,      // stop.events processed
  ReachedCollisions,  // stop.collisions_per_particle reached
  ReachedEnergy,      // kinetic energy fell to stop.energy_fraction of the initial
  NoMoreEvents,       // nothing will ever happen again (every disk at rest, or moving freely forever)
  Stalled,            // time stopped advancing: inelastic collapse; the run's message says what to do
  CameToRest,         // an inelastic run cooled below the speeds the scalar type resolves; see the message
  NonFinite,          // a NaN or infinity appeared (overflow): the run stopped at that event; see the message
  Collapsed,          // inelastic collapse: a disk slowed below resolvable speeds while much energy remains
  EndedByProgram,     // Simulation::finish ended it at the current time (its log is complete)
  Inexact,            // the run outgrew its scalar type: disks overlapped, or the clock passed what it holds
};
const char* to_string(RunStatus);
// The status a log's final words name (to_string(RunStatus), older words included); Running if none.
RunStatus status_from_text(const std::string& text);
bool is_finished(RunStatus);  // anything but Running

// One logged event with everything known about it, in the log's own values (exact, widened to Time).
// Fields a kind does not have are 0.
struct Event {
  std::uint64_t index = 0;  // events before it in the log
  Time time = 0;
  EventKind kind = EventKind::Pair;
  std::int32_t i = -1;  // the disk (pair: the lower id); -1 for an action
  std::int32_t j = -1;  // pair, step: the other disk; wall: WallId; wrap, shear: WrapDir; segment: its index; action: -1
  // Positions of i and j at the event (a wrap, a shear crossing: i's position after it moved).
  Time xi = 0, yi = 0, xj = 0, yj = 0;
  // Velocities just before and just after the event (pair: both disks; wall, segment: i; wrap: i's, unchanged).
  Time vix_before = 0, viy_before = 0, vjx_before = 0, vjy_before = 0;
  Time vix = 0, viy = 0, vjx = 0, vjy = 0;
  // Rough logs: angular velocities just before and just after (pair: both disks; wall: i; else unchanged).
  Time omega_i_before = 0, omega_j_before = 0, omega_i = 0, omega_j = 0;
};

}  // namespace ede
