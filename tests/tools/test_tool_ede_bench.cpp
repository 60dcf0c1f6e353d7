// ede-bench's command line as a user meets it: --help, and status 2 with CLI11's message for a bad one. The
// benchmarks themselves are not run here: they take minutes and measure the machine, not ede's results;
// the exceptions are small versions of the ones that check results (stress, accuracy --quick).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "tool_runner.hpp"

using namespace ede::test;

TEST_CASE("ede-bench: a bad command line exits with status 2 and CLI11's message, --help with 0", "[tool][ede-bench]") {
  const ToolRun flag =
      run_tool("ede-bench", "speed " + source_path("examples/gas.toml") + " --no-such-flag", "bench-flag");
  CHECK(flag.status == 2);
  CHECK(flag.err.find("--no-such-flag") != std::string::npos);
  CHECK(run_tool("ede-bench", "speed", "bench-no-scene").status == 2);
  CHECK(run_tool("ede-bench", "speed " + source_path("examples/gas.toml") + " --repeat 0", "bench-repeat").status == 2);
  CHECK(run_tool("ede-bench", "", "bench-nothing").status == 2);
  // The old spellings are gone (docs/cli.md: --set stop.events=N, -o FILE, --out-dir DIR).
  CHECK(run_tool("ede-bench", "speed " + source_path("examples/gas.toml") + " --events 10", "bench-events").status == 2);
  CHECK(run_tool("ede-bench", "effects --csv x.csv", "bench-csv").status == 2);
  CHECK(run_tool("ede-bench", "accuracy --out x", "bench-out").status == 2);
}

TEST_CASE("ede-bench: every command and subcommand answers --help and --version", "[tool][ede-bench]") {
  for (const std::string sub : {"", "speed", "log", "stress", "effects", "accuracy", "peers", "setup"}) {
    INFO(sub);
    const ToolRun help = run_tool("ede-bench", sub + " --help", "bench-help");
    CHECK(help.status == 0);
    CHECK(help.out.find("--help") != std::string::npos);
    const ToolRun version = run_tool("ede-bench", sub + " --version", "bench-version");
    CHECK(version.status == 0);
    CHECK(version.out.rfind("ede-bench" + (sub.empty() ? "" : " " + sub) + ", ede ", 0) == 0);
  }
  const ToolRun help = run_tool("ede-bench-elastic", "--help", "bench-elastic-help");
  CHECK(help.status == 0);
  CHECK(help.out.find("--set") != std::string::npos);
  const ToolRun version = run_tool("ede-bench-elastic", "--version", "bench-elastic-version");
  CHECK(version.status == 0);
  CHECK(version.out.rfind("ede-bench-elastic, ede ", 0) == 0);
}

TEST_CASE("ede-bench: --set is checked like the scene's own value before anything runs", "[tool][ede-bench]") {
  const std::string scene = source_path("examples/bench/gas-N1000-phi0.5-walls.toml");
  const ToolRun bad = run_tool("ede-bench", "speed " + scene + " --set physics.restitution=2", "bench-set-bad");
  CHECK(bad.status == 1);
  CHECK(bad.err.find("gas-N1000-phi0.5-walls.toml: error: physics.restitution") != std::string::npos);
  CHECK(bad.err.find("--set #1") != std::string::npos);
  CHECK(bad.out.empty());
  const std::string csv = temp_path("bench-speed.csv");
  const ToolRun ok = run_tool("ede-bench",
                              "speed " + scene + " --repeat 1 --baseline-max-disks 0 --set stop.events=20000 -o " + csv,
                              "bench-set-ok", 120);
  INFO(ok.out << ok.err);
  REQUIRE(ok.status == 0);
  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 2);
  CHECK(rows[1].rfind("gas-N1000-phi0.5-walls,1000,20000,", 0) == 0);
}

TEST_CASE("ede-bench peers: a row per scene, log on and off after the warm-up, the CSV beside", "[tool][ede-bench]") {
  const std::string scene = source_path("examples/bench/gas-N1000-phi0.5-periodic.toml");
  const std::string csv = temp_path("bench-peers.csv");
  const ToolRun r = run_tool("ede-bench",
                             "peers " + scene + " --repeat 1 --warmup 2 --segment 2 --min-timed 0 --tmp-dir " + std::string(EDE_BINARY_DIR) + "/tests" +
                                 " -o " + csv,
                             "bench-peers", 120);
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("| gas-N1000-phi0.5-periodic | 1000 | 2 | ") != std::string::npos);
  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 2);
  CHECK(rows[1].rfind("gas-N1000-phi0.5-periodic,1000,2,", 0) == 0);
  // --min-timed stretches the segment of a small system: 10^4 pair collisions of 1000 disks are 20 per disk.
  const ToolRun longer = run_tool("ede-bench",
                                  "peers " + scene + " --repeat 1 --warmup 2 --segment 2 --min-timed 10000 --tmp-dir " +
                                      std::string(EDE_BINARY_DIR) + "/tests",
                                  "bench-peers-min-timed", 120);
  INFO(longer.out << longer.err);
  REQUIRE(longer.status == 0);
  CHECK(longer.out.find("| gas-N1000-phi0.5-periodic | 1000 | 20 | ") != std::string::npos);
  CHECK(run_tool("ede-bench", "peers " + scene + " --segment 0", "bench-peers-segment").status == 2);
}

TEST_CASE("ede-bench setup: a row per N, the blocked voxels placing what the grid alone places", "[tool][ede-bench]") {
  const std::string csv = temp_path("bench-setup.csv");
  const ToolRun r = run_tool("ede-bench", "setup --disks 500 --disks 3000 -o " + csv, "bench-setup", 120);
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("| 3000 | ") != std::string::npos);
  CHECK(r.out.find(" | yes | ") != std::string::npos);
  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 3);
  CHECK(rows[2].rfind("3000,", 0) == 0);
  // The other starts beside the default: free-voxel sampling and a lattice, each timed (> 0 s).
  REQUIRE(rows[0].find(",free_voxel_placement_s,setup_free_voxels_s,setup_lattice_s") != std::string::npos);
  const std::vector<std::string> fields = csv_fields(rows[2]);
  REQUIRE(fields.size() == 11);
  for (std::size_t k = 8; k < 11; ++k) CHECK(std::stod(fields[k]) > 0);
  CHECK(run_tool("ede-bench", "setup --packing-fraction 0.6", "bench-setup-phi").status == 2);
}

TEST_CASE("ede-bench stress: packing 0.8 and restitution 0.5 with TC keep every invariant (small)", "[tool][ede-bench][stress]") {
  // The by-hand version runs 10^7+ events (README, reliability); CI runs 3 10^5 per scene.
  const ToolRun r = run_tool("ede-bench", "stress --set stop.events=300000 --disks 2000 --checks 30 --out-dir " +
                                              std::string(EDE_BINARY_DIR) + "/tests",
                             "stress", 300);
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("| dense | 2000 | 300000 |") != std::string::npos);
  CHECK(r.out.find("| inelastic | 2000 | 300000 |") != std::string::npos);
  std::size_t exact = 0;
  for (std::size_t at = r.out.find("bit-exact"); at != std::string::npos; at = r.out.find("bit-exact", at + 1)) ++exact;
  CHECK(exact == 2);
}

namespace {

// A CSV file as rows of column name -> field (no quoted fields in ede-bench accuracy's tables).
std::vector<std::map<std::string, std::string>> read_csv_rows(const std::string& path) {
  const std::vector<std::string> all = lines(read_file(path));
  std::vector<std::map<std::string, std::string>> rows;
  if (all.empty()) return rows;
  const std::vector<std::string> names = csv_fields(all[0]);
  for (std::size_t k = 1; k < all.size(); ++k) {
    const std::vector<std::string> fields = csv_fields(all[k]);
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < names.size() && c < fields.size(); ++c) row[names[c]] = fields[c];
    rows.push_back(row);
  }
  return rows;
}

double number(const std::map<std::string, std::string>& row, const std::string& column) {
  REQUIRE(row.count(column));
  INFO(column << " = '" << row.at(column) << "'");
  char* end = nullptr;
  const double v = std::strtod(row.at(column).c_str(), &end);
  REQUIRE(end != row.at(column).c_str());
  REQUIRE(std::isfinite(v));
  return v;
}

}  // namespace

TEST_CASE("ede-bench accuracy --quick: a row per setting, finite errors ordered as physics says", "[tool][ede-bench][accuracy][slow]") {
  const std::string out = temp_path("accuracy");
  const ToolRun r = run_tool("ede-bench", "accuracy --quick --no-plot --out-dir " + out + " --scenes " +
                                              source_path("examples/accuracy") + " --tmp-dir " + out + "-tmp",
                             "accuracy", 300);
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const auto engine = read_csv_rows(out + "/engine.csv");
  // (scene, precision, contact) -> row; every setting on every scene, every error finite.
  std::map<std::string, std::map<std::string, std::string>> by;
  for (const auto& row : engine) {
    INFO(row.at("scene") << " " << row.at("precision") << " " << row.at("contact"));
    CHECK(row.at("failure") == "\"\"");
    CHECK(number(row, "ns_per_event") > 0);
    CHECK(number(row, "repeats_agree") == 1);
    for (const char* c : {"energy_drift", "energy_drift_max", "largest_overlap", "reversal_rms_c5", "reversal_rms_c10",
                          "reversal_rms_c20", "reversal_returned_c20", "divergence_path_collisions"})
      number(row, c);
    by[row.at("scene") + "/" + row.at("precision") + "/" + row.at("contact")] = row;
  }
  const std::vector<std::string> precisions = {"float", "double", "long_double"};
  for (const std::string scene : {"gas", "dense", "crystal"})
    for (const std::string& p : precisions)
      for (const std::string contact : {"stable", "textbook"}) CHECK(by.count(scene + "/" + p + "/" + contact) == 1);
  REQUIRE(engine.size() >= 18);
  for (const std::string scene : {"gas", "dense", "crystal"}) {
    INFO(scene);
    const auto& f = by[scene + "/float/stable"];
    const auto& d = by[scene + "/double/stable"];
    const auto& l = by[scene + "/long_double/stable"];
    // Round-off: each step in precision leaves less drift, and float's overlaps are far above double's.
    CHECK(number(f, "energy_drift_max") > 100 * number(d, "energy_drift_max"));
    CHECK(number(d, "energy_drift_max") > number(l, "energy_drift_max"));
    CHECK(number(f, "largest_overlap") > 100 * number(d, "largest_overlap"));
    CHECK(number(d, "largest_overlap") < 1e-13);
    // Time reversal comes back worse after more collisions and in a narrower type.
    CHECK(number(f, "reversal_rms_c20") > number(d, "reversal_rms_c20"));
    CHECK(number(d, "reversal_rms_c20") > number(l, "reversal_rms_c20"));
    // The log stores the run's own type: bytes grow with it.
    CHECK(number(f, "log_bytes_per_event") < number(d, "log_bytes_per_event"));
    CHECK(number(d, "log_bytes_per_event") < number(l, "log_bytes_per_event"));
  }
  const auto& gf = by["gas/float/stable"];
  const auto& gd = by["gas/double/stable"];
  CHECK(number(gf, "reversal_rms_c5") < number(gf, "reversal_rms_c20"));
  // In the gas, runs one float ulp apart part after fewer collisions than runs one double ulp apart.
  CHECK(number(gf, "divergence_path_collisions") > 0);
  const double dd = number(gd, "divergence_path_collisions");
  CHECK((dd < 0 || dd > number(gf, "divergence_path_collisions")));

  const auto log = read_csv_rows(out + "/log.csv");
  REQUIRE(log.size() == 4);  // off, two keyframe intervals, defaults
  CHECK(number(log[1], "bytes_per_event") > number(log[2], "bytes_per_event"));  // denser keyframes: bigger
  CHECK(number(log[1], "seek_median_seconds") < number(log[3], "seek_median_seconds"));

  const auto stepped = read_csv_rows(out + "/time_stepped.csv");
  REQUIRE(stepped.size() == 5);  // event-driven, other seed, dt = 1, 0.3, 0.1 tau
  CHECK(stepped[0].at("method") == "event-driven");
  CHECK(stepped[1].at("method") == "event-driven (other seed)");
  CHECK(number(stepped[0], "energy_drift") < 1e-13);
  for (std::size_t k = 2; k < stepped.size(); ++k) {
    CHECK(stepped[k].at("method") == "time-stepped");
    CHECK(number(stepped[k], "energy_drift") < 1e-12);  // elastic impulses: energy kept by construction
    CHECK(number(stepped[k], "cpu_ratio") > 0);
    if (k > 2) {
      CHECK(number(stepped[k], "rate_error") < number(stepped[k - 1], "rate_error"));
      CHECK(number(stepped[k], "cooling_error") < number(stepped[k - 1], "cooling_error"));
      CHECK(number(stepped[k], "step_over_diameter") < number(stepped[k - 1], "step_over_diameter"));
    }
  }
  CHECK(number(stepped[2], "largest_overlap") > 0.01);  // dt = tau: disks run deep into each other
  const std::string md = read_file(out + "/tables.md");
  CHECK(md.find("| long double, textbook root |") != std::string::npos);
  CHECK(md.find("### The log") != std::string::npos);
  std::filesystem::remove_all(out);
}
