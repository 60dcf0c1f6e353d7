// The few scalar functions and constants the engine needs, for every scalar type it is built for: float,
// double, long double and, where GCC's libquadmath is available (EDE_HAVE_FLOAT128), __float128.
//
// For the standard types each function forwards to its std:: namesake and scalar_limits<T> is
// std::numeric_limits<T>: after inlining, the code is what calling std:: directly gave. __float128 has no
// std::sqrt and no std::numeric_limits specialization in strict C++ (-std=c++20), so it gets quadmath's
// functions and its constants as exact double literals (2^-112 is a double; infinity converts exactly).
// The engine calls these qualified (ede::sqrt), so a missing include is a compile error, never a silent
// fall back to the C library's double ::sqrt.
// Rejected: adding overloads to namespace std or specializing std::numeric_limits<__float128> (the
// standard allows neither for a type the program does not define, and libstdc++ specializes the latter
// itself in GNU mode), and wrapping __float128 in a class with operators (more code than the engine it
// serves, and a second arithmetic to trust).
#pragma once

#include <bit>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <type_traits>

#if EDE_HAVE_FLOAT128
#include <quadmath.h>
#endif

namespace ede {

template <class T>
struct scalar_limits : std::numeric_limits<T> {};

// c ? a : b without a branch for float and double: both values are ready and one is picked by a bit
// mask, so a coin-flip condition costs no misprediction (GCC turns a plain ?: on doubles back into a
// jump). Other types use ?: (they are not the fast engines).
template <class T>
inline T select_value(bool c, T a, T b) {
  if constexpr (std::is_same_v<T, double> || std::is_same_v<T, float>) {
    using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
    const Bits mask = Bits(0) - Bits(c);
    return std::bit_cast<T>(Bits((std::bit_cast<Bits>(a) & mask) | (std::bit_cast<Bits>(b) & ~mask)));
  } else {
    return c ? a : b;
  }
}

template <std::floating_point T>
inline T sqrt(T x) { return std::sqrt(x); }
template <std::floating_point T>
inline T abs(T x) { return std::abs(x); }
template <std::floating_point T>
inline T floor(T x) { return std::floor(x); }
// The remainder of x / y with the sign of x, computed exactly (IEEE fmod rounds nothing).
template <std::floating_point T>
inline T fmod(T x, T y) { return std::fmod(x, y); }

#if EDE_HAVE_FLOAT128
template <>
struct scalar_limits<__float128> {
  static constexpr __float128 epsilon() { return __float128(0x1p-112); }
  static constexpr __float128 infinity() { return __float128(std::numeric_limits<double>::infinity()); }
  static __float128 min() { return ldexpq(__float128(1), -16382); }  // the smallest normal, 2^-16382
};

inline __float128 sqrt(__float128 x) { return sqrtq(x); }
inline __float128 abs(__float128 x) { return fabsq(x); }
inline __float128 floor(__float128 x) { return floorq(x); }
inline __float128 fmod(__float128 x, __float128 y) { return fmodq(x, y); }
#endif

}  // namespace ede
