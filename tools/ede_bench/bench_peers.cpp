// ede-bench peers [SCENE.toml...] [--repeat N] [--warmup C] [--segment C] [--min-timed P] [--set key=value]...
//                 [-o FILE.csv]
// The table the published event-driven codes are compared on (issue 15; docs/performance.md, "Against the
// peers"): pair collisions per wall-clock second over a steady segment (after --warmup collisions per disk,
// then --segment more, but at least --min-timed pair collisions in all), ede with the log off and on,
// medians of --repeat rounds in which every case runs once per configuration (interleaved, so a busy machine disturbs both alike), and the log's cost as the
// median of the per-round ratios. The peers themselves are built and run outside the repository
// (docs/performance.md says how); their numbers go beside these.
// Each run is its own process (study/log_measure.hpp: run_measured), so peak RSS is per run.
// Why a minimum: a run's end waits for the log's writer to code the chunks still queued (up to ~5 x 16 384
// events) and syncs the file to disk, a fixed ~4-5 ms that is ~15 % of a 10-collisions-per-disk segment at
// N = 10^4 (30 ms) and nothing at 10^6; 2 * 10^6 collisions make the segment steady at every N
// (docs/performance-journal.md, sixth round).
// Rejected: timing ede-sim from outside (setup, which at N = 10^6 takes longer than the segment, and the
// summary would be in the time).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <unistd.h>

#include "commands.hpp"
#include "study/log_measure.hpp"
#include "study/measurement.hpp"

namespace ede::bench {

namespace {

using study::fmt;
using study::median;
using study::RunConfig;
using study::RunResult;

struct PeersOptions {
  std::vector<std::string> scenes = {
      "examples/bench/gas-N10000-phi0.5-periodic.toml", "examples/bench/gas-N10000-phi0.3-periodic.toml",
      "examples/bench/gas-N100000-phi0.5-periodic.toml", "examples/bench/gas-N1000000-phi0.5-periodic.toml"};
  int repeat = 3;
  double warmup = 25, segment = 10, min_timed = 2e6;
  std::vector<std::string> overrides;
  std::string csv_path, tmp_dir;
};

struct Case {
  std::string label;
  double segment = 0;  // pair collisions per disk timed
  std::vector<RunResult> off, on;
};

// The timed collisions per disk for a scene: --segment, or more to reach --min-timed pair collisions.
double segment_for(const std::string& scene, const std::vector<std::string>& overrides, const PeersOptions& o) {
  auto s = load_scene_file(scene, study::as_overrides(overrides));
  double disks = 0;
  if (s)
    for (const SpeciesSpec& sp : s.value().species) disks += double(sp.count);
  return disks > 0 ? std::max(o.segment, 2 * o.min_timed / disks) : o.segment;
}

double rate(const RunResult& r) { return r.wall > 0 ? r.timed_pairs / r.wall : 0; }

std::vector<double> rates(const std::vector<RunResult>& runs) {
  std::vector<double> v;
  for (const RunResult& r : runs) v.push_back(rate(r));
  return v;
}

int run_peers(const PeersOptions& o) {
  std::vector<std::string> overrides = o.overrides;
  // The run ends by collisions per disk; the bench scenes' own stop.events must not end it first.
  overrides.push_back("stop.events=1000000000000000");
  if (!check_scenes(o.scenes, overrides)) return 1;
  const std::string dir = o.tmp_dir.empty() ? std::filesystem::temp_directory_path().string() : o.tmp_dir;
  std::vector<Case> cases;
  for (const std::string& s : o.scenes) cases.push_back({study::scene_label(s), segment_for(s, overrides, o), {}, {}});
  for (int round = 0; round < o.repeat; ++round)
    for (std::size_t k = 0; k < o.scenes.size(); ++k)
      for (int log = 0; log < 2; ++log) {
        const bool on = (log + round) % 2 == 1;  // alternate which configuration runs first
        RunConfig c;
        c.label = cases[k].label;
        c.scene = o.scenes[k];
        c.overrides = overrides;
        c.overrides.push_back("stop.collisions_per_particle=" + fmt(o.warmup + cases[k].segment, 6));
        c.log = on;
        c.log_path = dir + "/ede-bench-peers-" + std::to_string(getpid()) + ".ede";
        c.warmup_collisions_per_disk = o.warmup;
        RunResult r = study::run_measured(c);
        std::filesystem::remove(c.log_path);
        if (!r.ok) return fail(o.scenes[k] + ": " + r.failure);
        std::fprintf(stderr, "  %s, log %s, round %d: %.3g M collisions/s\n", c.label.c_str(), on ? "on" : "off",
                     round + 1, rate(r) / 1e6);
        (on ? cases[k].on : cases[k].off).push_back(r);
      }
  std::printf("Pair collisions per wall-clock second (millions) over the timed collisions per disk after %s (at "
              "least %s, and %s pair collisions in all), medians of %d interleaved rounds; log cost = median over "
              "rounds of (log off / log on) - 1.\n\n",
              fmt(o.warmup).c_str(), fmt(o.segment).c_str(), fmt(o.min_timed).c_str(), o.repeat);
  std::printf("| case | N | timed collisions per disk | ede, log off | ede, log on | log cost | engine B/disk | peak RSS "
              "B/disk, log off | peak RSS B/disk, log on |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::ostringstream csv;
  csv << "scene,disks,timed_collisions_per_disk,log_off_pairs_per_second,log_on_pairs_per_second,log_cost,engine_bytes_per_disk,"
         "peak_rss_off_per_disk,peak_rss_on_per_disk\n";
  for (const Case& c : cases) {
    const double n = c.off.front().disks;
    std::vector<double> cost, rss_off, rss_on;
    for (std::size_t k = 0; k < c.off.size(); ++k) {
      cost.push_back(rate(c.off[k]) / rate(c.on[k]) - 1);
      rss_off.push_back(c.off[k].peak_rss / n);
      rss_on.push_back(c.on[k].peak_rss / n);
    }
    const double off = median(rates(c.off)), on = median(rates(c.on));
    std::printf("| %s | %.0f | %s | %s | %s | %.0f %% | %s | %s | %s |\n", c.label.c_str(), n, fmt(c.segment).c_str(),
                fmt(off / 1e6).c_str(), fmt(on / 1e6).c_str(), 100 * median(cost),
                fmt(c.off.front().engine_bytes / n).c_str(), fmt(median(rss_off)).c_str(),
                fmt(median(rss_on)).c_str());
    csv << c.label << "," << n << "," << c.segment << "," << off << "," << on << "," << median(cost) << ","
        << c.off.front().engine_bytes / n << "," << median(rss_off) << "," << median(rss_on) << "\n";
  }
  if (!o.csv_path.empty() && !write_file(o.csv_path, csv.str())) return 1;
  return 0;
}

}  // namespace

Command peers_command(CLI::App& app) {
  auto o = std::make_shared<PeersOptions>();
  CLI::App* s = app.add_subcommand(
      "peers", "pair collisions per second after a warm-up, log off and on: the table ede is compared to its peers on");
  s->add_option("scenes", o->scenes, "scene files (default: the four cases of docs/performance.md, from the "
                                     "repository root)");
  s->add_option("--repeat", o->repeat, "interleaved rounds; medians are reported")->check(CLI::Range(1, 100));
  s->add_option("--warmup", o->warmup, "pair collisions per disk before the clock starts")->check(CLI::Range(0.0, 1e6));
  s->add_option("--segment", o->segment, "pair collisions per disk timed after the warm-up")
      ->check(CLI::Range(0.01, 1e6));
  s->add_option("--min-timed", o->min_timed,
                "at least this many pair collisions timed in all (the segment grows at small N; 0: --segment alone)")
      ->check(CLI::Range(0.0, 1e12));
  add_set_option(s, o->overrides);
  s->add_option("--tmp-dir", o->tmp_dir, "where the logs are written (and deleted); default: the system's");
  s->add_option("-o,--output", o->csv_path, "also write the table as CSV to this file");
  return {s, [o] { return run_peers(*o); }};
}

}  // namespace ede::bench
