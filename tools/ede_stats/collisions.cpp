// Placeholder until the collisions subcommand is written: registers it and says it is not available yet.
#include <cstdio>

#include "stats_tool.hpp"

namespace ede::stats_tool {

Command add_collisions_command(CLI::App& app) {
  app.add_subcommand("collisions", "(not yet available)");
  return [] {
    std::fprintf(stderr, "ede-stats: collisions is not available yet\n");
    return 1;
  };
}

}  // namespace ede::stats_tool
