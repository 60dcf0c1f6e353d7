// Initial velocities of one species, by its velocity rule, drawn after its positions from its own stream.
//
// Maxwell-Boltzmann uses each disk's own mass (vx, vy ~ N(0, kT/m) with k = 1), so a species of mixed
// sizes and density-based masses is still at temperature T. The sample's net momentum is left as drawn
// (of order sqrt(N m kT)): removing it would couple the disks' draws and change a species' velocities
// whenever its count changes.
// Rejected: drawing speeds from the 2D Maxwell (Rayleigh) distribution and a direction separately (two
// special functions where one normal pair does it).
#pragma once

#include <vector>

#include "core/rng.hpp"
#include "ede/scene.hpp"

namespace ede::setup_detail {

// Fills vx and vy (resized to mass.size()) for disks of the given masses. The spec must be valid (checked
// by setup: a list has one entry per disk, numbers finite, speed and temperature >= 0).
void assign_velocities(const VelocitySpec& spec, const std::vector<double>& mass, Rng& rng,
                       std::vector<double>& vx, std::vector<double>& vy);

// Rough disks: appends each disk's moment of inertia I = f m r^2 and its initial angular velocity (the
// species' spin rule) to inertia and omega. Maxwell takes one normal_pair per disk after the velocities
// (omega from z0, z1 unused), so adding spin leaves every position and velocity as it was.
void assign_spins(const SpeciesSpec& species, const std::vector<double>& mass, const std::vector<double>& radius,
                  Rng& rng, std::vector<double>& omega, std::vector<double>& inertia);

}  // namespace ede::setup_detail
