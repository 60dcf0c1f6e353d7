// LogWriter<T>: the sink that records a run to an event log (.ede; format in schema/FORMAT.md).
//
// Every event that changes the state (pair, wall, wrap, action) goes into chunks of columns; the full state
// goes into keyframes every keyframe_interval logged events and at every engine rebuild (those are
// resumable); an index and a fixed trailer close the file at the end. Coding the columns, compression
// and writing run on a second thread in submission order (the event loop only copies each event), so logging costs the simulation little and the bytes never depend on
// timing. The writer never changes the run: a run with and without a log produces the same events.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/scene.hpp"
#include "log/log_reader.hpp"
#include "core/sink.hpp"

namespace ede {

// max(2^18, 16 N) logged events: a keyframe costs ~34 bytes per disk; at N = 10^4 a version 2 log holds
// ~4.4 bytes per event, so 2^18 adds ~0.5 B/event and brings the median seek in a 10^7-event log from
// ~34 ms (2^20) to ~14 ms. The 16 N term keeps keyframes a bounded share of the file at large N: 34 N / I
// bytes per event, ~2 with 16 N (4 N gave ~8.5 at N = 10^5, more than the events themselves). A seek then
// replays up to ~N / 10^6 s of events at N > 16384, and less in practice: the engine's rebuild keyframes
// (every 16 N engine events, ~11 N logged at phi = 0.5) fall in between. docs/performance.md, "Event log".
std::uint64_t auto_keyframe_interval(std::size_t disks);

struct LogSettings {
  std::uint64_t keyframe_interval = 0;         // logged events between keyframes; 0: auto_keyframe_interval
  std::uint32_t chunk_events = 16384;          // events per chunk
  int compression_level = 3;                   // zstd level (docs/log-format-choices in docs/performance.md)
  std::uint32_t format_version = 2;            // 2 (predicted columns), or 1 (for ede-replay convert and comparisons)
  // Recompute every prediction the engine vouched for (EventOutcome::v2_*_exact) and fail the log at the
  // first that differs (error()): slower; the tests, and a scene's log.check_exactness.
  bool check_exactness = false;
  static LogSettings from(const LogSpec& spec);
};

// What the header records about the run besides the per-disk constants the writer reads at on_start.
struct LogRunInfo {
  std::string scene_name;
  std::string scene_text;
  std::uint64_t seed = 0;
  ScalarKind scalar = ScalarKind::Double;
  std::vector<std::string> species_names;
  double lx = 1, ly = 1;
  BoundaryKind boundary = BoundaryKind::Walls;
  std::uint64_t rebuild_interval = 0;
  bool tc_model = false;
  double gx = 0, gy = 0;  // gravity
  // Restitution as the engine applies it (format version 2 stores it for replay's velocity predictions):
  // S x S values for S = max(1, species) species, pair (a, b) at a S + b, and one per wall (WallId order).
  std::vector<double> pair_restitution{1};
  double wall_restitution[4] = {1, 1, 1, 1};
  // Wall segments, five values each: ax, ay, bx, by, restitution (the header appends them to the walls').
  std::vector<double> segments;
  // The Andersen thermostat redraws velocities (thermostat events): format version 3 (FORMAT.md).
  bool thermostat = false;
  // A Lees-Edwards box (boundary Periodic, sliding images): shear events, format version 3 (FORMAT.md).
  bool shear = false;
  // Rough or spinning disks (EngineOptions::rotation): the header then carries I per disk and 1 + beta, and
  // chunks and keyframes the spins (FORMAT.md, "Rotation"). beta of S x S species pairs, then of the walls.
  bool rotation = false;
  // A stepped potential (Scene's physics.steps): its step events exist from format version 3 on, so create()
  // writes such a run in version 3 whatever version 1 or 2 the settings name (FORMAT.md, version 3).
  bool steps = false;
  std::vector<double> pair_roughness{-1};
  double wall_roughness = -1;
  std::string engine_version, compiler, compile_flags;  // empty: this build's (a converted log keeps its own)
  // The box, restitution, roughness and segments above are the ones the engine runs with (log_run_info,
  // run/log_run_info.hpp): only then does the writer take the engine's word for what it computed exactly as
  // the format predicts (EventOutcome::v2_*_exact); else it predicts every event itself (the same bytes
  // when the header is right, a larger but exact log when it is not).
  bool engine_constants = false;
  // pair_restitution, wall_restitution and segments from the scene's physics, as the engine builds them.
  void set_restitution(const PhysicsSpec& physics);
};

// Where an interrupted log continues (from LogReader::resume_point).
struct LogContinuation {
  std::uint64_t cut_offset = 0;        // the file is cut here (end of the resumable keyframe's record)
  std::uint64_t events_before = 0;     // logged events before the keyframe
  std::uint32_t run_id = 0;            // the log's run id (log/run_id.hpp), repeated in the new records
  struct Entry {
    std::uint8_t kind;
    std::uint64_t offset, first_event, count;
    double time_first, time_last;
    bool resumable;
  };
  std::vector<Entry> entries;          // index entries of the records kept
};

// The continuation of `log` from its keyframe k (resumable): the file is cut after that keyframe's record,
// and the index entries of the records kept are carried over.
LogContinuation continuation_from(const LogReader& log, std::size_t keyframe);

template <class T>
class LogWriter final : public Sink<T> {
 public:
  // A new log at `path`, or, with `continuation`, the continuation of an interrupted one (the events carry
  // the records the predictors read, so a continued log needs no state of its own).
  static Result<std::unique_ptr<LogWriter>> create(const std::string& path, const LogRunInfo& run,
                                                   const LogSettings& settings,
                                                   const LogContinuation* continuation = nullptr);
  ~LogWriter() override;

  void on_start(T time, const Particles<T>& particles) override;
  void on_event(const EventOutcome<T>& outcome, const Particles<T>& particles) override;
  void on_rebuild(const RebuildPoint<T>& point) override;
  void on_finish(T time, const Particles<T>& particles, RunStatus status) override;

  // Empty while all is well; else the first I/O error (the run goes on; the tool reports it at the end).
  std::string error() const;
  std::uint64_t events_logged() const;
  std::uint64_t bytes_written() const;  // after on_finish

  struct Impl;

 private:
  explicit LogWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace ede
