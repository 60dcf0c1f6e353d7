// What the ede-stats subcommands share. Each subcommand lives in its own file and registers itself with
// add_*_command, which returns the function main calls once the command line is parsed (the pattern of
// ede-replay). Every figure comes from a log: the subcommands replay it, they never re-run the physics.
// Rejected: one options struct for all subcommands, whose fields would mean different things in each.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace ede::stats_tool {

using Command = std::function<int()>;

Command add_hist_command(CLI::App& app);        // speed and energy histograms, Maxwell-Boltzmann fit
Command add_species_command(CLI::App& app);     // per-species mean speed, energy, temperature
Command add_energy_command(CLI::App& app);      // kinetic energy on a fine time grid
Command add_collisions_command(CLI::App& app);  // collisions per disk, rate, mean free time, speed classes
Command add_impacts_command(CLI::App& app);     // impact parameter and relative speed at collision, KS tests
Command add_pressure_command(CLI::App& app);    // pressure from the walls and from the virial
Command add_gr_command(CLI::App& app);          // pair correlation g(r), contact value g(sigma)
Command add_sk_command(CLI::App& app);          // static structure factor S(k)
Command add_psi6_command(CLI::App& app);        // bond-orientational order psi6, g6(r)
Command add_msd_command(CLI::App& app);         // mean-square displacement, D against Enskog
Command add_vacf_command(CLI::App& app);        // velocity autocorrelation, exact
Command add_viscosity_command(CLI::App& app);   // shear viscosity from the exact stress integral

}  // namespace ede::stats_tool
