// ede::Rng: xoshiro256** and SplitMix64, transcribed from Vigna's reference C code (prng.di.unimi.it).
//
// Everything here is integer arithmetic or IEEE-exact double operations (one multiply by a power of two,
// one correctly rounded sqrt), so the output is the same bit for bit on every platform; only normal_pair
// calls std::log (normal_pair_exact and exponential_exact use exact_log instead). below() is Lemire's "nearly divisionless" method: one 64x64->128 multiply per draw and a
// division only in the rare rejection branch. Rejected: x % n (biased) and the classic "reject above
// the largest multiple of n" (a division per draw).
#include "core/rng.hpp"

#include <cmath>

namespace ede {

namespace {

constexpr std::uint64_t kGolden = 0x9E3779B97F4A7C15ull;

// SplitMix64's output function: a bijection of the 64-bit words with mix(0) = 0.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// The high and low 64 bits of a * b.
void mul128(std::uint64_t a, std::uint64_t b, std::uint64_t& hi, std::uint64_t& lo) {
#ifdef __SIZEOF_INT128__
  const unsigned __int128 p = static_cast<unsigned __int128>(a) * b;
  hi = static_cast<std::uint64_t>(p >> 64);
  lo = static_cast<std::uint64_t>(p);
#else
  const std::uint64_t a_lo = a & 0xFFFFFFFFu, a_hi = a >> 32, b_lo = b & 0xFFFFFFFFu, b_hi = b >> 32;
  const std::uint64_t ll = a_lo * b_lo, lh = a_lo * b_hi, hl = a_hi * b_lo, hh = a_hi * b_hi;
  const std::uint64_t mid = (ll >> 32) + (lh & 0xFFFFFFFFu) + (hl & 0xFFFFFFFFu);
  hi = hh + (lh >> 32) + (hl >> 32) + (mid >> 32);
  lo = (mid << 32) | (ll & 0xFFFFFFFFu);
#endif
}

}  // namespace

std::uint64_t splitmix64_next(std::uint64_t& state) {
  state += kGolden;
  return mix(state);
}

Rng::Rng(std::uint64_t seed) {
  std::uint64_t sm = seed;
  for (auto& word : s_) word = splitmix64_next(sm);
}

Rng Rng::for_stream(std::uint64_t seed, std::uint64_t stream) { return Rng(seed ^ mix(stream * kGolden)); }

Rng Rng::from_state(const std::array<std::uint64_t, 4>& s) {
  Rng rng(0);
  if ((s[0] | s[1] | s[2] | s[3]) != 0) {
    for (int k = 0; k < 4; ++k) rng.s_[k] = s[k];
  }
  return rng;
}

std::uint64_t Rng::below(std::uint64_t n) {
  std::uint64_t hi, lo;
  mul128(next_u64(), n, hi, lo);
  if (lo < n) {
    const std::uint64_t threshold = (0 - n) % n;  // 2^64 mod n: the low words that would bias the result
    while (lo < threshold) mul128(next_u64(), n, hi, lo);
  }
  return hi;
}

void Rng::unit_vector(double& ux, double& uy) {
  for (;;) {
    const double u = 2.0 * uniform01() - 1.0;
    const double v = 2.0 * uniform01() - 1.0;
    const double s = u * u + v * v;
    if (s > 1.0 || s < 1e-200) continue;  // outside the disk, or too near the centre to normalise
    const double norm = std::sqrt(s);
    ux = u / norm;
    uy = v / norm;
    return;
  }
}

namespace {

// Marsaglia's polar method with the logarithm `ln`.
template <class Ln>
void polar_pair(Rng& rng, double& z0, double& z1, Ln ln) {
  for (;;) {
    const double u = 2.0 * rng.uniform01() - 1.0;
    const double v = 2.0 * rng.uniform01() - 1.0;
    const double s = u * u + v * v;
    if (s >= 1.0 || s == 0.0) continue;
    const double f = std::sqrt(-2.0 * ln(s) / s);
    z0 = u * f;
    z1 = v * f;
    return;
  }
}

}  // namespace

void Rng::normal_pair(double& z0, double& z1) {
  polar_pair(*this, z0, z1, [](double s) { return std::log(s); });
}

double exact_log(double x) {
  int e = 0;
  double m = std::frexp(x, &e);  // x = m 2^e, m in [0.5, 1): exact
  if (m < 0x1.6a09e667f3bcdp-1) {  // below sqrt(1/2): m in [sqrt(1/2), sqrt(2)) after doubling (exact)
    m = m * 2.0;
    e = e - 1;
  }
  const double z = (m - 1.0) / (m + 1.0);
  const double z2 = z * z;
  double sum = 1.0 / 23.0;
  for (int k = 10; k >= 0; --k) sum = sum * z2 + 1.0 / double(2 * k + 1);
  const double ln_m = 2.0 * z * sum;
  // ln 2 = ln2_hi + ln2_lo (to 1e-26), ln2_hi with 33 significant bits, so e * ln2_hi is exact (|e| <= 1075).
  constexpr double kLn2Hi = 0x1.62e42feep-1, kLn2Lo = 0x1.a39ef35793c76p-33;
  const double de = double(e);
  return de * kLn2Hi + (de * kLn2Lo + ln_m);
}

void Rng::normal_pair_exact(double& z0, double& z1) { polar_pair(*this, z0, z1, exact_log); }

}  // namespace ede
