// Particles<T>: masses and species stored once when every disk has the same, per disk otherwise; and what
// that leaves of the engine's memory per disk (issue 15: at most 120 B/disk in double).
#include <catch2/catch.hpp>
#include <cmath>

#include "core/particles.hpp"
#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

TEST_CASE("one mass and one species are stored once, and read the same for every disk", "[particles]") {
  Particles<double> p;
  p.disk.resize(5);
  p.set_masses(std::vector<double>(5, 2.5));
  p.set_species(std::vector<std::int32_t>(5, 3));
  CHECK(p.masses.size() == 1);
  CHECK(p.species_ids.size() == 1);
  for (std::size_t i = 0; i < 5; ++i) {
    CHECK(p.mass(i) == 2.5);
    CHECK(p.species_of(i) == 3);
  }
  CHECK(p.mass_column() == std::vector<double>(5, 2.5));
  CHECK(p.species_column() == std::vector<std::int32_t>(5, 3));
}

TEST_CASE("differing masses or species are stored per disk", "[particles]") {
  Particles<double> p;
  p.disk.resize(4);
  const std::vector<double> m{1, 1, 1, 4};  // one differs, at the end: all_of must look at every disk
  const std::vector<std::int32_t> s{0, 1, 0, 0};
  p.set_masses(m);
  p.set_species(s);
  CHECK(p.masses == m);
  CHECK(p.species_ids == s);
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(p.mass(i) == m[i]);
    CHECK(p.species_of(i) == s[i]);
  }
  CHECK(p.mass_column() == m);
}

TEST_CASE("a one-disk state keeps its one value", "[particles]") {
  Particles<double> p;
  p.disk.resize(1);
  p.set_masses({7.0});
  CHECK(p.mass(0) == 7.0);
  CHECK(p.mass_column() == std::vector<double>{7.0});
}

TEST_CASE("the engine stays within 120 bytes per disk at phi = 0.3 and 0.5", "[particles][memory]") {
  // 10^4 disks on a unit periodic box; phi = N pi r^2. The dilute gas has more grid cells per disk (cells
  // are at least a diameter wide): 2.6 at phi = 0.3 against 1.6 at 0.5.
  for (const double phi : {0.3, 0.5}) {
    const double r = std::sqrt(phi / (M_PI * 1e4));
    const InitialState s = lattice_gas(100, r, 1.0, 7);
    EngineOptions o;
    o.boundary = BoundaryKind::Periodic;
    o.stop.events = 1000;
    auto e = engine(s, o);
    REQUIRE(e->run() == RunStatus::ReachedEvents);
    INFO("phi = " << phi);
    CHECK(double(e->memory_bytes()) / double(s.size()) <= 120.0);
  }
}

TEST_CASE("a two-mass gas keeps a mass per disk and runs as before", "[particles][memory]") {
  InitialState s = lattice_gas(10, 0.01, 1.0, 3);
  for (std::size_t i = 0; i < s.size(); i += 2) s.mass[i] = 4.0;
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o.stop.events = 2000;
  auto e = engine(s, o);
  REQUIRE(e->run() == RunStatus::ReachedEvents);
  REQUIRE(e->particles().masses.size() == s.size());
  for (std::size_t i = 0; i < s.size(); ++i) CHECK(e->particles().mass(i) == s.mass[i]);
}
