// pair_root.hpp's branch-free contact time against geometry.hpp's pair_contact_time: the same bits on every
// kind of input (the engine's log bytes depend on it).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/geometry.hpp"
#include "engine/pair_root.hpp"

using namespace ede;

namespace {
std::uint64_t splitmix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
double uniform(std::uint64_t& s) { return double(splitmix(s) >> 11) * 0x1.0p-53; }

template <class T>
bool same_bits(T a, T b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class T>
void check(T dx, T dy, T dvx, T dvy, T s, T noise, std::uint64_t& failures) {
  const T want = pair_contact_time(dx, dy, dvx, dvy, s, noise);
  const T got = pair_contact_time_unbranched(dx, dy, dvx, dvy, s, noise);
  if (!same_bits(want, got)) ++failures;
}
}  // namespace

TEMPLATE_TEST_CASE("pair_contact_time_unbranched gives pair_contact_time's bits", "[geometry]", float, double) {
  using T = TestType;
  std::uint64_t seed = 15, failures = 0, hits = 0, receding = 0, zero = 0;
  const T noise = b_noise2_for(T(1));
  for (int n = 0; n < 200000; ++n) {
    const T s = T(0.001 + 0.01 * uniform(seed));
    // distances from overlapping to far, velocities of any direction, some tiny (grazing and sliding)
    const T dist = s * T(0.999 + 3 * uniform(seed) * uniform(seed));
    const T angle = T(6.283185307179586 * uniform(seed));
    const T speed = T(n % 7 == 0 ? 1e-9 * uniform(seed) : 2 * uniform(seed));
    const T vangle = T(6.283185307179586 * uniform(seed));
    const T dx = dist * std::cos(angle), dy = dist * std::sin(angle);
    const T dvx = speed * std::cos(vangle), dvy = speed * std::sin(vangle);
    check(dx, dy, dvx, dvy, s, noise, failures);
    check(dx, dy, dvx, dvy, s, T(0), failures);
    const T t = pair_contact_time(dx, dy, dvx, dvy, s, noise);
    hits += t > T(0) && t < kNever<T>;
    receding += t == kNever<T>;
    zero += t == T(0);
  }
  // the cases the decisions separate all occur
  CHECK(hits > 1000);
  CHECK(receding > 1000);
  CHECK(zero > 100);
  // degenerate inputs: at rest, touching exactly, head-on, NaN, infinities
  const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  const T cases[][5] = {{1, 0, 0, 0, 1},    {1, 0, -1, 0, 1},   {2, 0, -1, 0, 1},  {0, 2, 0, -1, 1},
                        {2, 0, 0, -1, 1},   {2, 1, -1, 0, 1},   {2, 1, -1, 1e-30f, 1}, {nan, 0, -1, 0, 1},
                        {2, 0, nan, 0, 1},  {inf, 0, -1, 0, 1}, {2, 0, -inf, 0, 1}, {0, 0, 0, 0, 1},
                        {0, 0, 1, 0, 1},    {1e-30f, 0, -1, 0, 0}};
  for (const auto& c : cases) {
    check(c[0], c[1], c[2], c[3], c[4], noise, failures);
    check(c[0], c[1], c[2], c[3], c[4], T(0), failures);
  }
  CHECK(failures == 0);
}
