// run/end_check.hpp: what the end of a run must show before it may be reported as done. Hand-made
// particles in each scalar type: overlaps beyond the round-off (walls, periodic images, a large disk among
// small ones), "no more events" while a disk moves, a clock that no longer resolves the disks, and the runs
// that pass (touching disks, disks at rest).
#include <catch2/catch.hpp>

#include "text_support.hpp"

#include "run/end_check.hpp"

namespace {

template <class T>
ede::Particles<T> particles(const std::vector<std::array<double, 5>>& disks) {  // x, y, vx, vy, r
  ede::Particles<T> p;
  for (const auto& d : disks) {
    ede::Disk<T> k{};
    k.x = T(d[0]), k.y = T(d[1]), k.vx = T(d[2]), k.vy = T(d[3]), k.r = T(d[4]), k.t = T(0);
    p.disk.push_back(k);
  }
  p.set_masses(std::vector<T>(disks.size(), T(1)));
  p.set_species(std::vector<std::int32_t>(disks.size(), 0));
  return p;
}

template <class T>
ede::EndCheckContext context(bool periodic = false) {
  ede::EndCheckContext c;
  c.source = "scene.toml";
  c.scalar = std::is_same_v<T, float> ? ede::ScalarKind::Float
             : std::is_same_v<T, double> ? ede::ScalarKind::Double
                                         : ede::ScalarKind::LongDouble;
  c.periodic = periodic;
  return c;
}


}  // namespace

TEMPLATE_TEST_CASE("the end check passes disks apart, touching or at rest", "[run][end_check]", float, double,
                   long double) {
  using T = TestType;
  const auto p = particles<T>({{0.3, 0.5, 1, 0, 0.1}, {0.5, 0.5, -1, 0, 0.1}, {0.8, 0.8, 0, 0, 0.05}});
  CHECK(ede::end_of_run_problem(p, T(0), ede::RunStatus::ReachedTime, context<T>()).empty());  // touching
  const auto rest = particles<T>({{0.3, 0.5, 0, 0, 0.1}, {0.7, 0.5, 0, 0, 0.1}});
  CHECK(ede::end_of_run_problem(rest, T(1), ede::RunStatus::NoMoreEvents, context<T>()).empty());
}

TEMPLATE_TEST_CASE("the end check finds an overlap beyond the round-off and names it", "[run][end_check]", float,
                   double, long double) {
  using T = TestType;
  // Disks 1 and 2 overlap by 10 % of their contact distance; disk 0 is far from both.
  const auto p = particles<T>({{0.1, 0.1, 0, 0, 0.05}, {0.5, 0.5, 1, 0, 0.1}, {0.68, 0.5, -1, 0, 0.1}});
  const std::string m = ede::end_of_run_problem(p, T(0), ede::RunStatus::ReachedTime, context<T>());
  CHECK(contains(m, "disks 1 and 2 overlap at the end"));
  CHECK(contains(m, "by 0.1 of their contact distance"));
  CHECK(contains(m, "Fix:"));
  // The same pair 1e-9 of the contact distance deep: within double's and long double's round-off at L = 1
  // (16 eps L = 3.6e-15 in double is far below it, so double flags it; float's 1.9e-6 does not).
  const auto shallow = particles<T>({{0.5, 0.5, 0, 0, 0.1}, {0.5 + 0.2 * (1 - 1e-9), 0.5, 0, 0, 0.1}});
  const bool flagged = !ede::end_of_run_problem(shallow, T(0), ede::RunStatus::ReachedTime, context<T>()).empty();
  CHECK(flagged == !std::is_same_v<T, float>);
}

TEMPLATE_TEST_CASE("the end check sees overlaps across a periodic edge and of a large disk", "[run][end_check]",
                   float, double) {
  using T = TestType;
  // Across the edge x = 0 / 1: centres 0.16 apart through the boundary, contact 0.2.
  const auto wrap = particles<T>({{0.02, 0.5, 0, 0, 0.1}, {0.86, 0.5, 0, 0, 0.1}, {0.5, 0.1, 0, 0, 0.05}});
  CHECK(contains(ede::end_of_run_problem(wrap, T(0), ede::RunStatus::ReachedTime, context<T>(true)),
                 "disks 0 and 1 overlap"));
  // A large disk (radius 0.3) among many small ones: the one it covers is found from the large disk's side.
  std::vector<std::array<double, 5>> d;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) d.push_back({0.05 + 0.1 * i, 0.05 + 0.1 * j, 0, 0, 0.01});
  d.push_back({0.5, 0.5, 0, 0, 0.04});  // centred on a gap: touches no small disk (gap radius ~0.0707 - 0.01)
  CHECK(ede::end_of_run_problem(particles<T>(d), T(0), ede::RunStatus::ReachedTime, context<T>()).empty());
  d.back()[4] = 0.3;
  const std::string m = ede::end_of_run_problem(particles<T>(d), T(0), ede::RunStatus::ReachedTime, context<T>());
  CHECK(contains(m, "overlap at the end"));
  CHECK(contains(m, "other overlapping pairs too"));
}

TEMPLATE_TEST_CASE("no more events while a disk moves is an overflowed clock, not rest", "[run][end_check]", float,
                   double) {
  using T = TestType;
  const auto p = particles<T>({{0.3, 0.5, 0, 0, 0.1}, {0.7, 0.5, 0, 1e-30, 0.1}});
  const std::string m = ede::end_of_run_problem(p, T(1), ede::RunStatus::NoMoreEvents, context<T>());
  CHECK(contains(m, "no event left"));
  CHECK(contains(m, "disk 1 still moves"));
  // Stalled, collapsed and non-finite runs already stop with their own message: nothing added.
  CHECK(ede::end_of_run_problem(p, T(1), ede::RunStatus::Stalled, context<T>()).empty());
  CHECK(ede::end_of_run_problem(p, T(1), ede::RunStatus::NonFinite, context<T>()).empty());
}

TEST_CASE("a float clock that no longer resolves the disks ends the run as inexact", "[run][end_check]") {
  // eps (L + 2 V t) at t = 1e5, V = 1: 1.2e-7 * 2e5 = 0.024 > 0.2 / 64.
  const auto p = particles<float>({{0.3, 0.5, 1, 0, 0.1}, {0.7, 0.5, 0, 0, 0.1}});
  const std::string m = ede::end_of_run_problem(p, 1e5f, ede::RunStatus::ReachedTime, context<float>());
  CHECK(contains(m, "no longer tells the disks' positions apart"));
  // The same in double is resolved: 2.2e-16 * 2e5 = 4.4e-11.
  const auto q = particles<double>({{0.3, 0.5, 1, 0, 0.1}, {0.7, 0.5, 0, 0, 0.1}});
  CHECK(ede::end_of_run_problem(q, 1e5, ede::RunStatus::ReachedTime, context<double>()).empty());
}
