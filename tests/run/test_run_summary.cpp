// to_json(RunSummary): valid JSON whatever the strings hold, numbers that read back exactly, null for
// numbers that are not finite.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "ede/simulation.hpp"

using namespace ede;

TEST_CASE("to_json writes valid JSON: escaped strings, exact doubles, null for non-finite", "[run][json]") {
  RunSummary s;
  s.scene = "dir \"x\"\\scene\n\x01.toml";
  s.effects = "bytes that are not UTF-8: \xff\xfe";
  s.sim_time = 0.1;
  s.wall_seconds = 1.0 / 3.0;
  s.energy_initial = std::numeric_limits<double>::quiet_NaN();
  s.energy_final = std::numeric_limits<double>::infinity();
  s.momentum_final[0] = -5e-324;  // the smallest subnormal
  s.momentum_final[1] = 1.7976931348623157e308;
  s.seed = std::numeric_limits<std::uint64_t>::max();
  const std::string text = to_json(s);
  INFO(text);
  CHECK(text.find('\n') == std::string::npos);
  const auto j = nlohmann::json::parse(text, nullptr, false);
  REQUIRE(!j.is_discarded());
  CHECK(j["scene"] == s.scene);
  CHECK(j["effects"].get<std::string>().rfind("bytes that are not UTF-8: ", 0) == 0);  // bad bytes replaced
  CHECK(j["sim_time"].get<double>() == 0.1);
  CHECK(j["wall_seconds"].get<double>() == 1.0 / 3.0);
  CHECK(j["energy_initial"].is_null());
  CHECK(j["energy_final"].is_null());
  CHECK(j["momentum_final"][0].get<double>() == -5e-324);
  CHECK(j["momentum_final"][1].get<double>() == 1.7976931348623157e308);
  CHECK(j["seed"].get<std::uint64_t>() == std::numeric_limits<std::uint64_t>::max());
}
