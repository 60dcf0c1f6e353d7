// The stress study; see stress.hpp.
#include "run/log_run_info.hpp"
#include "study/stress.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "engine/engine.hpp"
#include "log/log_reader.hpp"
#include "log/log_writer.hpp"
#include "replay/replay.hpp"
#include "setup/setup.hpp"
#include "study/measurement.hpp"

namespace ede::study {

namespace {

std::string dense_scene(std::uint64_t disks) {
  return "seed = 31\n[box]\nsize = [1.0, 1.0]\nboundary = \"periodic\"\n"
         "[[species]]\nname = \"disks\"\ncount = " + std::to_string(disks) +
         "\n[species.placement]\nkind = \"lattice\"\npacking_fraction = 0.8\n"
         "[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n[stop]\nevents = 10000000\n";
}

std::string inelastic_scene(std::uint64_t disks) {
  return "seed = 37\n[box]\nsize = [1.0, 1.0]\nboundary = \"periodic\"\n"
         "[physics]\nrestitution = 0.5\ntc = 1e-6\n"
         "[[species]]\nname = \"grains\"\ncount = " + std::to_string(disks) +
         "\n[species.placement]\nkind = \"random\"\npacking_fraction = 0.3\n"
         "[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n[stop]\nevents = 10000000\n";
}

struct Totals {
  double energy = 0, px = 0, py = 0, scale = 0;
};

Totals totals(const Particles<double>& p) {
  Totals t;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double m = p.mass(i), vx = p.disk[i].vx, vy = p.disk[i].vy;
    t.energy += 0.5 * m * (vx * vx + vy * vy);
    t.px += m * vx;
    t.py += m * vy;
    t.scale += m * std::hypot(vx, vy);
  }
  return t;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

StressOutcome run_scene(const std::string& name, const std::string& text, const StressPlan& o) {
  StressOutcome out;
  out.scene = name;
  const auto fail = [&](const std::string& why) {
    out.failure = why;
    return out;
  };
  auto scene = parse_scene_text(text, name + ".toml", as_overrides(o.overrides));
  if (!scene) return fail(scene.error().message);
  auto initial = build_initial_state(scene.value());
  if (!initial) return fail(initial.error().message);
  if (scene.value().scalar != ScalarKind::Double) return fail("the stress study runs in double only");
  const EngineOptions options = engine_options_from(scene.value(), initial.value().size());
  auto made = make_engine<double>(initial.value(), options);
  if (!made) return fail(made.error().message);
  EngineApi<double>& engine = *made.value();
  out.disks = initial.value().size();
  const std::string log_path = o.out_dir + "/stress-" + name + ".ede";
  auto writer = LogWriter<double>::create(log_path, log_run_info(scene.value(), options, initial.value().species_names),
                                          LogSettings::from(scene.value().log));
  if (!writer) return fail(writer.error().message);
  engine.add_sink(writer.value().get());

  const bool elastic = options.physics.restitution == 1.0 && options.physics.wall_restitution == 1.0;
  const Totals start = totals(engine.particles());
  double previous_energy = start.energy;
  const std::uint64_t events = scene.value().stop.events.value_or(0);
  const std::uint64_t slice = std::max<std::uint64_t>(1, events / std::max<std::uint64_t>(1, o.checks));
  const auto t0 = std::chrono::steady_clock::now();
  RunStatus status = RunStatus::Running;
  while (out.failure.empty() && status == RunStatus::Running) {
    status = engine.run(slice);
    if (status != RunStatus::Running && status != RunStatus::ReachedEvents) break;
    if (const std::string bad = engine.check_invariants(1e-9); !bad.empty()) out.failure = bad.substr(0, 300);
    out.largest_overlap = std::max(out.largest_overlap, engine.largest_overlap());
    const Totals now = totals(engine.particles());
    out.worst_energy_drift = std::max(out.worst_energy_drift, std::abs(now.energy / start.energy - 1));
    if (elastic && std::abs(now.energy / start.energy - 1) > 1e-10) out.failure = "the energy drifted";
    if (!elastic && now.energy > previous_energy * (1 + 1e-12)) out.failure = "the energy increased";
    previous_energy = now.energy;
    out.momentum_drift = std::max(out.momentum_drift, std::hypot(now.px - start.px, now.py - start.py) / start.scale);
    if (out.momentum_drift > 1e-9) out.failure = "the momentum drifted";
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (status == RunStatus::Running)  // a check failed: close the log where we stopped (else the engine did)
    writer.value()->on_finish(engine.time(), engine.particles(), status);
  out.events = engine.counts().events();
  out.status = status == RunStatus::ReachedEvents ? "ran its events" : to_string(status);
  out.energy_ratio = totals(engine.particles()).energy / start.energy;
  out.tc_share = engine.counts().collisions() ? double(engine.counts().tc_elastic) / double(engine.counts().collisions()) : 0;
  if (status == RunStatus::Stalled) out.failure = engine.stall_message();
  if (!writer.value()->error().empty()) out.failure = writer.value()->error();
  if (!out.failure.empty()) return out;

  auto log = LogReader::open(log_path);
  if (!log) return fail(log.error().message);
  auto replay = Replay<double>::create(log.value());
  if (!replay) return fail(replay.error().message);
  if (Status s = replay.value()->seek_time(engine.time()); !s) return fail(s.error().message);
  out.replay_exact = true;
  for (std::size_t i = 0; i < out.disks; ++i) {
    const Disk<double>& a = replay.value()->particles().disk[i];
    const Disk<double>& b = engine.particles().disk[i];
    out.replay_exact = out.replay_exact && same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.vx, b.vx) &&
                       same_bits(a.vy, b.vy) && same_bits(a.t, b.t);
  }
  if (!out.replay_exact) out.failure = "the log does not replay to the engine's state";
  if (!o.keep_logs) std::remove(log_path.c_str());
  return out;
}

}  // namespace

std::vector<StressOutcome> run_stress(const StressPlan& plan) {
  return {run_scene("dense", dense_scene(plan.disks), plan), run_scene("inelastic", inelastic_scene(plan.disks), plan)};
}

}  // namespace ede::study
