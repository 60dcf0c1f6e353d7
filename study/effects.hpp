// The effects study (ede-bench effects): what each physical effect costs per event, and what
// specializing the engine for a scene's effects saves. One scene (a 10^4-disk gas in two species), with
// one effect switched on at a time by overrides, each run in a child process and timed around the event
// loop only:
//  - by the engine make_engine picks for its effects (what ede-sim runs): the cost of each effect per
//    event, against the plain elastic gas;
//  - by the all-effects engine (make_study_engine's all_effects: the library's walls + gravity engine, in
//    which xi = 1, tc = 0 and g = 0 do nothing): what specialization saves;
//  - for the elastic gas, also by ede-bench-elastic, a binary holding only the elastic engine: the
//    elastic gas must run as fast in a binary with every effect compiled in as in one with only its own.
// ede-bench prints the rows.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::study {

struct EffectsPlan {
  std::string scene = "examples/bench/effects/gas-two-species.toml";
  int repeat = 5;                      // interleaved rounds; medians are reported
  std::vector<std::string> overrides;  // --set key=value on every run (stop.events: the run's length)
  std::string elastic_only_binary;     // the path of ede-bench-elastic
};

// A median with the range it came from (min-max over rounds): the noise to compare a ratio with.
struct Spread {
  double median = 0, low = 0, high = 0;
};

struct EffectRow {
  std::string label;              // the effect switched on
  std::string engine;             // what it runs as, in ede-sim's words (EngineApi::effects())
  double ns_per_event = 0, cycles_per_event = 0;  // CPU time and cycles, medians over rounds (cycles 0: n/a)
  Spread vs_elastic;              // cost per event / the elastic gas's, per round
  bool all_effects = false;       // also run by the all-effects engine (walled scenes only)
  double all_effects_ns_per_event = 0;
  Spread all_effects_ratio;       // all-effects engine / the specialized one, per round
};

struct EffectsResults {
  std::string scene;
  std::size_t disks = 0;
  std::uint64_t events = 0;  // per run
  int rounds = 0;
  bool cycles = false;       // ratios on user-mode cycles (perf events), else on the thread's CPU time
  std::vector<EffectRow> rows;
  // The elastic gas through make_engine in ede-bench (every effect compiled in) and in ede-bench-elastic.
  double elastic_ns_per_event = 0, elastic_only_ns_per_event = 0;
  Spread elastic_vs_elastic_only;
  // Two binaries differ in code layout (alignment of the hot loop), which moves a run by a few percent
  // either way whatever the code; the verdict is on "not slower", with the rounds' spread as the noise.
  bool elastic_not_slower() const { return elastic_vs_elastic_only.low - 1 <= 0.02; }
};

// An error names the effect whose run failed.
Result<EffectsResults> run_effects_study(const EffectsPlan& plan);

}  // namespace ede::study
