// The state at a time as CSV: header id,species,x,y,vx,vy,radius,mass, one row per disk in id order.
//
// Every number is printed with enough digits to read back to the identical value of its type (float 9,
// double 17, long double 21, __float128 36 significant digits), so a CSV is an exact snapshot, comparable bit for bit
// between ede-sim --final-state and ede-replay. Positions are drifted to `time` with the shared drift
// function.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "ede/error.hpp"

namespace ede {

template <class T>
void write_state_csv(std::FILE* out, const Particles<T>& p, T time, const std::vector<std::string>& species_names);

template <class T>
Status write_state_csv_file(const std::string& path, const Particles<T>& p, T time,
                            const std::vector<std::string>& species_names);

}  // namespace ede
