// ede-bench grow [--disks N]... [--rate R] [--set key=value]... [-o FILE.csv]: Lubachevsky-Stillinger
// growth ([grow], setup/grow.hpp) timed on the two targets, each at every --disks: equal disks to
// phi = 0.72 and a 50/50 mixture with radius ratio 1.4 until jammed (Z > 10^6), both in a periodic unit box.
// The time is the wall-clock time of build_initial_state (placement, growth, velocities, the overlap check),
// one run per row: a benchmark of seconds, not a timed test. Rejected: timing through Simulation::create,
// which adds the engine's first predictions and the log's header to what is asked about.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "ede/scene.hpp"
#include "ede/internal/setup.hpp"
#include "study/measurement.hpp"

namespace ede::bench {

namespace {

using study::fmt;

struct GrowPlan {
  std::vector<std::int64_t> disks{1000, 10000};
  double rate = 0.01;
  std::vector<std::string> overrides;
  std::string csv;
};

std::string scene_text(const std::string& kind, std::int64_t n, double rate) {
  std::string text = "seed = 1\n[box]\nsize = [1, 1]\nboundary = \"periodic\"\n";
  if (kind == "mono") {
    text += "[[species]]\nname = \"a\"\ncount = " + std::to_string(n) + "\nradius = 1\n";
    text += "[grow]\npacking_fraction = 0.72\n";
  } else {
    text += "[[species]]\nname = \"small\"\ncount = " + std::to_string(n / 2) + "\nradius = 1\n";
    text += "[[species]]\nname = \"big\"\ncount = " + std::to_string(n - n / 2) + "\nradius = 1.4\n";
    text += "[grow]\npressure = 1e6\n";
  }
  return text + "rate = " + fmt(rate, 6) + "\n[stop]\ntime = 1\n";
}

double packing(const InitialState& s) {
  double a = 0;
  for (double r : s.radius) a += 3.14159265358979323846 * r * r;
  return a / (s.lx * s.ly);
}

int grow(const GrowPlan& plan) {
  std::printf("| target | N | rate | phi reached | seconds | growth |\n|---|---:|---:|---:|---:|---|\n");
  std::string csv = "target,disks,rate,phi,seconds,note\n";
  for (const char* kind : {"mono", "bidisperse"}) {
    for (std::int64_t n : plan.disks) {
      std::vector<Override> overrides;
      for (const std::string& o : plan.overrides) overrides.push_back({o});
      auto scene = parse_scene_text(scene_text(kind, n, plan.rate), "grow-bench.toml", overrides);
      if (!scene) return fail(scene.error().message);
      const auto start = std::chrono::steady_clock::now();
      auto state = build_initial_state(scene.value());
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!state) return fail(state.error().message);
      const std::string target = std::string(kind) == "mono" ? "phi 0.72, equal disks" : "jammed, 50/50 ratio 1.4";
      std::printf("| %s | %lld | %s | %s | %s | %s |\n", target.c_str(), static_cast<long long>(n),
                  fmt(scene.value().grow->rate, 3).c_str(), fmt(packing(state.value()), 6).c_str(),
                  fmt(seconds, 3).c_str(), state.value().note.c_str());
      std::fflush(stdout);
      csv += std::string(kind) + "," + std::to_string(n) + "," + fmt(scene.value().grow->rate, 6) + "," +
             fmt(packing(state.value()), 12) + "," + fmt(seconds, 4) + ",\"" + state.value().note + "\"\n";
    }
  }
  if (!plan.csv.empty() && !write_file(plan.csv, csv)) return 1;
  return 0;
}

}  // namespace

Command grow_command(CLI::App& app) {
  auto plan = std::make_shared<GrowPlan>();
  CLI::App* g = app.add_subcommand("grow", "dense starts by Lubachevsky-Stillinger growth: time to phi 0.72 and to jamming");
  add_set_option(g, plan->overrides);
  g->add_option("--disks", plan->disks, "numbers of disks (default 1000 10000)")->check(CLI::Range(2, 10000000));
  g->add_option("--rate", plan->rate, "growth rate (default 0.01; grow.rate)")->check(CLI::Range(1e-9, 0.999));
  g->add_option("-o,--output", plan->csv, "the table as CSV");
  return {g, [plan] { return grow(*plan); }};
}

}  // namespace ede::bench
