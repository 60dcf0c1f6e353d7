// Numbers in the library's messages and reports: 6 significant digits, enough to recognise a value a user
// typed or to compare two. Rejected: std::to_string, whose fixed six decimals print 1e-7 as 0.000000.
#pragma once

#include <cstdio>
#include <string>

namespace ede {

inline std::string short_number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

}  // namespace ede
