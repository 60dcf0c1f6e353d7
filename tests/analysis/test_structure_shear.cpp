// g(r) of a sheared (Lees-Edwards) log: the state carries the images' offset as the run had it, and the
// pair count goes through the sliding image across the top and bottom edges (analysis/structure_cells.hpp),
// checked against every pair counted another way (the nearest of the nine images, each placed as the
// geometry says). Through the plain periodic image the same state has pairs closer than contact across the
// edge (the test shows the difference it makes); through the sliding one none. The run itself must end as
// it ran: the end-of-run overlap check (run/end_check.hpp) measured pairs across the edge through the plain
// image too and stopped this run as "overlapping" before it followed the sliding image.
#include <catch2/catch.hpp>
#include <cmath>

#include "ede/ede.hpp"
#include "tool_runner.hpp"  // temp_path

using namespace ede;

TEST_CASE("g(r) of a sheared log follows the sliding image", "[analysis][structure][shear]") {
  // 900 disks at packing 0.45 in a 30 x 30 box sheared fast (the images slide at 15): many contacts
  // across the top edge at every moment.
  const double l = 30, rate = 0.5, radius = std::sqrt(0.45 * l * l / (900 * M_PI));
  const std::string scene =
      "seed = 6\n[box]\nsize = [30.0, 30.0]\nboundary = \"lees-edwards\"\nshear_rate = 0.5\n[physics]\n"
      "restitution = 0.95\n[[species]]\nname = \"gas\"\ncount = 900\nradius = " + general_text(radius, 17) +
      "\n[species.placement]\nkind = \"lattice\"\n[species.velocity]\nkind = \"maxwell\"\ntemperature = 1.0\n"
      "[stop]\ntime = 3.0\n";
  const std::string path = test::temp_path("sheared-gr.ede");
  auto sim = Simulation::create(parse_scene_text(scene, "sheared-gr.toml").value(), {.log_path = path}).value();
  REQUIRE(sim.run() == RunStatus::ReachedTime);
  REQUIRE(sim.close());
  const Log log = Log::open(path).value();
  CHECK(log.info().shear_rate == rate);
  const double sigma = 2 * radius, r_max = 4 * sigma;
  PairCorrelationOptions o;
  o.r_max = r_max, o.bins = 80;
  for (const double t : {1.3, 2.9}) {
    const State s = log.state_at(t).value();
    INFO("t = " << t);
    CHECK(s.shear_offset == std::fmod(rate * l * double(s.time), l));  // the engine's rounding, in double
    const PairCorrelation g = pair_correlation(s, o).value();
    // Every pair by the nearest of its nine images: j's image in row k (k = -1, 0, 1) is at
    // (x_j + k offset + m l, y_j + k l), m = -1, 0, 1.
    std::vector<double> count(o.bins, 0);
    double closest = 1e300;
    for (std::size_t i = 0; i < s.size(); ++i)
      for (std::size_t j = i + 1; j < s.size(); ++j) {
        double best = 1e300;
        for (int k = -1; k <= 1; ++k)
          for (int m = -1; m <= 1; ++m) {
            const double dx = s.x[j] + k * s.shear_offset + m * l - s.x[i], dy = s.y[j] + k * l - s.y[i];
            best = std::min(best, dx * dx + dy * dy);
          }
        const double r = std::sqrt(best);
        closest = std::min(closest, r);
        if (r < r_max) count[std::size_t(r / (r_max / double(o.bins)))] += 2;  // ordered pairs
      }
    CHECK(closest > sigma * (1 - 1e-9));
    double total = 0;
    for (std::size_t b = 0; b < o.bins; ++b) {
      INFO("bin " << b);
      CHECK(g.count[b] == count[b]);
      total += count[b];
    }
    CHECK(total > 5000);
    // Through the plain image the edge's pairs land elsewhere, some closer than contact.
    State plain = s;
    plain.shear_offset = 0;
    const PairCorrelation p = pair_correlation(plain, o).value();
    double below_contact = 0;
    for (std::size_t b = 0; b < o.bins; ++b)
      if (p.r_hi[b] < sigma * (1 - 1e-9)) below_contact += p.count[b];
    CHECK(below_contact > 0);
  }
}
