// Setup: a checked Scene -> the disks at t = 0.
//
// Per species, in scene order: radii (fixed, uniform, or from a packing fraction), masses (fixed or
// proportional to area), positions (random non-overlapping with a grid, a lattice, or an explicit list),
// velocities (zero, one speed in random directions, a vector, Maxwell-Boltzmann, or a list). All randomness
// comes from ede::Rng seeded by the scene's seed, one stream per species, so adding a species does not
// change the disks of the ones before it. Every disk is checked against every other (overlap) and the box.
// Disk ids: contiguous per species, species in scene order. Within a random or lattice species the disks
// are ordered along a Hilbert curve over the box (ties by placement order), so disks near in space are
// near in memory; explicit species keep the order of their position list.
#pragma once

#include "core/initial_state.hpp"
#include "ede/error.hpp"
#include "ede/scene.hpp"

namespace ede {

Result<InitialState> build_initial_state(const Scene& scene);

// Checks a hand-made or loaded state: 1 to 10^8 disks, columns of one length, finite numbers, positive
// radius and mass, species indices in range, disks inside the box (walls: the whole disk in [0, lx] x
// [0, ly]; periodic: the centre in [0, lx) x [0, ly) and the disk no wider than the box), and no two
// disks overlapping beyond a relative tolerance of 1e-12 of the contact distance (minimum image when
// periodic). Grid-accelerated: O(N). Messages start with source_name and name disks by id and species;
// given the scene the state was built from, an overlap is said as the loader says errors (FILE:LINE:COL,
// the key of the [x, y] in an explicit list, Fix:).
Status check_initial_state(const InitialState& state, BoundaryKind boundary, const std::string& source_name,
                           const Scene* scene = nullptr);

// Wall segments (check_segments.cpp): finite, of non-zero length, restitution in [0, 1], end points in the
// box; refused in a periodic box and with gravity. And every disk at least its radius from every segment
// (1e-12 relative tolerance, like overlaps).
Status check_segments(const std::vector<SegmentSpec>& segments, double lx, double ly, BoundaryKind boundary,
                      bool gravity, const std::string& source_name);
Status check_disks_clear_of_segments(const InitialState& state, const std::vector<SegmentSpec>& segments,
                                     const std::string& source_name);

}  // namespace ede
