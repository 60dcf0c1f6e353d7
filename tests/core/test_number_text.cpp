// core/number_text.hpp writes numbers with std::to_chars and must give, byte for byte, what printf's %.*g
// gave (every CSV ede wrote before used it, and CSVs are compared byte for byte): checked on special values
// and on many random bit patterns of each type, whatever they mean as numbers.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "core/number_text.hpp"
#include "core/rng.hpp"

using namespace ede;

namespace {

std::string printf_text(double v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}
std::string printf_text(long double v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*Lg", digits, v);
  return b;
}

template <class T>
T from_bits(std::uint64_t low, std::uint64_t high) {
  T v;
  unsigned char raw[sizeof(T)] = {};
  std::memcpy(raw, &low, std::min(sizeof low, sizeof raw));
  if constexpr (sizeof(T) > 8) std::memcpy(raw + 8, &high, std::min(sizeof high, sizeof raw - 8));
  std::memcpy(&v, raw, sizeof v);
  return v;
}

}  // namespace

TEST_CASE("number text is printf's %.*g: special values", "[core][number_text]") {
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const double v : {0.0, -0.0, 1.0, 0.1, -2.5, 1000.0, 1e16, 1e17, 123456789012345678.0, 5e-324,
                         2.2250738585072014e-308, 1.7976931348623157e308, 1e-7, inf, -inf}) {
    CHECK(exact_number(v) == printf_text(v, 17));
    CHECK(short_number(v) == printf_text(v, 6));
    CHECK(exact_number(float(v)) == printf_text(double(float(v)), 9));
    CHECK(exact_number((long double)v) == printf_text((long double)v, 21));
  }
  CHECK(exact_number(std::numeric_limits<long double>::denorm_min()) ==
        printf_text(std::numeric_limits<long double>::denorm_min(), 21));
  CHECK(exact_number(std::numeric_limits<long double>::max()) ==
        printf_text(std::numeric_limits<long double>::max(), 21));
  CHECK(exact_number(std::nan("")) == printf_text(std::nan(""), 17));
}

TEST_CASE("number text is printf's %.*g: random bit patterns of float, double and long double",
          "[core][number_text][slow]") {
  Rng rng(2024);
  for (int k = 0; k < 200000; ++k) {
    const std::uint64_t a = rng.next_u64(), b = rng.next_u64();
    const double d = from_bits<double>(a, 0);
    const float f = from_bits<float>(a >> 32, 0);
    // x87 long double: 64-bit mantissa with its explicit integer bit set (the other encodings are not
    // values a computation produces), then sign and exponent.
    const long double ld = from_bits<long double>(a | (std::uint64_t(1) << 63), b & 0xFFFF);
    if (exact_number(d) != printf_text(d, 17) || short_number(d) != printf_text(d, 6) ||
        exact_number(f) != printf_text(double(f), 9) || exact_number(ld) != printf_text(ld, 21)) {
      FAIL_CHECK("differs from printf for bits " << a << " " << b << ": " << exact_number(d) << " "
                                                 << exact_number(f) << " " << exact_number(ld));
      break;
    }
  }
}
