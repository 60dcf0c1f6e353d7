// Dense states as a user makes them: the jamming example scene through ede-sim (phi_J in its summary), the
// equation-of-state sweep's small version through ede-sweep (Z against Kolafa-Rottner, the figure), and
// ede-bench grow. The small sweep: N = 400, 30 collisions per disk, phi 0.60-0.74; at phi <= 0.65 its Z
// must be within 5% of Kolafa-Rottner (its block errors there are 1.5-2%, measured; fixed seeds).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "tool_runner.hpp"

using namespace ede::test;

TEST_CASE("ede-sim grows the bidisperse example to jamming and reports phi_J", "[tools][grow][slow]") {
  const ToolRun r = run_tool("ede-sim", source_path("examples/dense/jam-bidisperse.toml") +
                                            " --json -q --set species.small.count=150 --set species.big.count=150",
                             "jam");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("\"setup_note\"") != std::string::npos);
  CHECK(r.out.find("(jammed: Z = ") != std::string::npos);
  const auto at = r.out.find("to 0.8");
  CHECK(at != std::string::npos);
}

TEST_CASE("a grown state is the log's first keyframe and a later scene starts from it", "[tools][grow]") {
  const std::string log = sim_log(source_path("examples/dense/grow-0.72.toml"),
                                  " --set species.disks.count=300 --set stop.collisions_per_particle=5",
                                  temp_path("grown.ede"), "grown");
  const ToolRun p = run_tool("ede-replay", "state " + log + " --at 0", "grown-state");  // the first keyframe
  INFO(p.err);
  REQUIRE(p.status == 0);
  const auto rows = lines(p.out);
  REQUIRE(rows.size() == 301);
  double area = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double r = std::stod(csv_fields(rows[i])[6]);
    area += 3.14159265358979323846 * r * r;
  }
  CHECK(std::abs(area / 0.72 - 1) < 1e-12);  // the unit box, grown exactly to 0.72
  const std::string scene = temp_path("from-grown.toml");
  std::ofstream(scene) << "[box]\nboundary = \"periodic\"\n[start]\nfrom = \"" << log
                       << "\"\nat = 0\n[stop]\ncollisions_per_particle = 2\n";
  const ToolRun r = run_tool("ede-sim", scene + " -q", "from-grown");
  INFO(r.err);
  CHECK(r.status == 0);
}

TEST_CASE("ede-sweep runs the small equation-of-state sweep and draws Z against Kolafa-Rottner", "[tools][grow][slow]") {
  const std::string dir = temp_path("eos-small");
  const std::string png = dir + ".png";
  std::filesystem::remove_all(dir);
  const ToolRun r = run_tool(
      "ede-sweep", source_path("examples/sweeps/eos-dense.sweep.toml") +
                       " -q -j 2 --set species.disks.count=400 --set stop.collisions_per_particle=30 --out-dir " + dir +
                       " --plot " + png +
                       " --quantity pressure.z_virial --against grow.packing_fraction --reference kolafa-rottner"
                       " --reference henderson --mark-transition",
      "eos", 600);
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(std::filesystem::file_size(png) > 1000);
  CHECK(std::filesystem::exists(dir + "/reference-kolafa-rottner.csv"));
  const auto rows = lines(read_file(dir + "/points.csv"));
  REQUIRE(rows.size() == 16);
  const auto header = csv_fields(rows[0]);
  const auto column = [&](const std::string& name) {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return k;
    FAIL("no column " << name);
    return std::size_t(0);
  };
  const std::size_t phi = column("grow.packing_fraction"), z = column("pressure.z_virial_mean"),
                    kr = column("pressure.z_kolafa_rottner_mean"), psi = column("structure.psi6_mean");
  int compared = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto f = csv_fields(rows[i]);
    const double p = std::stod(f[phi]);
    CHECK(std::stod(f[psi]) >= 0);
    CHECK(std::stod(f[psi]) <= 1);
    if (p > 0.655) continue;
    INFO("phi = " << p << ": Z = " << f[z] << ", Kolafa-Rottner " << f[kr]);
    CHECK(std::abs(std::stod(f[z]) / std::stod(f[kr]) - 1) < 0.05);
    ++compared;
  }
  CHECK(compared == 6);
  std::filesystem::remove_all(dir);
  std::filesystem::remove(png);
}

TEST_CASE("ede-bench grow times both targets", "[tools][grow][slow]") {
  const ToolRun r = run_tool("ede-bench", "grow --disks 200", "bench-grow", 300);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("| phi 0.72, equal disks | 200 |") != std::string::npos);
  CHECK(r.out.find("| jammed, 50/50 ratio 1.4 | 200 |") != std::string::npos);
}
