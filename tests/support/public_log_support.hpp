// Logs for tests of the public analysis functions, written through the public API alone: a scene from
// TOML text, run by ede::Simulation into temp_path(file), opened as an ede::Log.
#pragma once

#include <catch2/catch.hpp>
#include <string>

#include "ede/ede.hpp"
#include "scene_test_support.hpp"  // scene_of, run_to_log
#include "tool_runner.hpp"  // temp_path

namespace ede::test {

inline Log public_log(const std::string& toml, const std::string& file) {
  auto log = Log::open(run_to_log(scene_of(toml, file), file));
  REQUIRE(log);
  return std::move(log).value();
}

// N equal disks of radius r in a unit box (walls or periodic) starting at speed 1 in random directions.
inline std::string gas_toml(int count, double radius, const std::string& stop, const std::string& extra = "",
                            const std::string& boundary = "walls") {
  return "seed = 5\n" + extra + "\n[box]\nsize = [1.0, 1.0]\nboundary = \"" + boundary +
         "\"\n\n[[species]]\nname = \"gas\"\ncount = " + std::to_string(count) + "\nradius = " +
         std::to_string(radius) + "\n\n[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n\n[stop]\n" + stop + "\n";
}

// Two species: 300 "light" disks (m = 1) and 100 "heavy" ones (m = 4), all at speed 1.
inline std::string mixture_toml(const std::string& stop) {
  return "seed = 3\n[box]\nsize = [1.0, 1.0]\n\n[[species]]\nname = \"light\"\ncount = 300\nradius = 0.006\nmass = 1.0\n"
         "[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n\n[[species]]\nname = \"heavy\"\ncount = 100\n"
         "radius = 0.012\nmass = 4.0\n[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n\n[stop]\n" +
         stop + "\n";
}

}  // namespace ede::test
