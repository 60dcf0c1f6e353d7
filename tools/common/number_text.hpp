// Numbers as text in the tools: exact digits for CSV files and for times a user may type back, short
// ones for reports.
//
// Exact is ede::exact_text: the digits that read back to the identical value of the log's scalar type
// (a double: 17 significant digits). Short is std::to_chars with chars_format::general and a precision,
// which the standard specifies to print as printf's %.<precision>g, so reports read as they always have
// (6 digits unless a line wants fewer). One path for every tool. Rejected: snprintf helpers in each file
// (brief, number, num, p_text, ...), five spellings of one idea with buffers sized by hand.
#pragma once

#include <charconv>
#include <cmath>
#include <string>

#include "ede/state.hpp"

namespace ede::tools {

// `digits` significant digits, as %.<digits>g prints them.
inline std::string brief(double v, int digits = 6) {
  char b[64];
  const std::to_chars_result r = std::to_chars(b, b + sizeof b, v, std::chars_format::general, digits);
  return std::string(b, r.ptr);
}

// `decimals` digits after the point, as %.<decimals>f prints them (for numbers known to be small).
inline std::string fixed(double v, int decimals) {
  char b[400];
  const std::to_chars_result r = std::to_chars(b, b + sizeof b, v, std::chars_format::fixed, decimals);
  return std::string(b, r.ptr);
}

// A double exactly (17 significant digits), and as a CSV cell: NaN (no value) is an empty field.
inline std::string exact(double v) { return exact_text(v, ScalarKind::Double); }
inline std::string exact_cell(double v) { return std::isnan(v) ? std::string() : exact(v); }

}  // namespace ede::tools
