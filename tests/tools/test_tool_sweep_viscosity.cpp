// ede-sweep's viscosity quantities (tools/sweep/quantities.cpp): a sweep over the shear rate collects
// viscosity.eta@T0 and its error per run, the same numbers ede-stats viscosity --from T0 prints for that
// run's log.
#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tool_runner.hpp"

using namespace ede::test;

TEST_CASE("ede-sweep: viscosity quantities of sheared runs are ede-stats viscosity's numbers", "[tool][sweep][shear]") {
  const std::string dir = temp_path("sweep-viscosity");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::string scene = read_file(source_path("examples/shear/viscosity-gas.toml"));
  scene.replace(scene.find("time = 20000.0"), 14, "time = 300.0");
  std::ofstream(dir + "/gas.toml") << scene;
  std::ofstream(dir + "/v.sweep.toml")
      << "scene = \"gas.toml\"\nresults = \"out\"\nseeds = 1\ncollect = [\"viscosity.eta@100\", "
         "\"viscosity.eta_error@100\", \"viscosity.rate_reduced@100\"]\n[[parameter]]\nkey = \"box.shear_rate\"\n"
         "values = [0.02, 0.04]\n";
  const ToolRun r = run_tool("ede-sweep", dir + "/v.sweep.toml --out-dir " + dir + "/out -j 2", "sweep-viscosity");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const std::string runs = read_file(dir + "/out/runs.csv");
  std::stringstream lines(runs);
  std::string header;
  std::getline(lines, header);
  const std::vector<std::string> names = csv_fields(header);
  const auto column = [&](const std::string& name) {
    return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
  };
  REQUIRE(column("viscosity.eta@100") < names.size());
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    const std::vector<std::string> f = csv_fields(line);
    const std::string log = dir + "/out/" + f[column("log")];
    const ToolRun s = run_tool("ede-stats", "viscosity " + log + " --from 100 --json", "sweep-viscosity-stats");
    REQUIRE(s.status == 0);
    const auto doc = nlohmann::json::parse(s.out);
    CHECK(std::stod(f[column("viscosity.eta@100")]) == Approx(doc["viscosity"].get<double>()).epsilon(1e-15));
    CHECK(std::stod(f[column("viscosity.eta_error@100")]) == Approx(doc["viscosity_error"].get<double>()).epsilon(1e-15));
    CHECK(std::stod(f[column("viscosity.rate_reduced@100")]) == Approx(doc["reduced_rate"].get<double>()).epsilon(1e-15));
    ++rows;
  }
  CHECK(rows == 2);
}
