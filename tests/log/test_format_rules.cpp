// The format owns its arithmetic (issue 33): format version 2's predictors and state update live in
// libede/src/log/rules/, written from schema/FORMAT.md, and the engine keeps its own functions. Two things
// are checked here:
//   1. the floors: nothing in libede/src/log/ includes the engine, and the rules include only the standard
//      library and each other, so nothing done to the engine or core can change what an old log decodes to;
//   2. where the engine's functions and the format's give the same bits. For the state update this is what
//      makes a log exact at all (positions are never stored: replay's must be the engine's), so it must hold
//      for every input; for the collision rules and contact times it is what makes an ordinary run's
//      residuals 0 (a log stays exact either way, only larger). When the engine's arithmetic changes on
//      purpose (a faster root, say), the failing comparison says which predictor no longer follows it: a
//      new format version with a new predictor, or accept larger logs; never edit log/rules/ in place.
// Inputs: random values over many scales with the special values mixed in (±0, subnormals, huge values,
// ±inf, NaN), in float, double and long double; bits compared exactly (every NaN alike: same_bits).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <string>

#include "core/drift.hpp"
#include "core/geometry.hpp"
#include "core/particles.hpp"
#include "core/segment.hpp"
#include "core/state_update.hpp"
#include "engine/collide.hpp"
#include "log/rules/collisions_v2.hpp"
#include "log/rules/geometry_v2.hpp"
#include "log/rules/state_update.hpp"

using namespace ede;

namespace {

// The bits of a scalar (a long double's 10 significant bytes); any NaN equals any NaN. A NaN's sign and
// payload come from whichever operand the compiler puts first in a commutative operation, which it may
// choose differently in each place it inlines a function; no log holds a NaN (a run stops at its first
// non-finite value, run/finite_guard.hpp), so they are never coded against.
template <class T>
bool same_bits(T a, T b) {
  if (a != a && b != b) return true;
  constexpr std::size_t n = sizeof(T) == 4 ? 4 : sizeof(T) == 8 ? 8 : 10;
  return std::memcmp(&a, &b, n) == 0;
}

// Values over many scales, with the special values mixed in.
template <class T>
class Inputs {
 public:
  explicit Inputs(std::uint64_t seed) : state_(seed) {}
  T any() {
    const std::uint64_t r = next();
    switch (r % 16) {
      case 0: return special(r >> 8);
      case 1: return T(std::ldexp(double(unit()) - 0.5, int(r >> 8) % 200 - 100));
      default: return T(4 * unit() - 2);
    }
  }
  T positive() {
    T v = any();
    if (v != v) return v;
    return v < 0 ? -v : v;
  }
  T unit() { return T(double(next() >> 11) * 0x1.0p-53); }

 private:
  static T special(std::uint64_t k) {
    using L = std::numeric_limits<T>;
    const T values[] = {T(0), -T(0), L::denorm_min(), L::min(), L::max(), -L::max(), L::infinity(),
                        -L::infinity(), L::quiet_NaN(), L::epsilon(), T(1), T(-1), T(0.5)};
    return values[k % (sizeof values / sizeof values[0])];
  }
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t state_;
};

constexpr int kTrials = 200000;

template <class T>
Disk<T> random_disk(Inputs<T>& in) {
  Disk<T> d{};
  d.x = in.any(), d.y = in.any(), d.vx = in.any(), d.vy = in.any(), d.t = in.any(), d.r = in.positive();
  return d;
}

template <class T>
bool same_record(const Disk<T>& a, const Disk<T>& b) {
  return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.vx, b.vx) && same_bits(a.vy, b.vy) &&
         same_bits(a.t, b.t);
}

template <class T>
void check_state_update() {
  Inputs<T> in(1);
  int differ = 0;
  for (int k = 0; k < kTrials; ++k) {
    const Disk<T> d = random_disk(in);
    const T t = in.any(), gx = k % 3 == 0 ? T(0) : in.any(), gy = k % 5 == 0 ? T(0) : in.any();
    const std::int32_t dir = std::int32_t(k % 4);
    const T lx = in.positive(), ly = in.positive();
    Disk<T> e = d, f = d;
    advance_disk(e, t, gx, gy);
    rules::bring_to(f, t, gx, gy);
    differ += !same_record(e, f);
    e = d, f = d;
    advance_disk(e, t);
    rules::bring_to(f, t, T(0), T(0));
    differ += !same_record(e, f);
    e = d, f = d;
    wrap_disk(e, t, dir, lx, ly);
    rules::wrap(f, t, dir, lx, ly);
    differ += !same_record(e, f);
    e = d, f = d;
    reverse_disk(e, t, gx, gy);
    rules::reverse(f, t, gx, gy);
    differ += !same_record(e, f);
  }
  CHECK(differ == 0);
}

template <class T>
void check_times() {
  Inputs<T> in(2);
  int differ = 0;
  for (int k = 0; k < kTrials; ++k) {
    const T dx = in.any(), dy = in.any(), dvx = in.any(), dvy = in.any(), s = in.positive();
    const T lx = in.positive(), ly = in.positive();
    const T beta = k % 4 == 0 ? T(0) : rules::v2::noise_floor2(lx, ly);
    differ += !same_bits(b_noise2_for(std::max(lx, ly)), rules::v2::noise_floor2(lx, ly));
    differ += !same_bits(pair_contact_time(dx, dy, dvx, dvy, s, beta), rules::v2::contact_time(dx, dy, dvx, dvy, s, beta));
    differ += !same_bits(time_to_reach(dx, dvx, dy), rules::v2::reach(dx, dvx, dy));
    differ += !same_bits(time_to_reach_accelerated(dx, dvx, dvy, T(0)), rules::v2::reach_accelerated(dx, dvx, dvy));
  }
  CHECK(differ == 0);
}

template <class T>
void check_segments() {
  Inputs<T> in(3);
  int differ = 0;
  for (int k = 0; k < kTrials; ++k) {
    const T ax = in.any(), ay = in.any(), bx = in.any(), by = in.any(), xi = in.unit();
    const Segment<T> e = make_segment(ax, ay, bx, by, xi);
    const rules::v2::Segment<T> f = rules::v2::make_segment(ax, ay, bx, by, xi);
    differ += !(same_bits(e.ux, f.ux) && same_bits(e.uy, f.uy) && same_bits(e.nx, f.nx) && same_bits(e.ny, f.ny) &&
                same_bits(e.length, f.length) && same_bits(e.one_plus_xi, f.one_plus_xi));
    const T x = in.any(), y = in.any(), vx = in.any(), vy = in.any(), r = in.positive(), beta = in.positive();
    differ += !same_bits(segment_contact_time(e, x, y, vx, vy, r, beta),
                         rules::v2::segment_contact_time(f, x, y, vx, vy, r, beta));
    T evx = vx, evy = vy, fvx = vx, fvy = vy;
    const T k2 = k % 2 ? T(2) : e.one_plus_xi;
    collide_segment(e, x, y, k2, evx, evy);
    rules::v2::segment_rule(f, x, y, k2, fvx, fvy);
    differ += !(same_bits(evx, fvx) && same_bits(evy, fvy));
  }
  CHECK(differ == 0);
}

template <class T>
void check_collisions() {
  Inputs<T> in(4);
  int differ = 0;
  for (int k = 0; k < kTrials; ++k) {
    const T dx = in.any(), dy = in.any(), mi = in.positive(), mj = in.positive(), one_plus_xi = 1 + in.unit();
    T e[4] = {in.any(), in.any(), in.any(), in.any()};
    T f[4] = {e[0], e[1], e[2], e[3]};
    collide_pair(dx, dy, mi, mj, one_plus_xi, e[0], e[1], e[2], e[3]);
    rules::v2::pair_rule(dx, dy, mi, mj, one_plus_xi, f[0], f[1], f[2], f[3]);
    for (int c = 0; c < 4; ++c) differ += !same_bits(e[c], f[c]);

    const T ri = in.positive(), rj = in.positive(), ii = in.positive(), ij = in.positive();
    const T k_b = k % 3 == 0 ? T(0) : 2 * in.unit(), dvx = in.any(), dvy = in.any();
    T ew[2] = {in.any(), in.any()}, fw[2] = {ew[0], ew[1]};
    collide_pair_tangential(dx, dy, dvx, dvy, mi, mj, ri, rj, ii, ij, k_b, e[0], e[1], e[2], e[3], ew[0], ew[1]);
    rules::v2::pair_rule_tangential(dx, dy, dvx, dvy, mi, mj, ri, rj, ii, ij, k_b, f[0], f[1], f[2], f[3], fw[0], fw[1]);
    for (int c = 0; c < 4; ++c) differ += !same_bits(e[c], f[c]);
    differ += !(same_bits(ew[0], fw[0]) && same_bits(ew[1], fw[1]));

    const std::int32_t wall = std::int32_t(k % 4);
    const bool vertical = wall == kWallLeft || wall == kWallRight, tc = k % 7 == 0;
    const T xi = in.unit(), vx0 = in.any(), vy0 = in.any();
    T evx = vx0, evy = vy0, fvx = vx0, fvy = vy0;
    if (tc)
      collide_wall_elastic(vertical, evx, evy);
    else
      collide_wall(vertical, xi, evx, evy);
    rules::v2::wall_rule(wall, tc, xi, fvx, fvy);
    differ += !(same_bits(evx, fvx) && same_bits(evy, fvy));
    static constexpr int kNormal[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};  // Engine::kWallNormal
    T eww = ew[0], fww = ew[0];
    collide_wall_tangential(T(kNormal[wall][0]), T(kNormal[wall][1]), vx0, vy0, mi, ri, ii, k_b, evx, evy, eww);
    rules::v2::wall_rule_tangential(wall, vx0, vy0, mi, ri, ii, k_b, fvx, fvy, fww);
    differ += !(same_bits(evx, fvx) && same_bits(evy, fvy) && same_bits(eww, fww));
  }
  CHECK(differ == 0);
}

// The files under `dir` and the quoted includes in each.
template <class F>
void for_each_include(const std::filesystem::path& dir, F&& f) {
  const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path());
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
      if (std::regex_search(line, m, include)) f(entry.path(), m[1].str());
  }
}

}  // namespace

TEST_CASE("the engine's state update is the format's, bit for bit", "[log][format_rules]") {
  check_state_update<float>();
  check_state_update<double>();
  check_state_update<long double>();
}

TEST_CASE("the engine's contact and wall times are format version 2's predictors", "[log][format_rules]") {
  check_times<float>();
  check_times<double>();
  check_times<long double>();
}

TEST_CASE("the engine's segments and their rule are format version 2's", "[log][format_rules]") {
  check_segments<float>();
  check_segments<double>();
  check_segments<long double>();
}

TEST_CASE("the engine's collision rules are format version 2's predictors", "[log][format_rules]") {
  check_collisions<float>();
  check_collisions<double>();
  check_collisions<long double>();
}

TEST_CASE("the log includes nothing of the engine, and the format's rules only the standard library", "[log][format_rules]") {
  const std::filesystem::path src = std::filesystem::path(EDE_SOURCE_DIR) / "libede" / "src";
  int checked = 0;
  for_each_include(src / "log", [&](const std::filesystem::path& file, const std::string& included) {
    ++checked;
    INFO(file.string() << " includes " << included);
    CHECK(included.rfind("engine/", 0) != 0);
    if (file.parent_path().filename() == "rules") CHECK(included.rfind("log/rules/", 0) == 0);
  });
  CHECK(checked > 50);  // the walk found the log's files
}
