// The one random number generator of ede: xoshiro256** (Blackman & Vigna 2018), seeded by SplitMix64.
//
// Every random draw in setup goes through this class, so a scene and a seed give the same initial state on
// every compiler and standard library. Doubles are made from the top 53 bits explicitly; no
// std::uniform_real_distribution & co., whose output differs between standard libraries.
// Seeding follows Vigna's reference code: the four state words are the first four outputs of SplitMix64
// started at the seed. Streams (one per species) get their own SplitMix64 start, see for_stream().
// Rejected: std::mt19937_64 (portable, but slower, 2.5 KB of state, and it tempts one to use the
// non-portable distributions next to it).
#pragma once

#include <array>
#include <cstdint>

namespace ede {

// SplitMix64 (Steele, Lea & Flood; Vigna's splitmix64.c): advances `state` by the golden-ratio increment
// and returns the mixed output. Exposed for seeding and for the reference-vector tests.
std::uint64_t splitmix64_next(std::uint64_t& state);

// The top 53 bits of `bits` times 2^-53: uniform in [0, 1), every value a multiple of 2^-53.
constexpr double uniform01_from_bits(std::uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

// ln(x) for finite x > 0 from IEEE operations alone (+, -, *, / and the exact frexp), in a fixed order, so
// its bits do not depend on the libm: x = m 2^e with m in [sqrt(1/2), sqrt(2)), z = (m - 1) / (m + 1),
// ln m = 2 (z + z^3/3 + ... + z^23/23) by Horner's rule in z^2 (|z| <= 0.1716: the next term is below 1e-18
// of the sum), ln x = e ln2_hi + (e ln2_lo + ln m) with ln 2 split so that e ln2_hi is exact. Within a few
// units in the last place of the correctly rounded value (tests/core/test_rng.cpp). Rejected: std::log,
// which the standard does not require to be correctly rounded, so two libms may differ in the last bit.
double exact_log(double x);

class Rng {
 public:
  explicit Rng(std::uint64_t seed);

  // Inline (random placement draws two per candidate, ~10^8 at 10^6 disks near jamming).
  std::uint64_t next_u64() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  // Uniform in [0, 1): the top 53 bits of next_u64() times 2^-53.
  double uniform01() { return uniform01_from_bits(next_u64()); }
  // Uniform in [lo, hi): lo + (hi - lo) * uniform01().
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  // Uniform in {0, ..., n-1} for n >= 1, without modulo bias (Lemire's method with rejection).
  std::uint64_t below(std::uint64_t n);
  // A unit vector with uniformly distributed direction, by rejection from the square [-1,1]^2 and one
  // correctly rounded sqrt: no libm trigonometry, so it is bit-identical everywhere.
  void unit_vector(double& ux, double& uy);
  // A pair of independent standard normal deviates (Marsaglia's polar method; uses std::log and std::sqrt,
  // so the last bit may differ between libms: std::log is not required to be correctly rounded).
  void normal_pair(double& z0, double& z1);
  // The same method with exact_log (below) for std::log: bit-identical on every platform, for draws that
  // are part of a run's trajectory (the thermostat), not only of its start.
  void normal_pair_exact(double& z0, double& z1);
  // Exponential with mean 1: -exact_log(1 - uniform01()), 1 - u in (0, 1] exactly.
  double exponential_exact() { return -exact_log(1.0 - uniform01()); }

  // A generator for an independent stream, e.g. one per species. Its SplitMix64 starts at
  // seed ^ mix(stream * 0x9E3779B97F4A7C15), where mix is SplitMix64's output function (a bijection with
  // mix(0) = 0): stream 0 is Rng(seed), and other streams start at scrambled points of SplitMix64's cycle.
  // The plain seed ^ (stream * 0x9E37...) is rejected: SplitMix64 steps by that same constant, so for
  // seed 0 stream 1 would start one step after stream 0 and share three of its four state words.
  static Rng for_stream(std::uint64_t seed, std::uint64_t stream);

  // The raw state, for tests against the reference vectors. `s` must not be all zero (xoshiro's one fixed
  // point; all zeros is replaced by Rng(0)'s state).
  static Rng from_state(const std::array<std::uint64_t, 4>& s);
  std::array<std::uint64_t, 4> state() const { return {s_[0], s_[1], s_[2], s_[3]}; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
};

}  // namespace ede
