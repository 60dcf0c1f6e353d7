// Pilot runs for --dry-run (see dry_run.hpp).
#include "dry_run.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <unistd.h>

#include "ede/number_text.hpp"

namespace ede::sweep {

namespace {

struct Pilot {
  std::string name, error;
  double seconds = 0, bytes = 0;  // extrapolated to the whole run
  bool finished = false, bounded = false;
};

double share(const Simulation& sim, const StopSpec& stop) {
  double f = 0;
  if (stop.time) f = std::max(f, double(sim.time()) / *stop.time);
  if (stop.events) f = std::max(f, double(sim.counts().events()) / double(*stop.events));
  if (stop.collisions_per_particle)
    f = std::max(f, sim.summary().collisions_per_particle / *stop.collisions_per_particle);
  return std::min(f, 1.0);
}

Pilot pilot(const Sweep& s, const PlannedRun& r, const std::string& dir, double limit) {
  Pilot p;
  p.name = r.name;
  std::vector<Override> overrides;
  for (const std::string& o : r.overrides) overrides.push_back({o});
  auto scene = load_scene_file(s.spec.scene_path, overrides);
  if (!scene) return p.error = scene.error().message, p;
  const std::string path = dir + "/" + r.name + ".ede";
  const auto start = std::chrono::steady_clock::now();
  auto sim = Simulation::create(scene.value(), {path, {}});
  if (!sim) return p.error = sim.error().message, p;
  double elapsed = 0;
  RunStatus status = RunStatus::Running;
  while (status == RunStatus::Running && elapsed < limit) {
    status = sim.value().run(20000);
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  p.finished = status != RunStatus::Running;
  const double f = p.finished ? 1.0 : share(sim.value(), scene.value().stop);
  p.bounded = !p.finished && scene.value().stop.energy_fraction.has_value();
  (void)sim.value().close();
  std::error_code ignored;
  const double bytes = double(std::filesystem::file_size(path, ignored));
  if (f <= 0) return p.error = "no progress to extrapolate from in " + brief(elapsed, 2) + " s", p;
  p.seconds = elapsed / f;
  p.bytes = bytes / f;
  return p;
}

std::string mib(double bytes) { return brief(bytes / 1048576.0, 3) + " MiB"; }

}  // namespace

std::string dry_run_report(const Sweep& s, std::size_t jobs, double pilot_seconds) {
  std::string t = s.spec.path + ": " + std::to_string(s.runs.size()) + " runs (" + std::to_string(point_count(s.spec)) +
                  " points x " + std::to_string(std::max<std::size_t>(1, s.spec.seeds.size())) + " seeds), results in " +
                  s.results + "\n";
  const std::string dir = (std::filesystem::temp_directory_path() / ("ede-sweep-pilot-" + std::to_string(getpid()))).string();
  std::filesystem::create_directories(dir);
  std::vector<const PlannedRun*> pilots{&s.runs.front()};
  if (s.runs.size() > 1) pilots.push_back(&s.runs.back());
  double seconds = 0, bytes = 0;
  std::size_t measured = 0;
  bool bounded = false;
  for (const PlannedRun* r : pilots) {
    const Pilot p = pilot(s, *r, dir, pilot_seconds);
    if (!p.error.empty()) {
      t += "pilot " + p.name + ": " + p.error + "\n";
      continue;
    }
    t += "pilot " + p.name + ": " + (p.finished ? "finished" : "extrapolated") + ", ~" + brief(p.seconds, 2) +
         " s and " + mib(p.bytes) + " of log per run" + (p.bounded ? " (at most: it stops on energy)" : "") + "\n";
    seconds += p.seconds, bytes += p.bytes, bounded = bounded || p.bounded, ++measured;
  }
  std::filesystem::remove_all(dir);
  if (measured == 0) return t + "estimate: none (no pilot ran)\n";
  const double n = double(s.runs.size());
  const double wall = seconds / double(measured) * n / double(std::max<std::size_t>(1, std::min(jobs, s.runs.size())));
  t += "estimate: " + std::string(bounded ? "at most " : "") + brief(wall / 60, 2) + " min on " + std::to_string(jobs) +
       " workers, " + mib(bytes / double(measured) * n) + " of logs (the mean of the pilots, times " +
       std::to_string(s.runs.size()) + " runs)\n";
  return t;
}

}  // namespace ede::sweep
