// ede-bench effects. One scene (a 10^4-disk gas in two species), with one effect switched on at a time by
// overrides, each run in a child process and timed around the event loop only:
//  - by the engine make_engine picks for its effects (what ede-sim runs): the cost of each effect per
//    event, against the plain elastic gas;
//  - by the all-effects engine (walls, inelastic with TC, gravity, all compiled in and decided at run
//    time by the values: xi = 1, tc = 0, g = 0 then do nothing): what specialization saves;
//  - for the elastic gas, also by ede-bench-elastic, a binary holding only the elastic engine: the
//    elastic gas must run as fast in a binary with every effect compiled in as in one with only its own.
// Runs are interleaved (every configuration once per round, rounds repeated) so that a slow spell of a
// noisy machine hits all of them; figures are medians over rounds, and ratios are taken within a round
// before the median, with their spread (min-max over rounds) as the noise to compare a ratio with.
// Effects change the physics (cooling slows the gas; a strong g piles it up near the floor, where events
// cost more because the neighbourhoods are fuller), so the figure is per event, not per unit of simulated
// time, and gravity is measured weak (the code's cost on the same gas) and strong (what a user sees).
#include "bench_effects.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "bench_common.hpp"
#include "cpu_cycles.hpp"
#include "engine/engine.hpp"
#include "ede/scene.hpp"
#include "setup/setup.hpp"
#include "timed_run.hpp"

namespace ede::bench {

namespace {

struct EffectConfig {
  std::string label;                   // the row's name
  std::vector<std::string> overrides;  // --set style, on top of the scene
  bool walls = true;                   // the all-effects engine is built for walls only
};

std::vector<EffectConfig> effect_configs() {
  const std::string inelastic_pairs = "physics.restitution=0.98", inelastic_ab = "physics.pairs[0].restitution=0.98";
  return {
      {"elastic (walls)", {}},
      {"periodic box", {"box.boundary=periodic"}, false},
      {"inelastic walls (xi_w = 0.9)", {"physics.wall_restitution=0.9"}},
      {"inelastic pairs (xi = 0.98)", {inelastic_pairs, inelastic_ab}},
      {"restitution per pair (a-b: 0.98)", {inelastic_ab}},
      {"inelastic + TC (tc = 1e-5)", {inelastic_pairs, inelastic_ab, "physics.tc=1e-5"}},
      // A weak g bends the paths by ~1e-4 over a run: the cost of the code (quadratic wall and cell times)
      // on the same gas. A strong g also piles the gas up near the floor, where events cost more (denser).
      {"gravity, weak (g = 0.001)", {"physics.gravity=[0, -0.001]"}},
      {"gravity, strong (g = 1)", {"physics.gravity=[0, -1]"}},
      {"every effect (weak g)", {inelastic_pairs, "physics.pairs[0].restitution=0.9", "physics.wall_restitution=0.9",
                                 "physics.tc=1e-5", "physics.gravity=[0, -0.001]"}},
  };
}

struct Setup {
  std::string failure;
  InitialState initial;
  EngineOptions options;
};

Setup load(const std::string& path, const EffectConfig& config, std::uint64_t events) {
  std::vector<Override> overrides;
  for (const std::string& o : config.overrides) overrides.push_back({o});
  overrides.push_back({"stop.events=" + std::to_string(events)});
  Setup s;
  auto scene = load_scene_file(path, overrides);
  if (!scene) return s.failure = scene.error().message, s;
  auto initial = build_initial_state(scene.value());
  if (!initial) return s.failure = initial.error().message, s;
  s.options = engine_options_from(scene.value(), initial.value().size());
  s.initial = std::move(initial).value();
  return s;
}

// The child's side: the engine make_engine picks (or the all-effects one), timed.
int measure_in_child(const std::string& path, const EffectConfig& config, std::uint64_t events, bool all_effects,
                     std::string& out) {
  Setup s = load(path, config, events);
  if (!s.failure.empty()) return out = s.failure, 1;
  s.options.all_effects = all_effects;
  auto made = make_engine<double>(s.initial, s.options);
  if (!made) return out = made.error().message, 1;
  out = tools::timed_run_report(*made.value());
  return 0;
}

// ede-bench-elastic, next to this executable.
std::string elastic_only_binary() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("ede-bench-elastic") : (self.parent_path() / "ede-bench-elastic").string();
}

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

ChildMeasurement run_elastic_only(const std::string& path, std::uint64_t events) {
  ChildMeasurement m;
  const std::string command =
      shell_quoted(elastic_only_binary()) + " " + shell_quoted(path) + " " + std::to_string(events) + " 2>&1";
  std::FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return m.failure = "cannot run " + command, m;
  std::string output;
  char buf[512];
  while (std::fgets(buf, sizeof buf, pipe)) output += buf;
  const int status = pclose(pipe);
  m.ok = status == 0;
  if (m.ok)
    m.values = parse_key_values(output);
  else
    m.failure = output.empty() ? "ede-bench-elastic failed (status " + std::to_string(status) + ")" : output;
  return m;
}

double ns_per_event(const ChildMeasurement& m) {
  return get(m.values, "events") > 0 ? 1e9 * get(m.values, "wall") / get(m.values, "events") : 0;
}
double cycles_per_event(const ChildMeasurement& m) {
  return get(m.values, "events") > 0 ? get(m.values, "cycles") / get(m.values, "events") : 0;
}

// Per configuration: one measurement per round of each engine kind.
struct Series {
  std::vector<ChildMeasurement> specialized, all_effects;
};

struct Spread {
  double median = 0, low = 0, high = 0;
};
Spread spread_of(const std::vector<double>& v) {
  if (v.empty()) return {};
  return {median(v), *std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end())};
}

std::string with_spread(const Spread& s) { return fmt(s.median) + " (" + fmt(s.low) + "-" + fmt(s.high) + ")"; }

std::string first_failure(const std::vector<ChildMeasurement>& runs) {
  for (const ChildMeasurement& m : runs)
    if (!m.ok) return m.failure;
  return "";
}

}  // namespace

int run_effects(const EffectsOptions& o) {
  const std::vector<EffectConfig> configs = effect_configs();
  // What each configuration runs as, in ede-sim's words (and a check that every override is valid).
  std::vector<std::string> effects;
  std::size_t disks = 0;
  for (const EffectConfig& c : configs) {
    Setup s = load(o.scene, c, o.events);
    disks = s.initial.size();
    if (!s.failure.empty()) return std::fprintf(stderr, "ede-bench effects: %s\n", s.failure.c_str()), 1;
    auto made = make_engine<double>(s.initial, s.options);
    if (!made) return std::fprintf(stderr, "ede-bench effects: %s\n", made.error().message.c_str()), 1;
    effects.push_back(made.value()->effects());
  }

  // Ratios are taken on user-mode cycles when perf events are available (the other jobs of a shared
  // machine disturb them much less than wall time), else on wall time.
  const bool use_cycles = tools::CpuCycles().available();
  const auto cost_per_event = [&](const ChildMeasurement& m) {
    return use_cycles ? cycles_per_event(m) : ns_per_event(m);
  };
  std::vector<Series> series(configs.size());
  std::vector<ChildMeasurement> elastic_only;
  // A warm-up run, not counted: the first child of a session runs on a cold cache and a slow clock.
  run_child_measurement([&](std::string& out) { return measure_in_child(o.scene, configs[0], o.events, false, out); });
  for (int round = 1; round <= o.repeat; ++round) {
    std::fprintf(stderr, "ede-bench effects: round %d of %d\n", round, o.repeat);
    for (std::size_t k = 0; k < configs.size(); ++k) {
      const EffectConfig& c = configs[k];
      series[k].specialized.push_back(run_child_measurement(
          [&](std::string& out) { return measure_in_child(o.scene, c, o.events, false, out); }));
      if (c.walls)
        series[k].all_effects.push_back(run_child_measurement(
            [&](std::string& out) { return measure_in_child(o.scene, c, o.events, true, out); }));
      if (k == 0) elastic_only.push_back(run_elastic_only(o.scene, o.events));
    }
  }
  for (std::size_t k = 0; k < configs.size(); ++k) {
    const std::string failed = first_failure(series[k].specialized) + first_failure(series[k].all_effects);
    if (!failed.empty())
      return std::fprintf(stderr, "ede-bench effects: %s: %s\n", configs[k].label.c_str(), failed.c_str()), 1;
  }
  if (const std::string failed = first_failure(elastic_only); !failed.empty())
    return std::fprintf(stderr, "ede-bench effects: ede-bench-elastic: %s\n", failed.c_str()), 1;

  std::printf("Scene %s (%zu disks), %llu events per run, %d rounds; ns/event medians over rounds, ratios "
              "per round then median (min-max over rounds in brackets), on %s.\n\n",
              o.scene.c_str(), disks, static_cast<unsigned long long>(o.events), o.repeat,
              use_cycles ? "user-mode cycles per event" : "wall time per event (no perf events here)");
  std::printf("| effects switched on | engine (ede-sim's effects line) | ns/event | cycles/event | vs elastic | "
              "all-effects engine ns/event | all-effects / specialized |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|\n");
  std::FILE* csv = o.csv_path.empty() ? nullptr : std::fopen(o.csv_path.c_str(), "w");
  if (csv)
    std::fprintf(csv, "effects,engine,ns_per_event,cycles_per_event,ratio_to_elastic,all_effects_ns_per_event,"
                      "all_effects_ratio,all_effects_ratio_low,all_effects_ratio_high\n");
  for (std::size_t k = 0; k < configs.size(); ++k) {
    const Series& s = series[k];
    std::vector<double> ns, cycles, vs_elastic, generic, generic_ratio;
    for (std::size_t r = 0; r < s.specialized.size(); ++r) {
      ns.push_back(ns_per_event(s.specialized[r]));
      cycles.push_back(cycles_per_event(s.specialized[r]));
      vs_elastic.push_back(cost_per_event(s.specialized[r]) / cost_per_event(series[0].specialized[r]));
      if (r < s.all_effects.size()) {
        generic.push_back(ns_per_event(s.all_effects[r]));
        generic_ratio.push_back(cost_per_event(s.all_effects[r]) / cost_per_event(s.specialized[r]));
      }
    }
    const Spread ratio = spread_of(generic_ratio);
    const bool have_cycles = median(cycles) > 0;
    std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", configs[k].label.c_str(), effects[k].c_str(),
                fmt(median(ns)).c_str(), have_cycles ? fmt(median(cycles)).c_str() : "n/a",
                k == 0 ? "1" : with_spread(spread_of(vs_elastic)).c_str(),
                generic.empty() ? "(walls only)" : fmt(median(generic)).c_str(),
                generic.empty() ? "" : with_spread(ratio).c_str());
    if (csv)
      std::fprintf(csv, "\"%s\",\"%s\",%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", configs[k].label.c_str(),
                   effects[k].c_str(), median(ns), median(cycles), median(vs_elastic),
                   generic.empty() ? 0.0 : median(generic), ratio.median, ratio.low, ratio.high);
  }
  if (csv) std::fclose(csv);

  // The elastic gas in this binary (every effect compiled in) against ede-bench-elastic (only its own).
  std::vector<double> all_ns, only_ns, only_ratio;
  for (std::size_t r = 0; r < elastic_only.size(); ++r) {
    all_ns.push_back(ns_per_event(series[0].specialized[r]));
    only_ns.push_back(ns_per_event(elastic_only[r]));
    only_ratio.push_back(cost_per_event(series[0].specialized[r]) / cost_per_event(elastic_only[r]));
  }
  const Spread ratio = spread_of(only_ratio);
  // Two binaries differ in code layout (alignment of the hot loop), which moves a run by a few percent
  // either way whatever the code; the verdict is on "not slower", with the rounds' spread as the noise.
  const double slower = ratio.low - 1;
  const std::string verdict =
      slower <= 0.02 ? "not slower with every effect compiled in"
                     : "slower with every effect compiled in, by " + fmt(100 * slower, 2) + "% at least: investigate";
  std::printf("\nElastic gas, every effect compiled in (ede-bench, through make_engine): %s ns/event; only the "
              "elastic path compiled in (ede-bench-elastic): %s ns/event; ratio %s: %s.\n",
              fmt(median(all_ns)).c_str(), fmt(median(only_ns)).c_str(),
              with_spread(ratio).c_str(), verdict.c_str());
  return 0;
}

}  // namespace ede::bench
