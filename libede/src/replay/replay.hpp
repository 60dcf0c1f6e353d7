// Replay<T>: the exact state at any time or event of a log, without rerunning the physics.
//
// seek_time(t) loads the last keyframe at or before t and applies the events after it with the shared
// state-update functions (state_update.hpp), up to and including every event at time t; positions at t
// then come from the shared drift function. The result is bit-identical to the engine's own state at t.
// Cost: one keyframe plus the events since it, never the whole log.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/particles.hpp"
#include "ede/error.hpp"
#include "ede/events.hpp"
#include "log/chunk_codec.hpp"
#include "log/log_reader.hpp"

namespace ede {

template <class T>
struct ReplayedEvent {
  std::uint64_t index = 0;
  T time{};
  EventKind kind{};
  std::int32_t i = -1, j = -1;    // j: partner, wall id or wrap direction
  T vix{}, viy{}, vjx{}, vjy{};   // post-event velocities (pair: both; wall: i)
  // Positions at the event (after it: a wrap has moved i by one box length) and velocities just before.
  T xi{}, yi{}, xj{}, yj{};
  T vix0{}, viy0{}, vjx0{}, vjy0{};
  T wi{}, wj{}, wi0{}, wj0{};     // rough logs: angular velocities after and before (pair: both; wall: i)
};

// The time the run of `log` reached (complete logs), else its last event's time, exactly in T;
// `time_without_chunks` for an incomplete log with no chunk (its first keyframe's time).
template <class T>
T log_final_time(const LogReader& log, T time_without_chunks);

// What for_each_event computes for each event beyond its index, time, kind, ids and the velocities (and
// spins) after it: the velocities and spins just before it, and the positions at it. Each costs ~50
// instructions per event (callgrind: ~11 % of a walk that writes rows); a caller that does not read them
// (the narrow rows of Log::event_rows) turns them off, and the fields then stay zero.
struct EventExtras {
  bool before = true;
  bool positions = true;
};

// What a resumable keyframe stores beyond the state: the engine's bookkeeping at one of its rebuild points
// (last partners, TC times, counters, sample and action indices), as the log holds it. Turning it into
// the engine's own ResumePoint is run/'s business (run/run_resume.hpp): replay reads logs and never
// makes an engine.
template <class T>
struct StoredRebuildPoint {
  T time{};
  std::vector<Disk<T>> disks;     // x, y, vx, vy, t and last_partner as stored; r from the header
  std::vector<T> last_collision;  // TC model only
  std::vector<T> omega;           // rough logs
  EventCounts counts;
  std::uint64_t next_sample_index = 0;
  std::uint64_t next_action_index = 0;
  std::uint64_t same_time_events = 0;
  double initial_energy = 0;
};

template <class T>
class Replay {
 public:
  // Fails if the log's scalar type is not T.
  static Result<std::unique_ptr<Replay>> create(std::shared_ptr<const LogReader> log);

  // The state after every event with time <= t. t beyond the end of the log is refused.
  Status seek_time(T t);
  // The state after the first n events.
  Status seek_event(std::uint64_t n);
  // Applies the next event and returns it (for lockstep comparison with an engine); an error at the end.
  Result<ReplayedEvent<T>> next_event();
  // Applies the events [from, to) in order (seeking to `from` first), calling f for each. An empty f applies
  // them as a seek does, building no per-event record (the state-only replay rate of ede-bench log).
  Status for_each_event(std::uint64_t from, std::uint64_t to, const std::function<bool(const ReplayedEvent<T>&)>& f,
                        EventExtras extras = {});

  const Particles<T>& particles() const { return state_; }
  T time() const { return time_; }                         // the time positions are reported at
  std::uint64_t events_applied() const { return applied_; }
  T final_time() const;                                     // the time the run reached (complete logs), else last event
  // What a resumable keyframe (index into log->keyframes()) stores; an error for any other keyframe.
  Result<StoredRebuildPoint<T>> rebuild_point(std::size_t keyframe) const;
  // Asked before each chunk is decoded (Log::set_interrupt_check): when it returns true, the seek or walk
  // stops at that chunk boundary, where every earlier event is applied and the replay stays usable, and
  // returns an Error saying it was interrupted. nullptr or an empty function: never asked.
  void set_interrupt_check(const std::function<bool()>* interrupted) { interrupted_ = interrupted; }

 private:
  explicit Replay(std::shared_ptr<const LogReader> log);
  Status load_keyframe(std::size_t k);
  Status open_chunk();
  std::size_t keyframe_for_event(std::uint64_t n) const;
  std::size_t chunk_containing(std::uint64_t event) const;
  Status advance(std::uint64_t target_event, const T* until_time,
                 const std::function<bool(const ReplayedEvent<T>&)>& f, EventExtras extras = {});

  Error non_finite_error(std::uint64_t event) const;
  struct Cursor;  // the chunk being decoded and the next decoded event (replay.cpp)
  void before_event(const DecodedEvent<T>& e, ReplayedEvent<T>& out) const;
  void unchanged_after(const DecodedEvent<T>& e, ReplayedEvent<T>& out) const;
  void after_event(const DecodedEvent<T>& e, ReplayedEvent<T>& out) const;

  std::shared_ptr<const LogReader> log_;
  std::shared_ptr<Cursor> cursor_;
  Particles<T> state_;
  T lx_{}, ly_{};
  EventPhysics<T> physics_;  // version 2's predictions (header physics)
  T time_{};
  T last_event_time_{};
  T last_event_time_initial_{};  // the first keyframe's time: the end of a log with no chunk
  std::uint64_t applied_ = 0;
  bool loaded_ = false;
  const std::function<bool()>* interrupted_ = nullptr;
};

}  // namespace ede
