// Placeholder until the pressure subcommand is written: registers it and says it is not available yet.
#include <cstdio>

#include "stats_tool.hpp"

namespace ede::stats_tool {

Command add_pressure_command(CLI::App& app) {
  app.add_subcommand("pressure", "(not yet available)");
  return [] {
    std::fprintf(stderr, "ede-stats: pressure is not available yet\n");
    return 1;
  };
}

}  // namespace ede::stats_tool
