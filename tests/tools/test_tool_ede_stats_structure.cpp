// ede-stats gr, sk, psi6, msd and vacf as a user runs them: the summary, the CSV header and rows, --json
// (parsed by nlohmann-json), a figure, and clear errors. One short periodic log (examples/scenes/periodic.toml,
// 1000 disks, t = 3) per process.
#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "tool_runner.hpp"

using namespace ede::test;

namespace {

std::string scratch(const std::string& name) { return temp_path("structure-tool-" + name); }

const std::string& periodic_log() {
  static const std::string log = sim_log(source_path("examples/scenes/periodic.toml"), " --set stop.time=3",
                                         scratch("periodic.ede"), "structure-sim-periodic");
  return log;
}

ToolRun stats(const std::string& args, const std::string& tag) { return run_tool("ede-stats", args, "structure-" + tag); }

}  // namespace

TEST_CASE("ede-stats gr: g(r) as CSV, g(sigma) three ways in the summary and in --json", "[tool][ede-stats]") {
  const std::string csv = scratch("gr.csv");
  const ToolRun r = stats("gr " + periodic_log() + " --from 1 --frames 10 --r-max 0.1 --bins 50 --contact -o " + csv, "gr");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("g(sigma) rate") != std::string::npos);
  const auto rows = lines(read_file(csv));
  REQUIRE(rows.size() == 51);
  CHECK(rows[0] == "r,r_lo,r_hi,g,count,ideal");
  const ToolRun j = stats("gr " + periodic_log() + " --from 1 --frames 10 --r-max 0.1 --bins 50 --contact --json", "gr-json");
  REQUIRE(j.status == 0);
  const auto doc = nlohmann::json::parse(j.out);
  CHECK(doc["command"] == "gr");
  CHECK(doc["columns"]["g"].size() == 50);
  // phi = 0.157: Henderson's g(sigma) = 1.30; the collision route within 3%.
  CHECK(doc["g_sigma_collisions"].get<double>() == Approx(1.30).epsilon(0.03));
}

TEST_CASE("ede-stats sk, psi6, msd and vacf write their CSV and figures", "[tool][ede-stats]") {
  const ToolRun sk = stats("sk " + periodic_log() + " --k-max 300 --shells 30 -o " + scratch("sk.csv"), "sk");
  INFO(sk.err);
  REQUIRE(sk.status == 0);
  CHECK(lines(read_file(scratch("sk.csv")))[0] == "k,k_lo,k_hi,s,vectors");
  const ToolRun p = stats("psi6 " + periodic_log() + " --disks " + scratch("disks.csv") + " --plot " + scratch("g6.png"), "psi6");
  INFO(p.err);
  REQUIRE(p.status == 0);
  CHECK(lines(read_file(scratch("disks.csv"))).size() == 1001);
  CHECK(read_file(scratch("g6.png")).substr(1, 3) == "PNG");
  const ToolRun m = stats("msd " + periodic_log() + " --from 0.5 --max-lag 1 --json", "msd");
  INFO(m.err);
  REQUIRE(m.status == 0);
  const auto doc = nlohmann::json::parse(m.out);
  CHECK(doc["diffusion"].get<double>() > 0);
  CHECK(doc["columns"]["msd"].size() == 101);
  const ToolRun v = stats("vacf " + periodic_log() + " --max-lag 1 --lag-step 0.1 -o " + scratch("vacf.csv"), "vacf");
  INFO(v.err);
  REQUIRE(v.status == 0);
  const auto rows = lines(read_file(scratch("vacf.csv")));
  REQUIRE(rows.size() == 12);
  CHECK(rows[0] == "lag,c,error,c_norm,green_kubo");
  CHECK(std::stod(csv_fields(rows[1])[1]) == Approx(1).epsilon(1e-12));  // C(0) = <v^2> = 1 (unit speeds)
}

TEST_CASE("ede-stats gr, msd: clear errors for a missing log, r_max past half the box, a lag past the window",
          "[tool][ede-stats]") {
  const ToolRun missing = stats("gr " + scratch("nope.ede"), "missing");
  CHECK(missing.status == 1);
  const ToolRun far = stats("gr " + periodic_log() + " --r-max 0.9", "far");
  CHECK(far.status == 1);
  CHECK(far.err.find("half the shorter side") != std::string::npos);
  const ToolRun lag = stats("msd " + periodic_log() + " --max-lag 5", "lag");
  CHECK(lag.status == 1);
  CHECK(lag.err.find("max lag < window length") != std::string::npos);
  const ToolRun both = stats("psi6 " + periodic_log() + " --at 1 --frames 3", "both");
  CHECK(both.status == 2);
}

TEST_CASE("ede-stats viscosity on sheared logs: each run's eta, the zero-shear fit, its CSV and figure",
          "[tool][ede-stats][shear]") {
  // examples/shear/viscosity-gas.toml, shortened to 600 time units, at two rates.
  const std::string scene = source_path("examples/shear/viscosity-gas.toml");
  const std::string a = sim_log(scene, " --set stop.time=600", scratch("nemd-a.ede"), "structure-sim-nemd-a");
  const std::string b = sim_log(scene, " --set stop.time=600 --set box.shear_rate=0.02", scratch("nemd-b.ede"),
                                "structure-sim-nemd-b");
  const std::string csv = scratch("nemd.csv");
  const ToolRun r = stats("viscosity " + a + " " + b + " --from 200 --blocks 5 -o " + csv + " --plot " +
                              scratch("nemd.png"), "nemd");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Matchers::Contains("shear rate 0.04") && Catch::Matchers::Contains("shear rate 0.02") &&
                        Catch::Matchers::Contains("zero shear") && Catch::Matchers::Contains("eta0* / eta_E* ="));
  const std::string text = read_file(csv);
  CHECK(text.rfind("shear_rate,reduced_rate,reduced_rate_squared,eta,eta_error,reduced_eta,", 0) == 0);
  CHECK(std::count(text.begin(), text.end(), '\n') == 3);  // header and one row per run
  CHECK(read_file(scratch("nemd.png")).size() > 1000);
  const ToolRun j = stats("viscosity " + a + " --from 200 --blocks 5 --json", "nemd-json");
  REQUIRE(j.status == 0);
  const auto doc = nlohmann::json::parse(j.out);
  CHECK(doc["viscosity"].get<double>() > 0);
  CHECK(doc["columns"]["eta"].size() == 1);
  // An equilibrium log after a sheared one: the route follows the first, and refuses the second.
  const ToolRun mixed = stats("viscosity " + a + " " + periodic_log(), "nemd-mixed");
  CHECK(mixed.status != 0);
  CHECK_THAT(mixed.err, Catch::Matchers::Contains("not sheared"));
}
