// The setup benchmark; see setup_bench.hpp.
#include "study/setup_bench.hpp"

#include <cmath>
#include <cstring>
#include <sstream>
#include <utility>

#include "ede/internal/run.hpp"
#include "ede/internal/setup.hpp"
#include "study/measurement.hpp"
#include "study/timed_run.hpp"

namespace ede::study {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::uint64_t digest(const std::vector<double>& x, const std::vector<double>& y) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (double v : {x[i], y[i]}) {
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
  }
  return h;
}

// place_random in the unit periodic box; CPU seconds, the positions' digest and the bitmap's bytes.
double time_placement(std::uint64_t n, const SetupPlan& plan, bool voxels, std::uint64_t& hash, double& bytes,
                      RandomSampling sampling = RandomSampling::Region) {
  const double r = std::sqrt(plan.packing_fraction / (double(n) * kPi));
  std::vector<double> radii(n, r), x, y;
  const double cpu0 = thread_cpu_seconds();
  setup_detail::PlacementGrid grid(1, 1, true, 2 * r, n);
  if (voxels) grid.enable_blocked_voxels(r, r);
  Rng rng(plan.seed);
  const Status st = setup_detail::place_random({{0, 0, 1, 1}, 1, 1, true, {}, sampling}, radii, grid, rng, x, y);
  const double cpu = thread_cpu_seconds() - cpu0;
  bytes = double(grid.blocked_voxels().bytes());
  hash = st ? digest(x, y) : 0;
  return st ? cpu : -1;
}

// The benchmark's scene with the given placement lines ("kind = ..." and its keys).
std::string scene_text(std::uint64_t n, const SetupPlan& plan, const std::string& placement) {
  std::ostringstream s;
  s.precision(17);
  s << "seed = " << plan.seed << "\n[box]\nsize = [1.0, 1.0]\nboundary = \"periodic\"\n[[species]]\nname = \"gas\"\n"
    << "count = " << n << "\n[species.placement]\n" << placement << "\npacking_fraction = " << plan.packing_fraction
    << "\n[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n[stop]\nevents = 1\n";
  return s.str();
}

int measure_in_child(std::uint64_t n, const SetupPlan& plan, std::string& out) {
  std::ostringstream o;
  o.precision(17);
  std::uint64_t hash = 0, naive_hash = 0;
  double bytes = 0, unused = 0;
  const double placement = time_placement(n, plan, true, hash, bytes);
  if (placement < 0) return out = "random placement failed", 1;
  o << "placement=" << placement << " voxel_bytes=" << bytes;
  if (plan.naive) {
    o << " naive=" << time_placement(n, plan, false, naive_hash, unused) << " same=" << (hash == naive_hash);
  }
  std::uint64_t free_hash = 0;
  o << " free_voxels=" << time_placement(n, plan, true, free_hash, unused, RandomSampling::FreeVoxels);
  // The whole setup of the other starts (free-voxel sampling, a hexagonal lattice), then the default's, whose
  // engine is started.
  using Start = std::pair<const char*, const char*>;
  for (const auto& [key, placement] : {Start{"setup_free", "kind = \"random\"\nsampling = \"free-voxels\""},
                                       Start{"setup_lattice", "kind = \"lattice\""}}) {
    auto scene = parse_scene_text(scene_text(n, plan, placement), "setup-bench.toml");
    if (!scene) return out = scene.error().message, 1;
    const double start = thread_cpu_seconds();
    if (auto planned = plan_run(scene.value()); !planned) return out = planned.error().message, 1;
    o << " " << key << "=" << (thread_cpu_seconds() - start);
  }
  const double cpu0 = thread_cpu_seconds();
  auto scene = parse_scene_text(scene_text(n, plan, "kind = \"random\""), "setup-bench.toml");
  if (!scene) return out = scene.error().message, 1;
  auto planned = plan_run(scene.value());
  if (!planned) return out = planned.error().message, 1;
  const double cpu1 = thread_cpu_seconds();
  auto run = start_run<double>(planned.value());
  if (!run) return out = run.error().message, 1;
  run.value().engine->run(0);  // starts: every disk's first prediction, no event
  const double cpu2 = thread_cpu_seconds();
  o << " setup=" << (cpu1 - cpu0) << " engine_start=" << (cpu2 - cpu1);
  out = o.str();
  return 0;
}

}  // namespace

std::vector<SetupRow> measure_setup(const SetupPlan& plan) {
  std::vector<SetupRow> rows;
  for (std::uint64_t n : plan.disks) {
    const ChildMeasurement m = run_child_measurement([&](std::string& out) { return measure_in_child(n, plan, out); });
    SetupRow row;
    row.disks = double(n);
    row.ok = m.ok;
    row.failure = m.failure;
    row.placement = get(m.values, "placement");
    row.naive_placement = get(m.values, "naive");
    row.same_positions = !plan.naive || get(m.values, "same") == 1;
    row.voxel_bytes = get(m.values, "voxel_bytes");
    row.setup = get(m.values, "setup");
    row.free_voxel_placement = get(m.values, "free_voxels");
    row.setup_free_voxels = get(m.values, "setup_free");
    row.setup_lattice = get(m.values, "setup_lattice");
    row.engine_start = get(m.values, "engine_start");
    row.peak_rss = m.peak_rss;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace ede::study
