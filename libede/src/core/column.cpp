// Column, exact_text and parse_exact (ede/state.hpp).
//
// Exact text uses the digits that round-trip each type (float 9, double 17, long double 21 significant
// digits) in %g form, the format every CSV of ede has used, so old and new outputs compare equal; it is
// written by ede/number_text.hpp (std::to_chars), like every number libede prints.
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "ede/number_text.hpp"
#include "ede/state.hpp"

namespace ede {

ScalarKind Column::scalar() const {
  switch (data_.index()) {
    case 1: return ScalarKind::Float;
    case 2: return ScalarKind::LongDouble;
    default: return ScalarKind::Double;
  }
}

std::size_t Column::size() const {
  return std::visit([](const auto& v) { return v.size(); }, data_);
}

double Column::operator[](std::size_t i) const {
  return std::visit([i](const auto& v) { return double(v[i]); }, data_);
}

long double Column::exact(std::size_t i) const {
  return std::visit([i](const auto& v) { return static_cast<long double>(v[i]); }, data_);
}

std::vector<double> Column::to_doubles() const {
  return std::visit([](const auto& v) { return std::vector<double>(v.begin(), v.end()); }, data_);
}

const void* Column::data() const {
  return std::visit([](const auto& v) -> const void* { return v.data(); }, data_);
}

template <class T>
const std::vector<T>& Column::values() const {
  if (const auto* v = std::get_if<std::vector<T>>(&data_)) return *v;
  throw Exception(Error{std::string("this column holds ") + to_string(scalar()) + " values, not the type asked for",
                        ErrorKind::Invalid});
}
template const std::vector<float>& Column::values<float>() const;
template const std::vector<double>& Column::values<double>() const;
template const std::vector<long double>& Column::values<long double>() const;

std::string exact_text(long double value, ScalarKind scalar) {
  switch (scalar) {
    case ScalarKind::Float: return exact_number(float(value));
    case ScalarKind::LongDouble:
    case ScalarKind::Float128: return exact_number(value);
    case ScalarKind::Double: break;
  }
  return exact_number(double(value));
}

Result<Time> parse_exact(const std::string& text, ScalarKind scalar) {
  const char* s = text.c_str();
  char* end = nullptr;
  errno = 0;
  Time v = 0;
  switch (scalar) {
    case ScalarKind::Float: v = std::strtof(s, &end); break;
    case ScalarKind::Double: v = std::strtod(s, &end); break;
    default: v = std::strtold(s, &end); break;
  }
  if (text.empty() || end != s + text.size() || !std::isfinite(v) || errno == ERANGE)
    return Error{"'" + text + "' is not a finite number"};
  return v;
}

}  // namespace ede
