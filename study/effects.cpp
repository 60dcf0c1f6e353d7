// The effects study; see effects.hpp. Runs are interleaved (every configuration once per round, rounds
// repeated) so that a slow spell of a noisy machine hits all of them; figures are medians over rounds,
// and ratios are taken within a round before the median, with their spread (min-max over rounds).
// Effects change the physics (cooling slows the gas; a strong g piles it up near the floor, where events
// cost more because the neighbourhoods are fuller), so the figure is per event, not per unit of simulated
// time, and gravity is measured weak (the code's cost on the same gas) and strong (what a user sees).
#include "study/effects.hpp"

#include <algorithm>
#include <cstdio>

#include "ede/internal/run.hpp"
#include "study/cpu_cycles.hpp"
#include "study/measurement.hpp"
#include "study/study_engine.hpp"
#include "study/timed_run.hpp"

namespace ede::study {

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
      // A divider with a hole across the middle (two segments): the segment engine's cost on the same
      // gas (the all-effects engine has no segments: that column stays empty).
      {"wall segments (a divider)",
       {"walls.segments=[{from=[0.5,0.0],to=[0.5,0.45]},{from=[0.5,0.55],to=[0.5,1.0]}]"},
       false},
      // Rough disks (omega per disk, the tangential impulse): the rough engine's cost on the same gas,
      // perfectly rough (elastic) and partly rough. Smooth scenes never run it (engine_factory.hpp): their
      // rows above are what they cost; the all-effects engine has no rotation, so that column stays empty.
      {"rough disks (beta = beta_w = 1)", {"physics.roughness=1", "physics.wall_roughness=1"}, false},
      {"rough disks (beta = 0.5, xi = 0.98)", {inelastic_pairs, "physics.roughness=0.5"}, false},
      // A stepped potential (square wells and shoulders, sigma = 0.0071364, lambda = 1.5): the stepped
      // engine's cost per event on the same gas; its step events are events too, and more of them per unit
      // of time. Hard-disk scenes never run it (engine_factory.hpp), so the rows above are what they cost.
      {"square well (lambda = 1.5, depth 0.5)", {"physics.steps=[{radius=[0.0107046],energy=[-0.5]}]"}, false},
      {"square shoulder (lambda = 1.5, 0.5)", {"physics.steps=[{radius=[0.0107046],energy=[0.5]}]"}, false},
      // The Andersen thermostat (one global clock, a redraw now and then): the thermostat engine's cost on
      // the same gas, redrawing rarely (0.01 per disk per unit time) and often (1). Scenes without it never
      // run that engine; the all-effects engine has none, so that column stays empty.
      {"thermostat (nu = 0.01)", {"thermostat.temperature=1", "thermostat.rate=0.01"}, false},
      {"thermostat (nu = 1)", {"thermostat.temperature=1", "thermostat.rate=1"}, false},
      // A Lees-Edwards box (the sliding images' offset, their scans, the realignments, the shear events):
      // the sheared engine's cost on the same gas, not sheared (rate 0: a periodic box run by it) and
      // sheared (rate 1: the images slide at one box length per unit time). Scenes without it never run
      // that engine; the all-effects engine has none, so that column stays empty.
      {"Lees-Edwards (rate 0)", {"box.boundary=\"lees-edwards\"", "box.shear_rate=0"}, false},
      {"Lees-Edwards (rate 1)", {"box.boundary=\"lees-edwards\"", "box.shear_rate=1"}, false},
      // The same with the thermostat drawing about the flow (the sheared engine carries its clock in every
      // sheared scene: the row above pays one comparison per event for it).
      {"Lees-Edwards (rate 1), thermostat (nu = 0.01)",
       {"box.boundary=\"lees-edwards\"", "box.shear_rate=1", "thermostat.temperature=1", "thermostat.rate=0.01"},
       false},
      {"every effect (weak g)", {inelastic_pairs, "physics.pairs[0].restitution=0.9", "physics.wall_restitution=0.9",
                                 "physics.tc=1e-5", "physics.gravity=[0, -0.001]"}},
  };
}

struct Setup {
  std::string failure;
  std::uint64_t events = 0;
  InitialState initial;
  EngineOptions options;
};

// The plan's overrides come after the configuration's: a user's --set has the last word.
Setup load(const EffectsPlan& plan, const EffectConfig& config) {
  std::vector<std::string> all = config.overrides;
  all.insert(all.end(), plan.overrides.begin(), plan.overrides.end());
  Setup s;
  auto scene = load_scene_file(plan.scene, as_overrides(all));
  if (!scene) return s.failure = scene.error().message, s;
  auto run = plan_run(scene.value());
  if (!run) return s.failure = run.error().message, s;
  s.events = scene.value().stop.events.value_or(0);
  s.options = run.value().options;
  s.initial = std::move(run.value().initial);
  return s;
}

// The child's side: the engine make_engine picks (or the all-effects one), timed.
int measure_in_child(const EffectsPlan& plan, const EffectConfig& config, bool all_effects, std::string& out) {
  Setup s = load(plan, config);
  if (!s.failure.empty()) return out = s.failure, 1;
  EngineVariant variant;
  variant.all_effects = all_effects;
  auto made = make_study_engine<double>(s.initial, s.options, variant);
  if (!made) return out = made.error().message, 1;
  out = timed_run_report(*made.value());
  return 0;
}

ChildMeasurement measure(const EffectsPlan& plan, const EffectConfig& config, bool all_effects) {
  return run_child_measurement([&](std::string& out) { return measure_in_child(plan, config, all_effects, out); });
}

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

ChildMeasurement run_elastic_only(const EffectsPlan& plan) {
  ChildMeasurement m;
  std::string command = shell_quoted(plan.elastic_only_binary) + " " + shell_quoted(plan.scene);
  for (const std::string& o : plan.overrides) command += " --set " + shell_quoted(o);
  command += " 2>&1";
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

// The event loop's CPU time per event (on a quiet machine its wall time; on a busy one the part of it the
// run itself spent).
double ns_per_event(const ChildMeasurement& m) {
  return get(m.values, "events") > 0 ? 1e9 * get(m.values, "cpu") / get(m.values, "events") : 0;
}
double cycles_per_event(const ChildMeasurement& m) {
  return get(m.values, "events") > 0 ? get(m.values, "cycles") / get(m.values, "events") : 0;
}

Spread spread_of(const std::vector<double>& v) {
  if (v.empty()) return {};
  return {median(v), *std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end())};
}

std::string first_failure(const std::vector<ChildMeasurement>& runs) {
  for (const ChildMeasurement& m : runs)
    if (!m.ok) return m.failure;
  return "";
}

// Per configuration: one measurement per round of each engine kind.
struct Series {
  std::vector<ChildMeasurement> specialized, all_effects;
};

}  // namespace

Result<EffectsResults> run_effects_study(const EffectsPlan& plan) {
  const std::vector<EffectConfig> configs = effect_configs();
  EffectsResults res;
  res.scene = plan.scene;
  res.rounds = plan.repeat;
  // What each configuration runs as, in ede-sim's words (and a check that every override is valid).
  for (const EffectConfig& c : configs) {
    Setup s = load(plan, c);
    if (!s.failure.empty()) return Error{s.failure};
    auto made = make_engine<double>(s.initial, s.options);
    if (!made) return made.error();
    EffectRow row;
    row.label = c.label;
    row.engine = made.value()->effects();
    res.rows.push_back(row);
    res.disks = s.initial.size();
    res.events = s.events;
  }
  // Ratios are taken on user-mode cycles when perf events are available, else on the thread's CPU time:
  // the other jobs of a shared machine disturb both much less than wall time.
  res.cycles = CpuCycles().available();
  const auto cost_per_event = [&](const ChildMeasurement& m) {
    return res.cycles ? cycles_per_event(m) : ns_per_event(m);
  };
  std::vector<Series> series(configs.size());
  std::vector<ChildMeasurement> elastic_only;
  measure(plan, configs[0], false);  // a warm-up, not counted: the first child runs on a cold cache
  for (int round = 1; round <= plan.repeat; ++round) {
    std::fprintf(stderr, "ede-bench effects: round %d of %d\n", round, plan.repeat);
    for (std::size_t k = 0; k < configs.size(); ++k) {
      series[k].specialized.push_back(measure(plan, configs[k], false));
      if (configs[k].walls) series[k].all_effects.push_back(measure(plan, configs[k], true));
      if (k == 0) elastic_only.push_back(run_elastic_only(plan));
    }
  }
  for (std::size_t k = 0; k < configs.size(); ++k)
    if (const std::string f = first_failure(series[k].specialized) + first_failure(series[k].all_effects); !f.empty())
      return Error{configs[k].label + ": " + f};
  if (const std::string f = first_failure(elastic_only); !f.empty()) return Error{"ede-bench-elastic: " + f};

  for (std::size_t k = 0; k < configs.size(); ++k) {
    const Series& s = series[k];
    EffectRow& row = res.rows[k];
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
    row.ns_per_event = median(ns);
    row.cycles_per_event = median(cycles);
    row.vs_elastic = spread_of(vs_elastic);
    row.all_effects = !generic.empty();
    row.all_effects_ns_per_event = median(generic);
    row.all_effects_ratio = spread_of(generic_ratio);
  }
  std::vector<double> all_ns, only_ns, only_ratio;
  for (std::size_t r = 0; r < elastic_only.size(); ++r) {
    all_ns.push_back(ns_per_event(series[0].specialized[r]));
    only_ns.push_back(ns_per_event(elastic_only[r]));
    only_ratio.push_back(cost_per_event(series[0].specialized[r]) / cost_per_event(elastic_only[r]));
  }
  res.elastic_ns_per_event = median(all_ns);
  res.elastic_only_ns_per_event = median(only_ns);
  res.elastic_vs_elastic_only = spread_of(only_ratio);
  return res;
}

}  // namespace ede::study
