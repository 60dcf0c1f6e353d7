// ede-stats impacts as a user runs it: the summary (KS against the uniform impact parameter and the
// flux-weighted relative speed), the CSV of both histograms, --json (parsed by nlohmann-json), a figure,
// and clear errors. One short periodic log (examples/scenes/periodic.toml, 1000 disks, t = 3) per process.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "tool_runner.hpp"

using namespace ede::test;

namespace {

std::string scratch(const std::string& name) { return temp_path("impacts-tool-" + name); }

const std::string& periodic_log() {
  static const std::string log = sim_log(source_path("examples/scenes/periodic.toml"), " --set stop.time=3",
                                         scratch("periodic.ede"), "impacts-sim-periodic");
  return log;
}

ToolRun stats(const std::string& args, const std::string& tag) { return run_tool("ede-stats", args, "impacts-" + tag); }

}  // namespace

TEST_CASE("ede-stats impacts: histograms of b and g against their laws, KS in the summary and --json", "[tool][ede-stats]") {
  const std::string csv = scratch("impacts.csv"), png = scratch("impacts.png");
  const ToolRun r = stats("impacts " + periodic_log() + " --from 1 --bins 10 -o " + csv + " --plot " + png, "csv");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("KS against U(0,1)") != std::string::npos);
  CHECK(r.out.find("Gamma(3/2)") != std::string::npos);
  const auto rows = lines(read_file(csv));
  REQUIRE(rows.size() == 11);
  CHECK(rows[0] == "b_left,b_right,b_density,b_law,g_left,g_right,g_density,g_law");
  CHECK(read_file(png).substr(1, 3) == "PNG");
  const ToolRun j = stats("impacts " + periodic_log() + " --from 1 --json", "json");
  REQUIRE(j.status == 0);
  const auto doc = nlohmann::json::parse(j.out);
  CHECK(doc["command"] == "impacts");
  CHECK(doc["pair_collisions"].get<double>() > 10000);
  CHECK(doc["columns"]["b_density"].size() == 20);
  // An equilibrium gas (the start of equal speeds relaxed by t = 1): both laws hold (p > 1e-3).
  CHECK(doc["impact_ks_p"].get<double>() > 1e-3);
  CHECK(doc["speed_ks_p"].get<double>() > 1e-3);
  CHECK(doc["mean_impact"].get<double>() == Approx(0.5).margin(0.02));
}

TEST_CASE("ede-stats impacts: clear errors for a missing log, bad bins and a range without collisions", "[tool][ede-stats]") {
  const ToolRun missing = stats("impacts " + scratch("no-such.ede"), "missing");
  CHECK(missing.status == 1);
  CHECK(missing.err.find("no-such.ede") != std::string::npos);
  const ToolRun bins = stats("impacts " + periodic_log() + " --bins 0", "bins");
  CHECK(bins.status == 2);
  const ToolRun empty = stats("impacts " + periodic_log() + " --from 1 --to 1", "empty");
  CHECK(empty.status == 1);
  CHECK(empty.err.find("no pair collision in the range") != std::string::npos);
}
