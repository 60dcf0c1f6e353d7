// A state read from CSV, the format ede-replay --at and ede-sim --final-state write (core/state_csv.hpp):
// the header id,species,x,y,vx,vy,radius,mass, then one row per disk with ids 0, 1, 2, ... in order.
// Species are names (numbers are names too) and get indices in order of first appearance. Numbers are read
// with std::from_chars, exactly (the writer prints the digits that read back to the same double).
// Every error names the file, the line and the column, what is wrong and the fix. Checks of the state as
// a whole (overlaps, the box) are check_initial_state's, once the box is known.
// Rejected: a CSV library (Debian has none the project uses, and the format is eight fixed columns).
#pragma once

#include <string>

#include "core/initial_state.hpp"
#include "ede/error.hpp"

namespace ede {

// The disks of a CSV state; lx and ly are left at 1 (the scene's box is set by the caller).
Result<InitialState> read_state_csv(const std::string& path);
// The same from text already read; `name` stands for the file in messages.
Result<InitialState> parse_state_csv(const std::string& text, const std::string& name);

}  // namespace ede
