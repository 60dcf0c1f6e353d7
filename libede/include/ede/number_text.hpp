// Numbers as text, for the library and the tools alike, all through one path: std::to_chars with
// chars_format::general (or fixed) and an explicit precision, which the standard specifies to give what
// printf's %.*g (%.*f) gives in the C locale.
//
// Two uses: exact text, with the significant digits that read back to the identical value (float 9,
// double 17, long double 21: the state CSV, times in messages), and short text for people (6 digits, to
// recognise a value a user typed or to compare two). Every CSV ede wrote before with printf compares
// byte for byte with one written now (checked on every example scene and 3 million random bit patterns
// of each type, with GCC 12 and Clang 14 on libstdc++ 12); the tools' reports and CSVs read as they did
// with their own copy of these functions, now gone. Chosen over libfmt: the same result without a
// dependency, no locale and no format string; a double takes 84 ns instead of snprintf's 287 (long double
// goes through libstdc++'s own printf path and costs about the same as before). Rejected: to_chars' shortest
// form (shorter, but old and new CSVs would no longer compare equal), std::to_string (fixed six decimals
// print 1e-7 as 0.000000). __float128, which to_chars does not know before GCC 13, stays with
// quadmath_snprintf (core/state_csv.cpp).
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>

namespace ede {

// Significant digits that round-trip T: float 9, double 17, long double (x87, 64-bit mantissa) 21.
template <class T>
inline constexpr int kExactDigits = std::is_same_v<T, float> ? 9 : std::is_same_v<T, double> ? 17 : 21;

// Room for any float, double or long double at any precision up to 21 digits: sign, 21 digits, point,
// exponent e-4951.
inline constexpr std::size_t kNumberTextSize = 40;

// Writes v as printf("%.*g", digits, v) would into [first, first + kNumberTextSize); returns the end.
template <class T>
char* put_general(char* first, T v, int digits) {
  return std::to_chars(first, first + kNumberTextSize, v, std::chars_format::general, digits).ptr;
}

template <class T>
std::string general_text(T v, int digits) {
  char b[kNumberTextSize];
  return std::string(b, put_general(b, v, digits));
}

// The text that reads back (strtof, strtod, strtold) to exactly v.
template <class T>
std::string exact_number(T v) {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double> || std::is_same_v<T, long double>);
  return general_text(v, kExactDigits<T>);
}

// `digits` significant digits, as %.<digits>g prints them: short text for messages and reports.
inline std::string brief(double v, int digits = 6) { return general_text(v, digits); }

// `decimals` digits after the point, as %.<decimals>f prints them (for numbers known to be small).
inline std::string fixed_text(double v, int decimals) {
  char b[400];
  return std::string(b, std::to_chars(b, b + sizeof b, v, std::chars_format::fixed, decimals).ptr);
}

// A double exactly (17 significant digits: a long double or Time argument is a double first), and as a
// CSV cell, where NaN (no value) is an empty field.
inline std::string exact_double(double v) { return exact_number(v); }
inline std::string exact_cell(double v) { return std::isnan(v) ? std::string() : exact_double(v); }

}  // namespace ede
