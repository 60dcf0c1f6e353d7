// Placeholder until the energy subcommand is written: registers it and says it is not available yet.
#include <cstdio>

#include "stats_tool.hpp"

namespace ede::stats_tool {

Command add_energy_command(CLI::App& app) {
  app.add_subcommand("energy", "(not yet available)");
  return [] {
    std::fprintf(stderr, "ede-stats: energy is not available yet\n");
    return 1;
  };
}

}  // namespace ede::stats_tool
