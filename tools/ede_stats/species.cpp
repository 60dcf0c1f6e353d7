// Placeholder until the species subcommand is written: registers it and says it is not available yet.
#include <cstdio>

#include "stats_tool.hpp"

namespace ede::stats_tool {

Command add_species_command(CLI::App& app) {
  app.add_subcommand("species", "(not yet available)");
  return [] {
    std::fprintf(stderr, "ede-stats: species is not available yet\n");
    return 1;
  };
}

}  // namespace ede::stats_tool
