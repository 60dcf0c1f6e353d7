// Which compiler and which floating-point flags built this ede: recorded in every log header, because a
// different compiler or flag is the first suspect when two runs part (ede-replay diff).
#pragma once

#include <string>

namespace ede {

std::string build_compiler();
std::string build_flags();

}  // namespace ede
