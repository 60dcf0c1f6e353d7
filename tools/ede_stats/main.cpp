// ede-stats: statistics and figures from an event log (histograms, Maxwell-Boltzmann comparison,
// per-species values, energy curves, collision statistics, pressure). Each subcommand writes CSV and, with
// --plot FILE.png|svg, a figure drawn by matplotlib from that CSV (tools/plot).
//
// Thin: one file per subcommand, each registering itself and returning the function to run (the pattern
// of ede-replay); the numbers come from ede/analysis.hpp and ede/pressure.hpp. Rejected: one binary per
// analysis (ede-hist, ede-energy, ...), five names to learn for one kind of job.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "tool_main.hpp"
#include "command_line.hpp"
#include "stats_tool.hpp"

static int run_main(int argc, char** argv) {
  CLI::App app{"ede-stats: statistics and figures from an ede event log"};
  app.require_subcommand(1);
  using namespace ede::stats_tool;
  const std::vector<std::pair<std::string, Command>> commands = {
      {"hist", add_hist_command(app)},         {"species", add_species_command(app)},
      {"energy", add_energy_command(app)},     {"collisions", add_collisions_command(app)},
      {"pressure", add_pressure_command(app)}, {"impacts", add_impacts_command(app)},
      {"gr", add_gr_command(app)},             {"sk", add_sk_command(app)},
      {"psi6", add_psi6_command(app)},         {"msd", add_msd_command(app)},
      {"vacf", add_vacf_command(app)},         {"viscosity", add_viscosity_command(app)},
  };
  ede::tools::add_version_flags(app, "ede-stats");
  if (const auto stop = ede::tools::parse_command_line(app, argc, argv)) return *stop;
  for (const auto& [name, run] : commands)
    if (app.got_subcommand(name)) return run();
  return 2;
}

// Out of memory, a stray exception and a failed stdout become one message and a documented status.
int main(int argc, char** argv) { return ede::tools::run_tool("ede-stats", run_main, argc, argv); }
