// ede-bench effects as a user runs it (--quick): every effect's row names the engine ede-sim would run
// for it, the CSV holds the same rows, and the elastic gas is compared with ede-bench-elastic, a binary
// that holds the elastic engine alone (checked on its symbols). The timings themselves are not tested
// (benchmarks are not timed tests): only that they are there and positive.
#include <catch2/catch.hpp>

#include "text_support.hpp"
#include <cstdlib>
#include <string>
#include <vector>

#include "tool_runner.hpp"

using namespace ede::test;

namespace {


}  // namespace

TEST_CASE("ede-bench effects: a row per effect, the engine it selects, the all-effects and elastic-only comparisons",
          "[tool][ede-bench]") {
  const std::string csv = temp_path("bench-effects.csv");
  const ToolRun r =
      run_tool("ede-bench",
               "effects --quick --set stop.events=20000 --scene " +
                   source_path("examples/bench/effects/gas-two-species.toml") + " -o " + csv,
               "bench-effects", 300);
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  for (const char* row : {"| elastic (walls) | walls, elastic, grid", "| periodic box | periodic, elastic, grid",
                          "| inelastic walls (xi_w = 0.9) | walls, inelastic (xi=1, 1 species pairs apart, xi_w=0.9)",
                          "| inelastic + TC (tc = 1e-5) | walls, inelastic (xi=0.98, 1 species pairs apart, xi_w=1), TC",
                          "| gravity, weak (g = 0.001) | walls, elastic, gravity (0, -0.001)",
                          "| gravity, strong (g = 1) | walls, elastic, gravity (0, -1)",
                          "| thermostat (nu = 0.01) | walls, elastic, Andersen thermostat (10000 disks, 100 redraws",
                          "| Lees-Edwards (rate 1) | lees-edwards, shear rate 1, elastic, grid",
                          "| Lees-Edwards (rate 1), thermostat (nu = 0.01) | lees-edwards, shear rate 1, elastic, "
                          "Andersen thermostat (10000 disks, 100 redraws",
                          "| every effect (weak g) | walls, inelastic (xi=0.98, 1 species pairs apart, xi_w=0.9), TC "
                          "(tc=1e-05), gravity (0, -0.001)"})
    CHECK(contains(r.out, row));
  CHECK(contains(r.out, "only the elastic path compiled in (ede-bench-elastic)"));
  CHECK(contains(r.out, "(10000 disks), 20000 events per run, 1 rounds"));

  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 20);  // the header, 19 rows (two square wells, two the thermostat, three shear)
  CHECK(rows[0].rfind("effects,engine,ns_per_event,cycles_per_event,ratio_to_elastic,all_effects_ns_per_event", 0) == 0);
  for (std::size_t k = 1; k < rows.size(); ++k) {
    // The figures after the two quoted fields: ns/event, cycles/event, ratio to elastic, all-effects ns/event.
    const std::string numbers = rows[k].substr(rows[k].rfind('"') + 2);
    char* end = nullptr;
    const double ns = std::strtod(numbers.c_str(), &end);
    CHECK(ns > 0);
    CHECK(*end == ',');
  }
  CHECK(contains(rows[1], "\"elastic (walls)\",\"walls, elastic, grid"));
  CHECK(contains(read_file(csv), "\"wall segments (a divider)\",\"walls, elastic, 2 segments, grid"));
  CHECK(contains(read_file(csv), "\"rough disks (beta = beta_w = 1)\",\"walls, elastic, rough (beta=1, beta_w=1"));
  CHECK(contains(read_file(csv), "\"square well (lambda = 1.5, depth 0.5)\",\"walls, elastic, stepped potential (1 step)"));
}

TEST_CASE("ede-bench-elastic: holds the elastic engine alone and refuses other scenes", "[tool][ede-bench]") {
  const ToolRun other = run_tool("ede-bench-elastic", source_path("examples/crater.toml"), "bench-elastic-crater");
  CHECK(other.status == 1);
  CHECK(contains(other.err, "crater.toml: this binary runs elastic gases in a walled box, in double, only"));
  const ToolRun usage = run_tool("ede-bench-elastic", "", "bench-elastic-usage");
  CHECK(usage.status == 2);
  CHECK(contains(usage.err, "scene is required"));
  const ToolRun run = run_tool("ede-bench-elastic",
                               source_path("examples/bench/effects/gas-two-species.toml") + " --set stop.events=5000",
                               "bench-elastic-run");
  CHECK(run.status == 0);
  CHECK(contains(run.out, "events=5000 "));

  // Its symbols name one Engine instantiation (nm is part of binutils, which the compiler needs).
  const std::string symbols = temp_path("bench-elastic-symbols.txt");
  const std::string command = "nm -C '" + std::string(EDE_BINARY_DIR) + "/tools/ede-bench-elastic' | grep -o " +
                              "'ede::Engine<[^>]*>' | sort -u > '" + symbols + "'";
  REQUIRE(std::system(command.c_str()) == 0);
  const std::vector<std::string> engines = lines(read_file(symbols));
  CHECK(engines == std::vector<std::string>{"ede::Engine<double, ede::WallsBoundary, ede::Elastic, ede::NoField, "
                                            "ede::StableContact, ede::NoSegments, ede::Smooth, ede::HardCore, "
                                            "ede::NoThermostat>"});
}
