// Pressure of a hard-disk gas from its event log: on the walls, and from the virial, with error bars.
//
// One replay pass over a time window (t0, t1] keeps a mirror of every velocity (the replayed state holds
// the velocities after an event; the mirror, those before it), so each event gives its impulse exactly:
//
// Wall pressure (walls boundary). A disk of mass m hitting the left or right wall gives it the normal
// momentum |dp_n| = m |vx' - vx| (top, bottom: vy); the tangential change of the course's wall rule with
// xi_w < 1 is friction, not pressure. 2D pressure is force per unit length:
//   P_wall(wall) = sum |dp_n| / (wall length * (t1 - t0)),   wall length Ly (left, right), Lx (bottom, top);
//   P_wall = sum over the four walls of |dp_n| / (perimeter * (t1 - t0)).
//
// Virial pressure (any boundary). The pressure tensor of a 2D system of area A, as the momentum flux
// through a line (kinetic part plus the forces acting across it), averaged over the box:
//   P_ab A = < sum_i m_i v_ia v_ib > + < sum_{pairs} r_ij,a F_ij,b >,   P = (P_xx + P_yy) / 2,
// with r_ij = r_i - r_j (from j to i) and F_ij the force on i from j. Hard disks act by impulses: the time
// average of a force over a window of length tau is the sum of the impulses in it over tau, so
//   P A = K + (1 / (2 tau)) sum_{pair collisions} r_ij . dp_i,        K = < sum_i m_i v_i^2 / 2 >,
// dp_i = m_i (v_i' - v_i) the impulse on i (= -dp_j), r_ij the contact vector at the collision (length
// r_i + r_j; minimum image in a periodic box). Sign: the contact pushes i away from j, so dp_i is parallel
// to r_ij and every term is positive, r_ij . dp_i = (r_i + r_j) mu (1 + xi) |g_n| (mu the reduced mass,
// g_n the normal relative velocity): hard-core repulsion raises the pressure above the ideal gas's.
// With kT = K / N (2D equipartition: two quadratic degrees of freedom of kT/2 each), P A = N kT + W/(2 tau).
// In a periodic box K is taken in the centre-of-mass frame (the total momentum is conserved and carries
// no pressure); with walls, in the box's frame.
//
// The same from the walls' side (Clausius): with G = sum_i r_i . p_i, <dG/dt> = 0 in a bounded box, so
// 2K + <sum_i r_i . F_i> = 0, the sum over pair forces and wall forces. A disk touching the left wall has
// its centre at x = r, not 0, so with pressure P on every wall the walls contribute
// -P [Ly (Lx - 2r) + Lx (Ly - 2r)] = -2 P A_v,  A_v = Lx Ly - r (Lx + Ly),
// and P A_v = K + W/(2 tau). In a walled box the virial pressure is therefore computed with A_v (the mean
// radius for r), which makes it equal to the wall pressure in expectation, exactly for a square box; with
// A = Lx Ly it would read low by a factor A_v / A (1 - 2r/L). One disk bouncing between two walls shows it:
// P_wall = m v^2 / ((L - 2r) L) on those two walls, 0 on the others, and K / A_v is their mean.
//
// Restitution xi < 1: the impulses are the actual ones (from the velocity change), so the formula gives
// the collisional stress of a driven or cooling granular gas, not an equilibrium pressure; the report says
// when the kinetic energy changed across the window.
//
// Errors: the window is cut into equal fine bins; B blocks of bins_per_block bins each give the reported
// value (mean of the block values, which is the value over the window) and its standard error, with the
// lag-1 correlation of the block values and a Flyvbjerg-Petersen blocking analysis of the bins as checks
// (block_average.hpp).
//
// Rejected: sampling the state at times and computing forces from overlaps or contact densities (the
// usual route for soft potentials): hard disks have no forces between collisions, and the contact-value
// route needs g(sigma) extrapolated from a histogram; the impulses are exact and already in the log.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ede/block_average.hpp"
#include "ede/error.hpp"
#include "ede/log.hpp"
#include "ede/scene.hpp"

namespace ede {

struct PressureOptions {
  std::optional<double> from;  // window start; default: equilibration_mean_free_times mean free times,
                               // at most half the run
  std::optional<double> to;    // window end; default: the end of the log
  double equilibration_mean_free_times = 20;
  std::size_t blocks = 20;           // B
  std::size_t bins_per_block = 64;   // fine bins per block, for the blocking analysis
};

// Henderson's equation of state for hard disks, Z = P A / (N kT) = (1 + phi^2 / 8) / (1 - phi)^2
// (Mol. Phys. 30, 971 (1975)): within ~0.5% of simulations up to phi ~ 0.6, exact to second order in phi.
double henderson_z(double phi);

// One observable over the window: its value per block, the mean and error, and the checks.
struct PressureSeries {
  std::vector<double> block;     // value in each of the B blocks
  BlockStats stats;              // mean +- standard error over the blocks, lag-1 correlation
  BlockingAnalysis blocking;     // of the fine bins
};

// Sums over the window, without any averaging: for exact checks.
struct PressureTotals {
  std::array<double, 4> wall_impulse{};  // sum |dp_n| per wall (WallId order: left, right, bottom, top)
  double virial_sum = 0;                 // W = sum over pair collisions of r_ij . dp_i
  double kinetic_integral = 0;           // integral of K over the window (K as in the header comment)
  double kinetic_start = 0, kinetic_end = 0;  // K at t0 and at t1
  std::uint64_t pair_collisions = 0, wall_collisions = 0;
};

struct PressureReport {
  // The system.
  std::size_t disks = 0;
  BoundaryKind boundary = BoundaryKind::Walls;
  ScalarKind scalar = ScalarKind::Double;
  double lx = 0, ly = 0;
  double area = 0;             // A = Lx Ly
  double virial_area = 0;      // A_v = A - r_mean (Lx + Ly) with walls, A when periodic
  double mean_radius = 0;
  double packing_fraction = 0; // sum pi r^2 / A
  // The window.
  double t0 = 0, t1 = 0;
  double end_time = 0;         // the end of the log
  bool default_start = false;  // t0 was chosen by the equilibration rule
  double mean_free_time = 0;   // N t_end / (2 pair collisions), whole log; infinity without collisions
  std::size_t blocks = 0, bins_per_block = 0;
  std::vector<double> block_t0, block_t1;
  // Results. Each is computed per fine bin, blocks are means of bins. Z = P A / (N kT) with A = Lx Ly.
  PressureSeries kT;                  // K / N (time averaged)
  std::array<PressureSeries, 4> wall; // walls only
  PressureSeries wall_mean;           // walls only: total normal impulse / (perimeter * time)
  PressureSeries virial;
  PressureSeries wall_minus_virial;   // walls only: the difference, bin by bin (its error counts the
                                      // correlation of the two in one run)
  PressureSeries z_wall, z_virial;    // walls only for z_wall
  std::vector<std::uint64_t> block_pair_collisions, block_wall_collisions;
  PressureTotals totals;
  std::vector<std::string> warnings;  // equilibration, energy not conserved, correlated blocks

  bool has_walls() const { return boundary == BoundaryKind::Walls; }
  double ideal() const;          // N kT / A (kT: the window's mean)
  double henderson() const;      // Z_H(phi) N kT / A
  double expected_area() const;  // the area the ideal gas and Henderson values use for this box: A_v with
                                 // walls (see the header comment), A when periodic
};

// Replays the log over the window once and measures. Fails on an unreadable log, a window outside the
// log or empty, or fewer than 2 blocks.
Result<PressureReport> measure_pressure(const Log& log, const PressureOptions& options = {});

}  // namespace ede
