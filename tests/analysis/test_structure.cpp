// Structure analyses (structure.hpp) on hand-made states, where the answer is exact: g(r) of perfect
// lattices, psi6 = 1 on a triangular lattice, the discrete Parseval sum rule and Bragg peaks of S(k), the
// walled normalisation of g(r) on an ideal gas (statistical: |g - 1| < 4 Poisson sigma per bin), and the
// contact-value fit on an exactly quadratic g.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "ede/structure.hpp"

using namespace ede;

namespace {

State empty_state(double lx, double ly, BoundaryKind b) {
  State s;
  s.lx = lx, s.ly = ly, s.boundary = b;
  s.species_names = {"disks"};
  return s;
}

State with(State s, const std::vector<double>& x, const std::vector<double>& y, double r = 0.01) {
  s.x = Column(x), s.y = Column(y);
  s.vx = Column(std::vector<double>(x.size(), 0)), s.vy = Column(std::vector<double>(x.size(), 0));
  s.radius = Column(std::vector<double>(x.size(), r)), s.mass = Column(std::vector<double>(x.size(), 1));
  s.species.assign(x.size(), 0);
  return s;
}

// M x M square lattice of spacing 1/M in the unit periodic box.
State square_lattice(int m) {
  std::vector<double> x, y;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) x.push_back((i + 0.5) / m), y.push_back((j + 0.5) / m);
  return with(empty_state(1, 1, BoundaryKind::Periodic), x, y);
}

// Triangular lattice of spacing a, M columns and M rows (M even): the box M a x M a sqrt(3)/2 holds it
// periodically without a seam.
State triangular_lattice(int m, double a) {
  std::vector<double> x, y;
  const double h = a * std::sqrt(3.0) / 2;
  for (int row = 0; row < m; ++row)
    for (int col = 0; col < m; ++col) x.push_back((col + 0.5 * (row % 2) + 0.25) * a), y.push_back((row + 0.5) * h);
  return with(empty_state(m * a, m * h, BoundaryKind::Periodic), x, y, 0.4 * a);
}

std::uint64_t splitmix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

TEST_CASE("g(r) of a square lattice: pairs at a, a sqrt(2), 2a and a sqrt(5) only, in exact numbers", "[analysis][structure]") {
  const int m = 10;
  const double a = 0.1;
  PairCorrelationOptions o;
  // Bins of 0.01 from 0.005, so that no lattice distance is near an edge: a in bin 9, a sqrt 2 in bin 13,
  // 2a in bin 19, a sqrt 5 (8 neighbours) in bin 21.
  o.r_min = 0.005, o.r_max = 0.245, o.bins = 24;
  const PairCorrelation g = pair_correlation(square_lattice(m), o).value();
  const double n = m * m;
  for (std::size_t k = 0; k < o.bins; ++k) {
    const double expected = (k == 9 || k == 13 || k == 19) ? 4 * n : k == 21 ? 8 * n : 0;
    INFO("bin " << k << " [" << g.r_lo[k] << ", " << g.r_hi[k] << ")");
    CHECK(g.count[k] == expected);
    // Ideal count: N (N - 1) / A^2 * pi A (r2^2 - r1^2), A = 1.
    const double ideal = n * (n - 1) * M_PI * (g.r_hi[k] * g.r_hi[k] - g.r_lo[k] * g.r_lo[k]);
    CHECK(g.ideal[k] == Approx(ideal).epsilon(1e-12));
    CHECK(g.g[k] == Approx(expected / ideal).epsilon(1e-12));
  }
  CHECK(a == Approx(0.5 * (g.r_lo[9] + g.r_hi[9])).epsilon(1e-12));
}

TEST_CASE("psi6 is 1 on every disk of a triangular lattice, and the lattice fits its periodic box", "[analysis][structure]") {
  const State s = triangular_lattice(12, 1.0);
  PairCorrelationOptions o;
  o.r_min = 0.05, o.r_max = 3.05, o.bins = 30;  // bins [0.05 + 0.1 k, 0.15 + 0.1 k): no distance at an edge
  const BondOrder b = bond_order(s, o).value();
  REQUIRE(b.psi6.size() == 144);
  for (const auto& v : b.psi6) {
    CHECK(std::real(v) == Approx(1).epsilon(1e-12));
    CHECK(std::abs(std::imag(v)) < 1e-12);
  }
  CHECK(b.global == Approx(1).epsilon(1e-12));
  CHECK(b.mean_local == Approx(1).epsilon(1e-12));
  // No seam: every disk has exactly 6 neighbours at a (bin 9), 6 at sqrt 3 (bin 16), 6 at 2 (bin 19), as
  // in the infinite lattice; g6 is 1 wherever there are pairs.
  CHECK(b.g6.count[9] == 6 * 144);
  CHECK(b.g6.count[16] == 6 * 144);
  CHECK(b.g6.count[19] == 6 * 144);
  CHECK(b.g6.count[12] == 0);
  for (std::size_t k = 0; k < o.bins; ++k)
    if (b.g6.count[k] > 0) CHECK(b.g6.g6[k] == Approx(1).epsilon(1e-12));
}

TEST_CASE("psi6 on a square lattice is at most 1/3: four-fold bonds have no six-fold component", "[analysis][structure]") {
  // The nearest six of a square-lattice site: the 4 at a (angles 0, 90, 180, 270 degrees: e^{6 i theta} =
  // 1, -1, 1, -1, summing to 0) and 2 of the 4 diagonals at a sqrt 2 (each +-i), chosen by id among equals:
  // |psi6| = |sum of two of +-i| / 6 <= 1/3.
  const auto p = psi6(square_lattice(8));
  for (const auto& v : p) CHECK(std::abs(v) <= 1.0 / 3 + 1e-12);
}

TEST_CASE("S(k) obeys the discrete Parseval sum rule for disks on a grid", "[analysis][structure]") {
  // Positions on distinct sites of an M x M grid (M = 7, odd): (1 / M^2) sum over the M^2 wave vectors
  // (p, q) in [-3, 3]^2 of N S(k) = sum over sites of (disks on the site)^2 = N. With S(0) = N and
  // S(k) = S(-k): (N + 2 sum over the half plane of S) / M^2 = 1 exactly.
  const int m = 7;
  std::uint64_t seed = 42;
  std::vector<int> site(m * m);
  for (int k = 0; k < m * m; ++k) site[k] = k;
  for (int k = m * m - 1; k > 0; --k) std::swap(site[k], site[splitmix(seed) % std::uint64_t(k + 1)]);
  std::vector<double> x, y;
  const int n = 20;
  for (int k = 0; k < n; ++k) x.push_back(double(site[k] % m) / m), y.push_back(double(site[k] / m) / m);
  const State s = with(empty_state(1, 1, BoundaryKind::Periodic), x, y);
  StructureFactorOptions o;
  o.k_max = 2 * M_PI * 3 * std::sqrt(2.0) * (1 + 1e-9);
  const StructureFactor f = structure_factor(s, o).value();
  double half = 0;
  std::size_t vectors = 0;
  for (std::size_t k = 0; k < f.s.size(); ++k) {
    const long p = std::lround(f.kx[k] / (2 * M_PI)), q = std::lround(f.ky[k] / (2 * M_PI));
    if (std::abs(p) <= 3 && std::abs(q) <= 3) half += f.s[k], ++vectors;
  }
  CHECK(vectors == 24);
  CHECK((n + 2 * half) / (m * m) == Approx(1).epsilon(1e-12));
}

TEST_CASE("S(k) of a triangular lattice: N at a reciprocal lattice vector, 0 between", "[analysis][structure]") {
  const int m = 12;
  const State s = triangular_lattice(m, 1.0);
  StructureFactorOptions o;
  o.k_max = 8;
  o.shells = 40;
  const StructureFactor f = structure_factor(s, o).value();
  bool found = false;
  for (std::size_t k = 0; k < f.s.size(); ++k) {
    const long p = std::lround(f.kx[k] * s.lx / (2 * M_PI)), q = std::lround(f.ky[k] * s.ly / (2 * M_PI));
    if (p == 0 && q == m) {  // b2 = (0, 4 pi / sqrt 3)
      found = true;
      CHECK(f.s[k] == Approx(144).epsilon(1e-9));
    }
    if (p == 1 && q == 0) CHECK(f.s[k] < 1e-20);                                       // not a lattice vector
  }
  CHECK(found);
}

TEST_CASE("g(r) with walls: an ideal gas filling the centres' rectangle gives g = 1 at every r", "[analysis][structure]") {
  // 40 independent configurations of 400 uniform points (overlaps allowed: an ideal gas) in
  // [r, Lx - r] x [r, Ly - r], Lx = 1.5, Ly = 1. The covariogram normalisation makes g = 1 up to r = 0.8;
  // the plain n 2 pi r dr one would read 1 - 2 r (Lx' + Ly') / (pi A') ~ 0.58 at r = 0.8. Tolerance: 4
  // standard errors of the mean over the configurations (pair counts of one configuration are correlated,
  // so Poisson errors would be too small), per bin.
  const double r = 0.01, lx = 1.5, ly = 1.0;
  const int configs = 40;
  std::uint64_t seed = 7;
  PairCorrelationOptions o;
  o.r_max = 0.8, o.bins = 8;
  std::vector<std::vector<double>> g_of(o.bins);
  PairCorrelation all;
  for (int c = 0; c < configs; ++c) {
    std::vector<double> x, y;
    for (int k = 0; k < 400; ++k) {
      x.push_back(r + (lx - 2 * r) * double(splitmix(seed) >> 11) * 0x1.0p-53);
      y.push_back(r + (ly - 2 * r) * double(splitmix(seed) >> 11) * 0x1.0p-53);
    }
    const State s = with(empty_state(lx, ly, BoundaryKind::Walls), x, y, r);
    const PairCorrelation g = pair_correlation(s, o).value();
    for (std::size_t k = 0; k < o.bins; ++k) g_of[k].push_back(g.g[k]);
    REQUIRE(add_pair_correlation(s, o, all));
  }
  finish_pair_correlation(all);
  CHECK(all.frames == std::size_t(configs));
  for (std::size_t k = 0; k < o.bins; ++k) {
    double mean = 0, ss = 0;
    for (const double v : g_of[k]) mean += v;
    mean /= configs;
    for (const double v : g_of[k]) ss += (v - mean) * (v - mean);
    const double se = std::sqrt(ss / (configs - 1) / configs);
    INFO("bin " << k << ": g = " << mean << " +- " << se);
    CHECK(std::fabs(mean - 1) < 4 * se);
    CHECK(all.g[k] == Approx(mean).epsilon(0.01));  // summed counts over summed ideal: the same average
  }
}

TEST_CASE("g(r) refuses r_max beyond half a periodic box and an unknown species", "[analysis][structure]") {
  const State s = square_lattice(4);
  PairCorrelationOptions o;
  o.r_max = 0.6;
  auto g = pair_correlation(s, o);
  REQUIRE(!g);
  CHECK_THAT(g.error().message, Catch::Contains("half the shorter side"));
  o.r_max = 0.4, o.species_a = 3;
  CHECK(!pair_correlation(s, o));
}

TEST_CASE("the contact value of an exactly quadratic g(r) is its intercept", "[analysis][structure]") {
  PairCorrelation g;
  for (int k = 0; k < 10; ++k) {
    const double x = 0.01 * k + 0.005;
    g.r_lo.push_back(1 + 0.01 * k), g.r_hi.push_back(1 + 0.01 * (k + 1));
    g.g.push_back(3 - 5 * x + 40 * x * x);
    g.count.push_back(1e4);
  }
  const ContactValue c = contact_from_gr(g, 1.0, 0.08).value();
  CHECK(c.value == Approx(3).epsilon(1e-12));  // a straight line through these bins gives 2.957
  CHECK(c.error > 0);
  CHECK(c.error < 0.1);
  CHECK(!contact_from_gr(g, 1.0, 0.035));  // three bins cannot show a quadratic's error
}

TEST_CASE("the Enskog and virial contact formulas invert their equations", "[analysis][structure]") {
  // omega = 2 n sigma g sqrt(pi kT / m) with n = 100, sigma = 0.01, g = 1.5, kT = 2, m = 3.
  const double omega = 2 * 100 * 0.01 * 1.5 * std::sqrt(M_PI * 2 / 3);
  CHECK(contact_from_collision_rate(omega, 10000, 100, 0.01, 2, 3).value == Approx(1.5).epsilon(1e-14));
  CHECK(contact_from_collision_rate(omega, 10000, 100, 0.01, 2, 3).error == Approx(0.015).epsilon(1e-12));
  const double z = 1 + M_PI / 2 * 100 * 1e-4 * 1.5;
  CHECK(contact_from_pressure(z, 0, 100, 0.01).value == Approx(1.5).epsilon(1e-12));
}
