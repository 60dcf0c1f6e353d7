// ede-bench setup [--disks N]... [--packing-fraction PHI] [--no-naive] [-o FILE.csv]: how long the start of
// a run takes (random placement, the rest of setup, the engine's first predictions) at each N, and random
// placement with the blocked-voxel test against the grid alone (study/setup_bench.hpp); a Markdown table.
#include <cstdio>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "study/measurement.hpp"
#include "study/setup_bench.hpp"

namespace ede::bench {

namespace {

using study::fmt;

struct SetupOptions {
  study::SetupPlan plan;
  bool no_naive = false;
  std::string csv_path;
};

int run_setup(SetupOptions& o) {
  o.plan.naive = !o.no_naive;
  const std::vector<study::SetupRow> rows = study::measure_setup(o.plan);
  std::printf("Equal disks at packing fraction %s in a periodic unit box; CPU seconds of the measuring thread, one "
              "run each.\n\n| N | placement s | grid-only placement s | speed-up | same positions | voxel map B/disk "
              "| setup s (all) | engine start s | peak RSS B/disk | free-voxel placement s | setup s, free voxels "
              "| setup s, lattice |\n|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n",
              fmt(o.plan.packing_fraction).c_str());
  std::ostringstream csv;
  csv << "disks,placement_s,naive_placement_s,same_positions,voxel_bytes_per_disk,setup_s,engine_start_s,"
         "peak_rss_bytes_per_disk,free_voxel_placement_s,setup_free_voxels_s,setup_lattice_s\n";
  int status = 0;
  for (const study::SetupRow& r : rows) {
    if (!r.ok) {
      std::printf("| %.0f | failed: %s |\n", r.disks, r.failure.c_str());
      status = 1;
      continue;
    }
    if (!r.same_positions) status = 1;
    const bool naive = o.plan.naive;
    std::printf("| %.0f | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.disks,
                fmt(r.placement, 3).c_str(), naive ? fmt(r.naive_placement, 3).c_str() : "-",
                naive && r.placement > 0 ? (fmt(r.naive_placement / r.placement, 3) + "x").c_str() : "-",
                naive ? (r.same_positions ? "yes" : "NO") : "-", fmt(r.voxel_bytes / r.disks, 3).c_str(),
                fmt(r.setup, 3).c_str(), fmt(r.engine_start, 3).c_str(), fmt(r.peak_rss / r.disks, 3).c_str(),
                fmt(r.free_voxel_placement, 3).c_str(), fmt(r.setup_free_voxels, 3).c_str(),
                fmt(r.setup_lattice, 3).c_str());
    csv << r.disks << "," << r.placement << "," << r.naive_placement << "," << r.same_positions << ","
        << r.voxel_bytes / r.disks << "," << r.setup << "," << r.engine_start << "," << r.peak_rss / r.disks << ","
        << r.free_voxel_placement << "," << r.setup_free_voxels << "," << r.setup_lattice << "\n";
  }
  if (!o.csv_path.empty() && !write_file(o.csv_path, csv.str())) return 1;
  return status;
}

}  // namespace

Command setup_command(CLI::App& app) {
  auto o = std::make_shared<SetupOptions>();
  CLI::App* s = app.add_subcommand("setup", "time to start a run at each N; blocked voxels against the grid alone");
  s->add_option("--disks", o->plan.disks, "disk counts (default 10^4 10^5 10^6)");
  s->add_option("--packing-fraction", o->plan.packing_fraction, "packing fraction (default 0.5)")
      ->check(CLI::Range(0.01, 0.54));
  s->add_flag("--no-naive", o->no_naive, "skip the grid-only placement");
  s->add_option("-o,--output", o->csv_path, "also write the table as CSV to this file");
  return {s, [o] { return run_setup(*o); }};
}

}  // namespace ede::bench
