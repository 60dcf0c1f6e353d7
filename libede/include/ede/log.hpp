// Log: an event log (.ede) opened for reading: what it holds, the exact state at any time, its events,
// a check against a re-run, and the first difference from another log.
//
//   ede::Log log = ede::Log::open("gas.ede").value();
//   ede::State s = log.state_at(0.5).value();       // bit-identical to the engine's state at t = 0.5
//
// Nothing in the file is trusted: sizes and offsets are checked before use, records carry checksums, and
// a damaged or truncated log gives an error naming the file and the byte, never a crash or a wrong state.
// A log whose run was killed reads up to its last complete record (info().complete is false and
// info().incomplete_reason says how far it goes). States are rebuilt by applying the logged events to the
// nearest keyframe with the engine's own state-update functions: a seek costs one keyframe plus the
// events since it, never the whole log, and the simulation never reruns (except in verify(), whose job it
// is; format version 2 decodes each stored velocity and time as a residual against the collision rule's
// and contact time's prediction, which is not a rerun: the stored residual has the last word).
// A Log is cheap to copy (copies share the file); one thread at a time per copy.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/events.hpp"
#include "ede/scene.hpp"
#include "ede/state.hpp"

namespace ede {

// What a reader accepts before it allocates: a log claiming more is refused as implausible. The defaults
// cover every run ede can make (10^8 disks; one record, e.g. a keyframe of 10^7 disks, up to 2 GiB);
// services reading untrusted logs pass tighter ones.
struct LogLimits {
  std::uint32_t max_disks = 100000000;
  std::uint64_t max_record_bytes = std::uint64_t(1) << 31;
};

struct LogInfo {
  std::string path;
  std::uint32_t format_version = 0;
  std::string engine_version, compiler, compile_flags;  // what wrote it
  ScalarKind scalar = ScalarKind::Double;
  std::uint64_t seed = 0;
  std::string scene_name, scene_text;  // the effective scene (TOML, after --set overrides): what was run
  std::uint64_t disks = 0;
  std::vector<std::string> species_names;
  std::vector<std::uint64_t> species_counts;  // disks per species
  double lx = 1, ly = 1;
  BoundaryKind boundary = BoundaryKind::Walls;
  bool lees_edwards = false;           // periodic with sliding images above and below (scene().shear_rate)
  double shear_rate = 0;               // a Lees-Edwards log's, from its scene (0 otherwise, or without a scene)
  bool rotates = false;                // rough or spinning disks: states and events carry omega
  bool tc_model = false;
  double gx = 0, gy = 0;
  double initial_energy = 0;
  std::uint32_t chunk_events = 0;
  std::uint64_t keyframe_interval = 0, rebuild_interval = 0;
  // Contents.
  std::uint64_t events = 0;            // logged events (pair, wall, wrap, action)
  std::uint64_t chunks = 0, keyframes = 0, resumable_keyframes = 0;
  std::uint64_t file_size = 0;
  double start_time = 0;
  Time end_time = 0;                   // complete: the time the run reached; else the last event's time
  double first_event_time = 0, last_event_time = 0;  // of the logged events, from the index (0 without any)
  // Completeness.
  bool complete = false;               // closed by its index and trailer: the run finished
  bool damaged = false;                // corrupted, not merely cut short (what precedes the damage reads)
  std::string incomplete_reason;       // why not complete, and how far the log goes
  std::string final_status;            // how the run ended (complete logs)
};

// Which events: by time (inclusive at both ends) and/or by index ([from_event, to_event)).
struct EventRange {
  std::optional<Time> from_time, to_time;
  std::optional<std::uint64_t> from_event, to_event;
};

// Events as columns, one entry per event, reals in the log's own scalar type (Column): what bindings hand
// on as arrays (numpy) without an Event per event. Fields a kind does not have are 0, as in Event.
struct EventColumns {
  std::vector<std::uint64_t> index;
  Column time;
  std::vector<std::uint8_t> kind;                   // EventKind
  std::vector<std::int32_t> i, j;
  Column vix, viy, vjx, vjy;                        // after the event
  Column xi, yi, xj, yj;                            // at the event (only when asked for; else empty)
  Column vix_before, viy_before, vjx_before, vjy_before;  // just before (only when asked for; else empty)
  std::size_t size() const { return index.size(); }
};

// Where Log::event_rows writes each field of an event in a row of `row_bytes` bytes: a byte offset, or -1
// for a field not wanted. Reals are written in the log's scalar type (LogInfo::scalar: float, double, or
// long double for long double and float128 runs), index as uint64, kind as uint8 (EventKind), i and j as
// int32; no alignment is assumed. The omega fields are 0 unless the log's disks rotate (LogInfo::rotates).
struct EventRowLayout {
  std::size_t row_bytes = 0;
  std::ptrdiff_t index = -1, time = -1, kind = -1, i = -1, j = -1;
  std::ptrdiff_t vix = -1, viy = -1, vjx = -1, vjy = -1;                              // after the event
  std::ptrdiff_t xi = -1, yi = -1, xj = -1, yj = -1;                                  // at the event
  std::ptrdiff_t vix_before = -1, viy_before = -1, vjx_before = -1, vjy_before = -1;  // just before
  std::ptrdiff_t omega_i = -1, omega_j = -1, omega_i_before = -1, omega_j_before = -1;
};

struct VerifyOptions {
  std::function<void(double fraction, std::uint64_t events)> progress;  // every 2^16 events
};

// The outcome of re-running a log's scene and comparing every event, keyframe and the end with the log.
struct VerifyReport {
  bool identical = false;            // every compared event, keyframe and the end agree
  bool partial = false;              // the log is incomplete: identical as far as it goes
  std::uint64_t events_compared = 0;
  std::uint64_t keyframes_checked = 0, resumable_checked = 0;
  std::string difference;            // the first difference, with both values (when !identical)
  std::string text;                  // the report in words, as ede-replay verify prints it
};

// The outcome of comparing two logs event by event (bisection over keyframes and chunks, then lockstep).
struct DiffReport {
  bool identical = false;                          // same events, final time and status
  std::optional<std::uint64_t> first_difference;   // the first event index at which they part
  std::string text;                                // notes, what was compared and the verdict, in words
};

class Log {
 public:
  // Opens and checks a log. Fails with the file and the byte for anything unreadable; a log cut short is
  // not an error (see LogInfo::complete).
  static Result<Log> open(const std::string& path, const LogLimits& limits = {});

  const LogInfo& info() const;
  // Lets a caller stop a long read (a binding's Ctrl-C): the states' seeks and the event walks of this Log
  // and its copies ask `interrupted` before each chunk they decode, from the thread decoding it (an event
  // walk asks from several threads at once); when it returns true they stop there and return an Error
  // saying so. The Log stays usable: the next call reads as if nothing had happened. Set it while no call
  // is in progress. (Analyses and verify make their own replays and do not ask.)
  void set_interrupt_check(std::function<bool()> interrupted);
  // The effective scene the log records, loaded again.
  Result<Scene> scene() const;

  // The state after every event with time <= t; t within [start, end] of the log.
  Result<State> state_at(Time t) const;
  // The state after the first n events (n <= info().events).
  Result<State> state_at_event(std::uint64_t n) const;
  // The state at the end: the time the run reached (complete logs), else after the last event.
  Result<State> state_at_end() const;

  // Events in a range, with positions and velocities before and after (memory: ~240 bytes each; use
  // for_each_event for long ranges).
  Result<std::vector<Event>> events(const EventRange& range) const;
  // The same, one at a time; f returns false to stop early.
  Status for_each_event(const EventRange& range, const std::function<bool(const Event&)>& f) const;
  // The same as columns: several times faster than one Event at a time for long ranges. `positions` and
  // `before` add those columns. The columns are sized once from the range. A range over several
  // keyframes is replayed in pieces on up to `threads` threads (0: one per core), each from its own
  // keyframe; the columns are the same bits whatever the number of threads.
  Result<EventColumns> event_columns(const EventRange& range, bool positions = false, bool before = false,
                                     unsigned threads = 0) const;
  // The same written as rows straight into a buffer the caller owns (a numpy structured array): one pass,
  // no intermediate columns, so the memory is touched once. `allocate(rows)` is called once, before any
  // event is replayed, and returns room for `rows` rows (an upper bound: the rows of the range's index
  // span); the result is the number of rows written (fewer when to_time ends the range inside a chunk).
  // The same threads and bits as event_columns.
  Result<std::uint64_t> event_rows(const EventRange& range, const EventRowLayout& layout,
                                   const std::function<void*(std::uint64_t rows)>& allocate,
                                   unsigned threads = 0) const;
  // Counts by kind from the chunks' kind columns alone (no replay).
  Result<EventCounts> count_events() const;
  // For each c (ascending, >= 0) the number of events after which the state is the one right after the
  // pair collision that brings the pair count to ceil(c N / 2) (N disks): the schedules' "collisions per
  // disk" ([[actions]] collisions_per_disk), so state_at_event(n) is the snapshot a scheduled action sees.
  // From the kind columns alone (no replay). Fails, naming the log's count, past its last pair collision.
  Result<std::vector<std::uint64_t>> events_after_collisions(const std::vector<double>& collisions_per_disk) const;

  // Re-runs the logged scene and compares everything with the log, bit for bit.
  Result<VerifyReport> verify(const VerifyOptions& options = {}) const;
  // The first event at which this log and `other` part. `full`: compare every record from the start
  // (reads both logs whole, so damage bisection would skip is found too).
  Result<DiffReport> diff(const Log& other, bool full = false) const;
  // A digest of what the log says (scene, every event, the final state), independent of how it is stored:
  // equal for logs of the same run whatever compiler or compression level wrote them. Replays the log.
  // The text names the hash: "xxh3-128:" and 32 hex digits.
  Result<std::string> content_digest() const;
  // Writes this (complete) log again at `out_path` in format version 1 or 2 (the latest, smaller): the same
  // header, events and keyframes, so every state read from the copy is bit-identical to this log's.
  Status convert(const std::string& out_path, std::uint32_t format_version = 2) const;

 private:
  struct Impl;
  friend struct LogAccess;  // the library's own code reaches the log's reader through it (internal)
  explicit Log(std::shared_ptr<Impl> impl);
  std::shared_ptr<Impl> impl_;
};

}  // namespace ede
