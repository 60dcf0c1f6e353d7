// ede-bench's command line as a user meets it: --help, and status 2 with CLI11's message for a bad one. The
// benchmarks themselves are not run here: they take minutes and measure the machine, not ede's results.
#include <catch2/catch.hpp>
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
  CHECK(run_tool("ede-bench", "--help", "bench-help").status == 0);
  CHECK(run_tool("ede-bench", "log --help", "bench-help-log").status == 0);
}

TEST_CASE("ede-bench stress: packing 0.8 and restitution 0.5 with TC keep every invariant (small)", "[tool][ede-bench][stress]") {
  // The by-hand version runs 10^7+ events (README, reliability); CI runs 3 10^5 per scene.
  const ToolRun r = run_tool("ede-bench", "stress --events 300000 --disks 2000 --checks 30 --out-dir " +
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
