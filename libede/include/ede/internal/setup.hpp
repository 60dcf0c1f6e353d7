// Internal tier (README.md here): setting up initial states and their parts (placement grid, random
// placement, the deterministic RNG), for the setup benchmark.
#pragma once

#include "core/initial_state.hpp"
#include "core/rng.hpp"
#include "setup/placement_grid.hpp"
#include "setup/setup.hpp"
#include "setup/setup_random_placement.hpp"
