// Effusion through a hole in a divider (examples/effusion.toml, smaller) against kinetic theory: a
// statistical test with a stated tolerance.
//
// Theory (docs/examples.md, "Effusion"): disks cross a line at n <|v|> / pi per unit length and time in
// 2D, <|v|> = sqrt(pi kT / 2m); a disk of radius r gets through a hole of width w when its centre clears
// both end points by r, which averaged over the crossing angle leaves w_eff = w - pi r. Two halves of area
// A then fill as N_right(t) = N/2 (1 - exp(-t / tau)), tau = pi A / (2 w_eff <|v|>). The hole (0.05) is
// small against the mean free path (0.35), as effusion needs.
// Tolerance: the count is a sum of nearly independent crossings, so its noise is about Poisson; crossings
// back to the left add to it, so we allow 4 sqrt(1.5 E) for the expected total E over eight seeds
// (~2600 crossings: 8 % of E).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "ede/scene.hpp"
#include "ede/simulation.hpp"
#include "scene_test_support.hpp"

TEST_CASE("segment effusion: the rate through a small hole matches kinetic theory", "[segment][statistical][slow]") {
  const double hole = 0.05, r = 0.0005, area = 1.0, t_end = 10.0;
  ede::test::GasToml gas = ede::test::left_half_gas("2000", "0.0005");
  gas.seed = "", gas.stop = "time = 10.0";
  const std::string text = gas.text() + ede::test::divider_toml("0.475", "0.525");
  double measured = 0, expected = 0;
  for (int seed = 1; seed <= 8; ++seed) {
    auto sim = ede::Simulation::create(ede::test::scene_of(text, "effusion.toml", {{"seed=" + std::to_string(seed)}}));
    REQUIRE(sim.ok());
    REQUIRE(sim.value().run() == ede::RunStatus::ReachedTime);
    const ede::State s = sim.value().state();
    double energy = 0;
    int right = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      energy += 0.5 * s.mass[i] * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
      right += s.x[i] > 1.0;
    }
    const double n = double(s.size()), kt = energy / n;
    const double mean_speed = std::sqrt(M_PI * kt / 2), w_eff = hole - M_PI * r;
    const double tau = M_PI * area / (2 * w_eff * mean_speed);
    measured += right;
    expected += n / 2 * (1 - std::exp(-t_end / tau));
  }
  const double tolerance = 4 * std::sqrt(1.5 * expected);
  INFO("measured " << measured << ", kinetic theory " << expected << " +- " << tolerance);
  CHECK(std::abs(measured - expected) < tolerance);
}
