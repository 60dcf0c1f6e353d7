// Numbers as text that reads back to the identical value, and times typed by a user read exactly.
//
// A scalar is printed with the significant digits that round-trip its type (float 9, double 17, long
// double 21), like the state CSV, so reports and CSVs name the very value a log holds. A number typed on
// the command line is read with the strto* of the log's scalar type, so `--at 0.1` in a float log is the
// float nearest 0.1, what a float engine stopping at stop.time = 0.1 reaches. The tools word their own
// messages from what read_time says was wrong. Rejected: reading every time as double and converting (a
// long double log's times would be rounded).
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

namespace ede::tools {

// Exact text of a scalar.
inline std::string exact(float v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.9g", double(v));
  return b;
}
inline std::string exact(double v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}
inline std::string exact(long double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.21Lg", v);
  return b;
}

// A CSV cell: exact, and NaN (no value) as an empty field.
inline std::string exact_cell(double v) { return std::isnan(v) ? "" : exact(v); }

// Short text for reports: 6 significant digits.
inline std::string brief(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

inline float parse_number(const char* s, char** end, float) { return std::strtof(s, end); }
inline double parse_number(const char* s, char** end, double) { return std::strtod(s, end); }
inline long double parse_number(const char* s, char** end, long double) { return std::strtold(s, end); }

// The whole of `text` as one finite number of type T (strtof, strtod or strtold); nullopt if it is not.
template <class T>
std::optional<T> parse_exact(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const T v = parse_number(text.c_str(), &end, T{});
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(double(v)) || errno == ERANGE)
    return std::nullopt;
  return v;
}

// What a time typed by a user is: a number >= 0 (exact in T), the word `end`, or neither.
enum class TimeText { Number, End, NotANumber, Negative };

template <class T>
struct ReadTime {
  TimeText kind = TimeText::NotANumber;
  T value{};  // for Number
};

template <class T>
ReadTime<T> read_time(const std::string& text) {
  if (text == "end") return {TimeText::End, T{}};
  const std::optional<T> v = parse_exact<T>(text);
  if (!v) return {TimeText::NotANumber, T{}};
  if (*v < T(0)) return {TimeText::Negative, *v};
  return {TimeText::Number, *v};
}

}  // namespace ede::tools
