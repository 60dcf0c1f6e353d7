// ede-stats: statistics and figures from an event log (histograms, Maxwell-Boltzmann comparison,
// per-species values, energy curves, collision statistics, pressure). Each subcommand writes CSV and, with
// --plot FILE.png|svg, a figure drawn by matplotlib from that CSV (tools/plot).
#include <CLI/CLI.hpp>
#include <vector>

#include "stats_tool.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ede-stats: statistics and figures from an ede event log"};
  app.require_subcommand(1);
  using namespace ede::stats_tool;
  const std::vector<std::pair<CLI::App*, Command>> commands = [&] {
    std::vector<std::pair<CLI::App*, Command>> out;
    for (auto add : {add_hist_command, add_species_command, add_energy_command, add_collisions_command,
                     add_pressure_command}) {
      const std::size_t before = app.get_subcommands({}).size();
      Command c = add(app);
      out.emplace_back(app.get_subcommands({})[before], std::move(c));
    }
    return out;
  }();
  CLI11_PARSE(app, argc, argv);
  for (const auto& [sub, run] : commands)
    if (*sub) return run();
  return 2;
}
