// The bytes of a scalar in the log, and an order-preserving integer for delta coding.
//
// float and double are stored as their IEEE bits (4 and 8 bytes); long double (x87 extended on x86-64) as
// its 10 significant bytes: the 6 bytes of padding in memory are not part of the value and may hold
// anything, so copying all 16 would make logs differ between identical runs. Byte order: little-endian,
// which the build checks (static_assert) rather than converting.
// ordered_key maps a scalar to an unsigned integer with the same order (negative values flipped), so the
// difference of two nearby values' keys is small: time deltas and velocity residuals code in few bytes.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace ede {

static_assert(std::endian::native == std::endian::little, "the log format is written for little-endian hosts");

using u128 = unsigned __int128;
using i128 = __int128;

template <class T>
struct ScalarBytes;

template <>
struct ScalarBytes<float> {
  static constexpr std::size_t kWidth = 4;
  static constexpr int kBits = 32;
};
template <>
struct ScalarBytes<double> {
  static constexpr std::size_t kWidth = 8;
  static constexpr int kBits = 64;
};
template <>
struct ScalarBytes<long double> {
  static_assert(std::numeric_limits<long double>::digits == 64, "long double must be x87 extended precision");
  static constexpr std::size_t kWidth = 10;
  static constexpr int kBits = 80;
};

template <class T>
constexpr std::size_t kScalarWidth = ScalarBytes<T>::kWidth;

template <class T>
inline void scalar_to_bytes(T v, unsigned char* out) {
  std::memcpy(out, &v, kScalarWidth<T>);
}

template <class T>
inline T scalar_from_bytes(const unsigned char* in) {
  T v{};  // long double: the padding bytes stay zero
  std::memcpy(&v, in, kScalarWidth<T>);
  return v;
}

// The value's bits as an integer (the low kBits bits).
template <class T>
inline u128 scalar_bits(T v) {
  u128 bits = 0;
  std::memcpy(&bits, &v, kScalarWidth<T>);
  return bits;
}

template <class T>
inline T scalar_from_bits(u128 bits) {
  T v{};
  std::memcpy(&v, &bits, kScalarWidth<T>);
  return v;
}

// Order-preserving: a < b (as numbers, for non-NaN) implies ordered_key(a) < ordered_key(b).
template <class T>
inline u128 ordered_key(T v) {
  constexpr int n = ScalarBytes<T>::kBits;
  const u128 mask = (u128(1) << n) - 1;
  const u128 sign = u128(1) << (n - 1);
  const u128 bits = scalar_bits(v);
  return (bits & sign) ? (~bits & mask) : (bits | sign);
}

template <class T>
inline T from_ordered_key(u128 key) {
  constexpr int n = ScalarBytes<T>::kBits;
  const u128 mask = (u128(1) << n) - 1;
  const u128 sign = u128(1) << (n - 1);
  key &= mask;
  return scalar_from_bits<T>((key & sign) ? (key & ~sign) : (~key & mask));
}

}  // namespace ede
