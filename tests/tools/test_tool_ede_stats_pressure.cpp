// ede-stats pressure as a user runs it: the summary and its numbers, the CSV (header, one row per block,
// consistent with the summary), figures in PNG and SVG, and clear errors on bad input.
//
// Logs come from ede-sim on the example scenes, shortened with --set; scratch files are per process.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "tool_runner.hpp"

using namespace ede::test;

namespace {

std::string scratch(const std::string& name) { return temp_path("pressure-tool-" + name); }

// A walled gas (examples/gas.toml: 2000 disks, phi = 0.157) and a periodic one (examples/scenes/periodic.toml),
// each written once per process.
const std::string& walled_log() {
  static const std::string log = sim_log(source_path("examples/gas.toml"), " --set stop.collisions_per_particle=40",
                                         scratch("walls.ede"), "pressure-sim-walls");
  return log;
}

const std::string& periodic_log() {
  static const std::string log = sim_log(source_path("examples/scenes/periodic.toml"), " --set stop.time=1",
                                         scratch("periodic.ede"), "pressure-sim-periodic");
  return log;
}

ToolRun pressure(const std::string& args, const std::string& tag) {
  return run_tool("ede-stats", "pressure " + args, "pressure-" + tag);
}

// The number after `label` in the summary.
double number_after(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  REQUIRE(at != std::string::npos);
  return std::strtod(text.c_str() + at + label.size(), nullptr);
}

const char* const kHeader =
    "block,t0,t1,kT,P_left,P_right,P_bottom,P_top,P_wall,P_virial,Z_wall,Z_virial,pair_collisions,wall_collisions";

}  // namespace

TEST_CASE("ede-stats pressure: summary of a walled gas, and a CSV row per block", "[tool][ede-stats]") {
  const std::string csv = scratch("walls.csv");
  const ToolRun r = pressure(walled_log() + " --from 0.2 --blocks 10 -o " + csv, "walls");
  INFO(r.err);
  REQUIRE(r.status == 0);
  for (const char* label : {"log ", "box ", "phi ", "window ", "blocks ", "kT ", "P_wall ", "P_virial ",
                            "difference ", "ideal gas ", "Henderson ", "checks "})
    CHECK((r.out.find(std::string("\n") + label) != std::string::npos || r.out.rfind(label, 0) == 0));
  CHECK(r.out.find("2000 disks") != std::string::npos);
  CHECK(r.out.find("A_v = A - r (Lx + Ly) = 0.99") != std::string::npos);
  CHECK(number_after(r.out, "\nphi ") == Approx(0.15708).epsilon(1e-4));
  CHECK(number_after(r.out, "\nkT ") == Approx(0.5).epsilon(1e-12));  // speed 1, elastic: exact
  // At phi = 0.157 the pressure is well above the ideal gas's and near Henderson's (walled-box effects ~1%).
  const double p_virial = number_after(r.out, "\nP_virial ");
  const double henderson = number_after(r.out, "Z N kT / A_v = ");
  CHECK(p_virial == Approx(henderson).epsilon(0.02));
  CHECK(number_after(r.out, "P_wall      mean ") == Approx(p_virial).epsilon(0.05));

  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 11);
  CHECK(rows[0] == kHeader);
  double sum = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const auto f = csv_fields(rows[k]);
    REQUIRE(f.size() == 14);
    CHECK(f[0] == std::to_string(k - 1));
    CHECK_FALSE(f[8].empty());  // P_wall
    sum += std::stod(f[9]);
  }
  CHECK(std::stod(csv_fields(rows[1])[1]) == Approx(0.2));
  CHECK(sum / 10 == Approx(p_virial).epsilon(1e-5));  // the summary is the mean of the blocks
}

TEST_CASE("ede-stats pressure: a periodic gas has only the virial pressure", "[tool][ede-stats]") {
  const std::string csv = scratch("periodic.csv");
  const ToolRun r = pressure(periodic_log() + " -o " + csv, "periodic");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("P_wall      n/a (periodic box: no walls)") != std::string::npos);
  CHECK(r.out.find("centre-of-mass frame") != std::string::npos);
  CHECK(r.out.find("difference") == std::string::npos);
  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 21);  // 20 blocks by default
  const auto f = csv_fields(rows[1]);
  REQUIRE(f.size() == 14);
  CHECK(f[4].empty());
  CHECK(f[8].empty());
  CHECK_FALSE(f[9].empty());
  CHECK(f[13] == "0");
}

TEST_CASE("ede-stats pressure --plot writes PNG and SVG figures", "[tool][ede-stats][slow]") {
  const std::string png = scratch("walls.png"), svg = scratch("periodic.svg");
  std::remove(png.c_str());
  std::remove(svg.c_str());
  const ToolRun a = pressure(walled_log() + " --plot " + png, "plot-png");
  INFO(a.err);
  REQUIRE(a.status == 0);
  CHECK(read_file(png).substr(0, 8) == "\x89PNG\r\n\x1a\n");
  const ToolRun b = pressure(periodic_log() + " --blocks 8 --plot " + svg, "plot-svg");
  INFO(b.err);
  REQUIRE(b.status == 0);
  CHECK(read_file(svg).find("<svg") != std::string::npos);
}

TEST_CASE("ede-stats pressure: clear errors on a missing log, an empty window and bad options", "[tool][ede-stats]") {
  const ToolRun missing = pressure(scratch("no-such.ede"), "missing");
  CHECK(missing.status == 1);
  CHECK(missing.err.find("ede-stats: error:") != std::string::npos);
  CHECK(missing.err.find("no-such.ede") != std::string::npos);

  const ToolRun empty = pressure(walled_log() + " --from 0.3 --to 0.3", "empty");
  CHECK(empty.status == 1);
  CHECK(empty.err.find("empty") != std::string::npos);

  const ToolRun late = pressure(walled_log() + " --to 1000", "late");
  CHECK(late.status == 1);
  CHECK(late.err.find("after the end of the log") != std::string::npos);

  const ToolRun one_block = pressure(walled_log() + " --blocks 1", "one-block");
  CHECK(one_block.status == 2);
  CHECK(one_block.err.find("ede-stats pressure: --blocks must be at least 2") == 0);

  const ToolRun flag = pressure(walled_log() + " --no-such-flag", "bad-flag");
  CHECK(flag.status == 2);
  CHECK(flag.err.find("--no-such-flag") != std::string::npos);
  CHECK(pressure(walled_log() + " --blocks many", "bad-number").status == 2);

  const ToolRun bad_plot = pressure(walled_log() + " --plot " + scratch("figure.pdf"), "bad-plot");
  CHECK(bad_plot.status == 2);
  CHECK(bad_plot.err.find(".png or .svg") != std::string::npos);

  const std::string not_a_log = scratch("not-a-log.ede");
  std::ofstream(not_a_log) << "hello";
  const ToolRun garbage = pressure(not_a_log, "garbage");
  CHECK(garbage.status == 1);
  CHECK(garbage.err.find("ede-stats: error:") != std::string::npos);
}
