// Pure geometry: contact times against hand-computed cases, and the stable root against the textbook one
// (the accuracy study's, study/textbook_contact.hpp).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "core/geometry.hpp"
#include "core/rng.hpp"
#include "core/scalar_math.hpp"
#include "study/textbook_contact.hpp"

using namespace ede;

TEST_CASE("pair_contact_time: head-on, receding, missing, touching", "[geometry]") {
  // Centres 1 apart along x, closing at speed 2, contact at distance 0.5: t = (1 - 0.5) / 2.
  CHECK(pair_contact_time(1.0, 0.0, -2.0, 0.0, 0.5) == 0.25);
  // Receding: never.
  CHECK(pair_contact_time(1.0, 0.0, 2.0, 0.0, 0.5) == kNever<double>);
  // Moving sideways (b = 0): never.
  CHECK(pair_contact_time(1.0, 0.0, 0.0, 1.0, 0.5) == kNever<double>);
  // Passing at impact parameter 0.6 > 0.5: never.
  CHECK(pair_contact_time(1.0, 0.6, -1.0, 0.0, 0.5) == kNever<double>);
  // Overlapping by round-off while approaching: now.
  CHECK(pair_contact_time(0.5 - 1e-17, 0.0, -1.0, 0.0, 0.5) == 0.0);
  // Overlapping but separating: never (they are moving apart after a collision).
  CHECK(pair_contact_time(0.4999, 0.0, 1.0, 0.0, 0.5) == kNever<double>);
  // NaN velocities never produce an event.
  CHECK(pair_contact_time(1.0, 0.0, std::nan(""), 0.0, 0.5) == kNever<double>);
}

TEST_CASE("pair_contact_time: oblique impact matches the closed form", "[geometry]") {
  // Relative motion along -x at speed 1 with offset y = b: contact when x = sqrt(s^2 - b^2).
  const double s = 0.2, b = 0.12, x0 = 1.0;
  const double expected = x0 - std::sqrt(s * s - b * b);
  CHECK(pair_contact_time(x0, b, -1.0, 0.0, s) == Approx(expected).epsilon(1e-15));
}

TEST_CASE("pair_contact_time: the stable root is as accurate as its input allows", "[geometry]") {
  // Near contact, c = |dx|^2 - s^2 carries a relative rounding error of about eps |dx|^2 / c from the
  // inputs themselves; no formula can do better. The stable root stays within a small multiple of that
  // bound; the textbook root adds its own cancellation (-b - sqrt(d) with sqrt(d) ~ -b) on top, so its
  // median error is larger for head-on approaches. Reference: the same formula in long double.
  std::uint64_t state = 12345;
  const auto uniform = [&]() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  };
  const double eps = 0x1.0p-52;
  for (double gap : {1e-3, 1e-6, 1e-9, 1e-12}) {
    std::vector<double> stable_err, textbook_err;
    for (int k = 0; k < 500; ++k) {
      const double s = 0.5 + uniform(), angle = 2 * M_PI * uniform(), dist = s * (1 + gap * (0.5 + uniform()));
      const double dx = dist * std::cos(angle), dy = dist * std::sin(angle);
      const double toward = angle + M_PI + 0.3 * (uniform() - 0.5), speed = 0.1 + uniform();
      const double dvx = speed * std::cos(toward), dvy = speed * std::sin(toward);
      const long double ref = pair_contact_time<long double>(dx, dy, dvx, dvy, s);
      REQUIRE(ref < kNever<long double>);
      const long double c = (long double)dx * dx + (long double)dy * dy - (long double)s * s;
      const double bound = 16 * eps * double(((long double)dist * dist) / c) + 16 * eps;
      const double stable = pair_contact_time(dx, dy, dvx, dvy, s);
      REQUIRE(stable >= 0);
      stable_err.push_back(double(std::abs(stable - ref) / ref));
      textbook_err.push_back(double(std::abs(pair_contact_time_textbook(dx, dy, dvx, dvy, s) - ref) / ref));
      REQUIRE(stable_err.back() <= bound);
    }
    std::sort(stable_err.begin(), stable_err.end());
    std::sort(textbook_err.begin(), textbook_err.end());
    INFO("gap " << gap << ": median relative error stable " << stable_err[250] << ", textbook " << textbook_err[250]);
    CHECK(stable_err[250] < textbook_err[250]);
  }
}

TEST_CASE("pair_contact_time: grazing contacts", "[geometry]") {
  // Impact parameter just inside the contact distance: a (grazing) collision, at a time close to the
  // moment of closest approach; just outside: none.
  const double s = 0.2, x0 = 1.0;
  const double inside = pair_contact_time(x0, s * (1 - 1e-9), -1.0, 0.0, s);
  const double outside = pair_contact_time(x0, s * (1 + 1e-9), -1.0, 0.0, s);
  CHECK(inside == Approx(x0 - s * std::sqrt(2e-9)).epsilon(1e-6));
  CHECK(outside == kNever<double>);
}

// The neighbour scan's branch-free root must give exactly the branching root's bits for every input, or
// the logs would change: random pairs (approaching, receding, missing, overlapping), the boundaries of each
// test (b = 0, b^2 at the noise floor, c = 0, d = 0) and non-finite inputs, in float and double.
template <class T>
static void check_select_matches(T dx, T dy, T dvx, T dvy, T s, T noise, int& compared) {
  const T branching = pair_contact_time(dx, dy, dvx, dvy, s, noise);
  const T selected = pair_contact_time_select(dx, dy, dvx, dvy, s, noise);
  ++compared;
  if (std::memcmp(&branching, &selected, sizeof(T)) != 0) {
    FAIL_CHECK("dx " << dx << " dy " << dy << " dv " << dvx << " " << dvy << " s " << s << " noise " << noise
                     << ": " << branching << " vs " << selected);
  }
}

template <class T>
static void check_select_on_random_pairs() {
  Rng rng(20261126);
  int compared = 0;
  const T noises[] = {T(0), b_noise2_for(T(40)), T(1e-3)};
  for (int n = 0; n < 200000; ++n) {
    const T s = T(0.01 + rng.uniform01());
    const T dx = T(rng.uniform(-3, 3)), dy = T(rng.uniform(-3, 3));
    const T dvx = T(rng.uniform(-2, 2)), dvy = T(rng.uniform(-2, 2));
    check_select_matches(dx, dy, dvx, dvy, s, noises[n % 3], compared);
  }
  const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
  const T special[] = {T(0), T(-0.0), T(1), T(-1), T(0.5), T(-0.5), T(1e-30), T(-1e-30), inf, -inf, nan};
  for (const T dx : special)
    for (const T dy : special)
      for (const T dvx : special)
        for (const T dvy : special)
          for (const T noise : {T(0), T(0.25)}) check_select_matches(dx, dy, dvx, dvy, T(0.5), noise, compared);
  // b = 0 exactly (sideways), c = 0 exactly (touching), d = 0 exactly (grazing: dy = s, dvx = -1, dvy = 0),
  // and b^2 exactly at the floor (b = -1, a = 1: b^2 = noise * a for noise = 1).
  check_select_matches(T(1), T(0), T(0), T(1), T(0.5), T(0), compared);
  check_select_matches(T(0.5), T(0), T(-1), T(0), T(0.5), T(0), compared);
  check_select_matches(T(1), T(0.5), T(-1), T(0), T(0.5), T(0), compared);
  check_select_matches(T(1), T(0), T(-1), T(0), T(0.5), T(1), compared);
  check_select_matches(T(1), T(0), T(-1), T(0), T(0.5), std::nextafter(T(1), T(0)), compared);
  CHECK(compared == 200000 + 11 * 11 * 11 * 11 * 2 + 5);
}

TEST_CASE("pair_contact_time_select: the same bits as pair_contact_time", "[geometry]") {
  check_select_on_random_pairs<double>();
  check_select_on_random_pairs<float>();
}

TEST_CASE("select_value: picks a or b by the condition, bit for bit", "[geometry]") {
  CHECK(select_value(true, 1.5, -2.0) == 1.5);
  CHECK(select_value(false, 1.5, -2.0) == -2.0);
  CHECK(std::signbit(select_value(true, -0.0, 0.0)));
  CHECK(std::isnan(select_value(false, 1.0f, std::numeric_limits<float>::quiet_NaN())));
  CHECK(select_value(true, std::numeric_limits<double>::infinity(), 0.0) == std::numeric_limits<double>::infinity());
  CHECK(select_value(false, 3.0L, 4.0L) == 4.0L);
}

TEST_CASE("time_to_reach: towards, away, at rest, past the line", "[geometry]") {
  CHECK(time_to_reach(0.25, 0.5, 0.75) == 1.0);
  CHECK(time_to_reach(0.75, -0.5, 0.25) == 1.0);
  CHECK(time_to_reach(0.25, 0.0, 0.75) == kNever<double>);
  CHECK(time_to_reach(0.8, 0.5, 0.75) == 0.0);  // already past while moving on: now
}

TEST_CASE("time_to_reach_accelerated: falling, thrown up, bouncing, turning back", "[geometry][gravity]") {
  // Dropped from rest 0.5 above the floor under g = 1: t = sqrt(2 h / g) = 1.
  CHECK(time_to_reach_accelerated(0.5, 0.0, -1.0) == Approx(1.0).epsilon(1e-15));
  // Thrown towards the line at speed 1 with no acceleration: linear.
  CHECK(time_to_reach_accelerated(0.25, -1.0, 0.0) == 0.25);
  // Thrown away (up) at speed 1 under g = 1 from 0.5 above the floor: s(t) = 0.5 + t - t^2/2 = 0 at
  // t = 1 + sqrt(2).
  CHECK(time_to_reach_accelerated(0.5, 1.0, -1.0) == Approx(1 + std::sqrt(2.0)).epsilon(1e-15));
  // Just bounced off the floor (s = 0, moving up at 2, g = 1): back after 2 u / g = 4.
  CHECK(time_to_reach_accelerated(0.0, 2.0, -1.0) == 4.0);
  CHECK(time_to_reach_accelerated(-1e-17, 2.0, -1.0) == 4.0);
  // Towards a ceiling 1 above, thrown up at 1 under g = 1 (in s: u = -1, a = +1): it turns back at 0.5.
  CHECK(time_to_reach_accelerated(1.0, -1.0, 1.0) == kNever<double>);
  // ... thrown at 2 it reaches it: s = 1 - 2t + t^2/2 = 0 at t = 2 - sqrt(2).
  CHECK(time_to_reach_accelerated(1.0, -2.0, 1.0) == Approx(2 - std::sqrt(2.0)).epsilon(1e-15));
  // At the line and moving out, or at rest and pulled out: now.
  CHECK(time_to_reach_accelerated(0.0, -1.0, -1.0) == 0.0);
  CHECK(time_to_reach_accelerated(0.0, 0.0, -1.0) == 0.0);
  // At the line, moving in and pushed further in: never.
  CHECK(time_to_reach_accelerated(0.0, 1.0, 1.0) == kNever<double>);
  // At rest on the line and pushed inwards, or rising to touch it exactly: touched, never crossed.
  CHECK(time_to_reach_accelerated(0.0, 0.0, 1.0) == kNever<double>);
  CHECK(time_to_reach_accelerated(0.5, -1.0, 2.0) == kNever<double>);
  // A record from before a cell crossing: 0.1 below the line it has crossed since, rising at 1 under g = 1.
  // s(t) = -0.1 + t - t^2/2 falls back through 0 at t = 1 + sqrt(1 - 0.2) (the rise through 0 is earlier).
  CHECK(time_to_reach_accelerated(-0.1, 1.0, -1.0) == Approx(1 + std::sqrt(0.8)).epsilon(1e-15));
  // ... and without acceleration, or pushed away: it never crosses back; a record below, still falling: now.
  CHECK(time_to_reach_accelerated(-0.1, 1.0, 0.0) == kNever<double>);
  CHECK(time_to_reach_accelerated(-0.1, 1.0, 1.0) == kNever<double>);
  CHECK(time_to_reach_accelerated(-0.1, -1.0, -1.0) == 0.0);
  // Never reaching the line from inside: never; from outside (round-off): now.
  CHECK(time_to_reach_accelerated(1.0, -1.0, 1.0) == kNever<double>);
  CHECK(time_to_reach_accelerated(-1e-15, 0.0, 1.0) == kNever<double>);  // outside but pushed back in
  // Only crossings at or after t_min count: a record from t = 0 of a coordinate that rose through the line
  // at t = 0.15 and falls back through it at t = 1.045 (s = 0.0786 - 0.5976 t + t^2 / 2, seen from above:
  // a > 0). Asked at t_min = 1.045 (just entered below): the upward crossing is past, none is ahead.
  CHECK(time_to_reach_accelerated(0.0786, -0.5976, 1.0, 1.05) == kNever<double>);
  CHECK(time_to_reach_accelerated(0.0786, -0.5976, 1.0, 0.0) == Approx(0.5976 - std::sqrt(0.5976 * 0.5976 - 0.1572)).epsilon(1e-12));
  // A tiny gap closing fast: no cancellation (the answer is gap / speed to first order).
  CHECK(time_to_reach_accelerated(1e-12, -1.0, -1.0) == Approx(1e-12).epsilon(1e-9));
}
