// The one way to make a run: what it is before its engine exists (RunPlan), and its engine and log
// writer made from that (start_run). Used by Simulation (new and resumed runs), Log::verify's re-run, the
// studies, the benchmarks and the fuzz harness (through ede/internal/run.hpp), so that they all run what
// ede-sim runs.
//
// plan_run sets a scene up (its disks, or its [start] state) and checks that the run can finish;
// plan_run_from does the same with a state the caller already has (verify re-runs a [start] log from the
// log's own first state, the fuzz harness makes its states from bytes). Either way the engine options are
// the scene's (engine_options_from), and a state whose disks spin runs a rough engine. A caller may then
// change a speed-only option (the speed study's all-pairs baseline, the fuzz harness's stall limit)
// before start_run.
// Rejected: each caller calling build_initial_state, engine_options_from and make_engine itself (five
// copies that had drifted apart: verify skipped the run checks and dropped a [start] state's spins, the
// speed study ignored [start], the fuzz harness wrote a log header without the restitution it ran with).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>

#include "core/initial_state.hpp"
#include "core/scalar_dispatch.hpp"
#include "ede/error.hpp"
#include "ede/scene.hpp"
#include "engine/engine.hpp"
#include "log/log_writer.hpp"

namespace ede {

struct RunPlan {
  Scene scene;           // a [start] scene with its source's provenance recorded (run_start.hpp)
  InitialState initial;  // the disks at the start: start_run hands them to the engine
  EngineOptions options;
};

Result<RunPlan> plan_run(const Scene& scene);
Result<RunPlan> plan_run_from(const Scene& scene, InitialState initial);

// The log sink of a run in T: none for __float128, which the log format does not hold.
template <class T>
using LogWriterFor = std::conditional_t<kLogScalar<T>, std::unique_ptr<LogWriter<T>>, std::nullptr_t>;

// Where a resumed run continues: the engine's resume point and the log's continuation at the last
// resumable keyframe, and the format version the log was written in (run_resume.hpp makes it).
template <class T>
struct Resumption {
  ResumePoint<T> point;
  LogContinuation continuation;
  std::uint32_t format_version = 0;
};

// Where a run writes its event log, if anywhere.
struct RunLog {
  std::string path;              // "": no log
  bool check_exactness = false;  // LogSettings::check_exactness: recompute what the engine vouches for
};

template <class T>
struct RunEngine {
  std::unique_ptr<EngineApi<T>> engine;
  LogWriterFor<T> log;  // null without a log path; not yet a sink of the engine: the caller adds it
};

// The engine for `plan` in T and, given a log path, its log writer (with `resume`, continuing that log). The
// plan's disks are freed once the engine holds them, before the log writer allocates (~52 B/disk less
// at the peak); its scene, box, species names and note stay. The log writer is left for the caller to
// add as the engine's first sink, behind whatever must see the outcomes first (Simulation's finite guard).
template <class T>
Result<RunEngine<T>> start_run(RunPlan& plan, const RunLog& log = {}, const Resumption<T>* resume = nullptr);

}  // namespace ede
