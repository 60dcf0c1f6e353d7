// Setup: determinism, per-species independence, placement (random, lattice, explicit), radii from a
// packing fraction, masses, velocity rules, and check_initial_state's refusals with their messages.
//
// Scenes are built as C++ structs (no TOML). Overlap and containment of small placements are checked by
// an all-pairs loop written here, independent of the grid that setup and check_initial_state share.
// Statistical checks use fixed seeds and 5-sigma tolerances.
#include <catch2/catch.hpp>

#include "text_support.hpp"
#include <cmath>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "setup/setup.hpp"

using namespace ede;

namespace {

constexpr double kPi = 3.14159265358979323846;

SpeciesSpec random_species(const std::string& name, std::int64_t count, double r_min, double r_max) {
  SpeciesSpec s;
  s.name = name;
  s.count = count;
  s.radius.min = r_min;
  s.radius.max = r_max;
  s.velocity.kind = VelocityKind::Maxwell;
  s.velocity.temperature = 1;
  return s;
}

SpeciesSpec packed_species(const std::string& name, std::int64_t count, double phi, PlacementKind kind) {
  SpeciesSpec s;
  s.name = name;
  s.count = count;
  s.radius.from_packing = true;
  s.placement.kind = kind;
  s.placement.packing_fraction = phi;
  return s;
}

Scene scene_of(std::vector<SpeciesSpec> species, BoundaryKind boundary = BoundaryKind::Walls,
               std::uint64_t seed = 1) {
  Scene scene;
  scene.source_name = "test.toml";
  scene.seed = seed;
  scene.boundary = boundary;
  scene.species = std::move(species);
  return scene;
}

InitialState build_ok(const Scene& scene) {
  Result<InitialState> r = build_initial_state(scene);
  if (!r) FAIL(r.error().message);
  return std::move(r).value();
}

std::string build_error(const Scene& scene) {
  Result<InitialState> r = build_initial_state(scene);
  REQUIRE_FALSE(r.ok());
  return r.error().message;
}

double min_image(double d, double length, bool periodic) {
  if (!periodic) return d;
  return d - length * std::round(d / length);
}

// The number of overlapping pairs, all pairs compared (an oracle independent of the grid).
int brute_force_overlaps(const InitialState& s, bool periodic) {
  int pairs = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const double dx = min_image(s.x[j] - s.x[i], s.lx, periodic);
      const double dy = min_image(s.y[j] - s.y[i], s.ly, periodic);
      const double c = s.radius[i] + s.radius[j];
      if (dx * dx + dy * dy < c * c) ++pairs;
    }
  }
  return pairs;
}

// Whether every disk of the species lies wholly in the region (or, along a wrapped dimension, in [0, L)).
bool inside_region(const InitialState& s, std::int32_t species, const Region& g, bool wrap_x, bool wrap_y) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.species[i] != species) continue;
    const double x = s.x[i], y = s.y[i], r = s.radius[i];
    const bool in_x = wrap_x ? (x >= 0 && x < s.lx) : (x - r >= g.x0 && x + r <= g.x1);
    const bool in_y = wrap_y ? (y >= 0 && y < s.ly) : (y - r >= g.y0 && y + r <= g.y1);
    if (!in_x || !in_y) return false;
  }
  return true;
}

double packing_fraction(const InitialState& s, std::int32_t species, double area) {
  double sum = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.species[i] == species) sum += kPi * s.radius[i] * s.radius[i];
  }
  return sum / area;
}


}  // namespace

TEST_CASE("setup is deterministic: same seed, same bits, another seed, other disks", "[setup]") {
  auto make = [](std::uint64_t seed) {
    SpeciesSpec gas = random_species("gas", 500, 0.005, 0.01);
    SpeciesSpec fast = random_species("fast", 20, 0.02, 0.02);
    fast.velocity.kind = VelocityKind::Speed;
    fast.velocity.speed = 3;
    return scene_of({gas, fast}, BoundaryKind::Periodic, seed);
  };
  const InitialState a = build_ok(make(7)), b = build_ok(make(7)), c = build_ok(make(8));
  CHECK(a.x == b.x);  // vector<double> ==: element by element, exact
  CHECK(a.y == b.y);
  CHECK(a.vx == b.vx);
  CHECK(a.vy == b.vy);
  CHECK(a.radius == b.radius);
  CHECK(a.mass == b.mass);
  CHECK(a.species == b.species);
  CHECK(a.x != c.x);
  CHECK(a.vx != c.vx);
}

TEST_CASE("species are contiguous, in scene order, with their names and the box", "[setup]") {
  Scene scene = scene_of({random_species("a", 30, 0.01, 0.01), random_species("b", 0, 0.01, 0.01),
                          random_species("c", 12, 0.02, 0.03)});
  scene.lx = 2;
  scene.ly = 3;
  for (auto& s : scene.species) s.placement.region = {0, 0, 2, 3};
  const InitialState s = build_ok(scene);
  REQUIRE(s.size() == 42);
  CHECK(s.lx == 2);
  CHECK(s.ly == 3);
  CHECK(s.species_names == std::vector<std::string>{"a", "b", "c"});
  for (std::size_t i = 0; i < s.size(); ++i) CHECK(s.species[i] == (i < 30 ? 0 : 2));
}

TEST_CASE("adding a species leaves the disks of the earlier ones unchanged", "[setup]") {
  SpeciesSpec gas = random_species("gas", 400, 0.004, 0.012);  // polydisperse: radii drawn, then sorted
  gas.placement.region = {0, 0, 1, 0.8};                       // periodic box: wraps in x only
  // The new species have larger disks (a coarser placement grid) and come after, random and explicit.
  SpeciesSpec big = random_species("big", 5, 0.05, 0.05);
  SpeciesSpec probe = random_species("probe", 1, 0.001, 0.001);
  probe.placement.kind = PlacementKind::Explicit;
  probe.placement.positions = {{0.5, 0.999}};
  probe.velocity.kind = VelocityKind::Vector;
  probe.velocity.vector = {0, -5};
  for (BoundaryKind boundary : {BoundaryKind::Walls, BoundaryKind::Periodic}) {
    const InitialState one = build_ok(scene_of({gas}, boundary, 3));
    const InitialState three = build_ok(scene_of({gas, big, probe}, boundary, 3));
    REQUIRE(three.size() == 406);
    for (std::size_t i = 0; i < one.size(); ++i) {
      INFO("disk " << i);
      CHECK(three.x[i] == one.x[i]);
      CHECK(three.y[i] == one.y[i]);
      CHECK(three.vx[i] == one.vx[i]);
      CHECK(three.vy[i] == one.vy[i]);
      CHECK(three.radius[i] == one.radius[i]);
    }
  }
}

TEST_CASE("random placement: no overlaps, every disk inside its region", "[setup][placement]") {
  struct Case {
    std::int64_t count;
    double r_min, r_max;
    Region region;
    BoundaryKind boundary;
  };
  const Case cases[] = {
      {1, 0.1, 0.1, {0, 0, 1, 1}, BoundaryKind::Walls},
      {10, 0.05, 0.05, {0, 0, 1, 1}, BoundaryKind::Walls},
      {1000, 0.01, 0.01, {0, 0, 1, 1}, BoundaryKind::Walls},
      {1000, 0.01, 0.01, {0, 0, 1, 1}, BoundaryKind::Periodic},
      {1500, 0.002, 0.015, {0, 0, 1, 1}, BoundaryKind::Periodic},  // polydisperse
      {1500, 0.002, 0.015, {0, 0, 1, 1}, BoundaryKind::Walls},
      {400, 0.008, 0.008, {0.2, 0.1, 0.7, 0.5}, BoundaryKind::Walls},  // a region inside the box
      {400, 0.008, 0.008, {0.2, 0.1, 0.7, 0.5}, BoundaryKind::Periodic},
      {600, 0.008, 0.008, {0, 0.3, 1, 0.6}, BoundaryKind::Periodic},  // a band: wraps in x only
  };
  for (const Case& c : cases) {
    SpeciesSpec s = random_species("gas", c.count, c.r_min, c.r_max);
    s.placement.region = c.region;
    const bool periodic = c.boundary == BoundaryKind::Periodic;
    const InitialState state = build_ok(scene_of({s}, c.boundary));
    INFO("count " << c.count << ", radii " << c.r_min << ".." << c.r_max << ", periodic " << periodic);
    CHECK(state.size() == std::size_t(c.count));
    CHECK(brute_force_overlaps(state, periodic) == 0);
    const bool wrap_x = periodic && c.region.x0 == 0 && c.region.x1 == 1;
    const bool wrap_y = periodic && c.region.y0 == 0 && c.region.y1 == 1;
    CHECK(inside_region(state, 0, c.region, wrap_x, wrap_y));
    for (std::size_t i = 0; i < state.size(); ++i) {
      REQUIRE(state.radius[i] >= c.r_min);
      REQUIRE(state.radius[i] <= c.r_max);
    }
  }
}

TEST_CASE("random placement in a periodic box uses the whole box, straddling the boundary", "[setup][placement]") {
  const InitialState periodic =
      build_ok(scene_of({random_species("gas", 2000, 0.005, 0.005)}, BoundaryKind::Periodic));
  const InitialState walls = build_ok(scene_of({random_species("gas", 2000, 0.005, 0.005)}, BoundaryKind::Walls));
  int straddling = 0;
  for (std::size_t i = 0; i < periodic.size(); ++i) {
    if (periodic.x[i] < periodic.radius[i] || periodic.y[i] < periodic.radius[i]) ++straddling;
    CHECK(walls.x[i] >= walls.radius[i]);
    CHECK(walls.y[i] >= walls.radius[i]);
  }
  // 2000 centres uniform in the unit box: about 2000 * 2 * 0.005 = 20 within r of the lower edges.
  CHECK(straddling > 5);
}

TEST_CASE("random species avoid the disks of earlier species", "[setup][placement]") {
  SpeciesSpec wall = random_species("bed", 50, 0.01, 0.01);
  wall.placement.kind = PlacementKind::Lattice;
  wall.placement.region = {0, 0, 1, 0.1};
  SpeciesSpec rock = random_species("rock", 3, 0.1, 0.1);
  rock.placement.kind = PlacementKind::Explicit;
  rock.placement.positions = {{0.5, 0.5}, {0.2, 0.8}, {0.8, 0.8}};
  SpeciesSpec gas = random_species("gas", 1500, 0.008, 0.008);  // region: the whole box
  const InitialState s = build_ok(scene_of({wall, rock, gas}));
  CHECK(brute_force_overlaps(s, false) == 0);
}

TEST_CASE("random placement orders disks along a space-filling curve", "[setup][placement]") {
  const InitialState s = build_ok(scene_of({random_species("gas", 10000, 0.003, 0.003)}, BoundaryKind::Periodic));
  double sum = 0;
  for (std::size_t i = 1; i < s.size(); ++i) sum += std::hypot(s.x[i] - s.x[i - 1], s.y[i] - s.y[i - 1]);
  // Random order: mean step 0.52 (two uniform points in the unit square). Mean spacing here: 0.01.
  CHECK(sum / double(s.size() - 1) < 0.03);
}

TEST_CASE("a radius from the packing fraction gives exactly that fraction", "[setup][placement]") {
  SpeciesSpec s = packed_species("gas", 3000, 0.4, PlacementKind::Random);
  s.placement.region = {0.5, 0.25, 1.5, 1.75};
  Scene scene = scene_of({s});
  scene.lx = 2;
  scene.ly = 2;
  const InitialState state = build_ok(scene);
  CHECK(packing_fraction(state, 0, 1.5) == Approx(0.4).epsilon(1e-12));
  CHECK(state.radius[0] == Approx(std::sqrt(0.4 * 1.5 / (3000 * kPi))).epsilon(1e-15));
  CHECK(inside_region(state, 0, s.placement.region, false, false));
}

TEST_CASE("random placement near 0.5 succeeds, at 0.6 it stops with the jamming message", "[setup][placement]") {
  const InitialState ok =
      build_ok(scene_of({packed_species("gas", 2000, 0.5, PlacementKind::Random)}, BoundaryKind::Periodic));
  CHECK(ok.size() == 2000);

  const std::string e = build_error(scene_of({packed_species("gas", 300, 0.6, PlacementKind::Random)}));
  INFO(e);
  CHECK(contains(e, "test.toml"));
  CHECK(contains(e, "species 'gas'"));
  CHECK(contains(e, "random placement stopped after 1000000 attempts with "));
  CHECK(contains(e, " of 300 disks placed (packing fraction 0.5"));
  CHECK(contains(e, "jams near 0.547"));
  CHECK(contains(e, "placement.kind = \"lattice\""));
}

TEST_CASE("lattices at high packing: the requested count, no overlaps, inside the region", "[setup][lattice]") {
  struct Case {
    LatticeKind kind;
    double phi;
    std::int64_t count;
    Region region;
    BoundaryKind boundary;
  };
  const Case cases[] = {
      {LatticeKind::Hexagonal, 0.8, 1000, {0, 0, 1, 1}, BoundaryKind::Walls},
      {LatticeKind::Hexagonal, 0.8, 997, {0, 0, 1, 1}, BoundaryKind::Walls},  // a partial last row
      {LatticeKind::Hexagonal, 0.8, 1000, {0, 0, 1, 1}, BoundaryKind::Periodic},
      {LatticeKind::Hexagonal, 0.8, 600, {0.1, 0.2, 0.9, 0.5}, BoundaryKind::Walls},
      {LatticeKind::Square, 0.7, 900, {0, 0, 1, 1}, BoundaryKind::Walls},
      {LatticeKind::Square, 0.7, 900, {0, 0, 1, 1}, BoundaryKind::Periodic},
      {LatticeKind::Square, 0.6, 1, {0, 0, 1, 1}, BoundaryKind::Walls},
      {LatticeKind::Hexagonal, 0.3, 2, {0, 0, 1, 1}, BoundaryKind::Walls},
  };
  for (const Case& c : cases) {
    SpeciesSpec s = packed_species("crystal", c.count, c.phi, PlacementKind::Lattice);
    s.placement.lattice = c.kind;
    s.placement.region = c.region;
    const bool periodic = c.boundary == BoundaryKind::Periodic;
    INFO("count " << c.count << ", phi " << c.phi << ", hexagonal " << (c.kind == LatticeKind::Hexagonal)
                  << ", periodic " << periodic);
    const InitialState state = build_ok(scene_of({s}, c.boundary));
    CHECK(state.size() == std::size_t(c.count));
    CHECK(brute_force_overlaps(state, periodic) == 0);
    const bool whole = periodic && c.region.x0 == 0 && c.region.x1 == 1 && c.region.y0 == 0 && c.region.y1 == 1;
    CHECK(inside_region(state, 0, c.region, whole, whole));
    CHECK(packing_fraction(state, 0, c.region.area()) == Approx(c.phi).epsilon(1e-12));
  }
}

TEST_CASE("lattice disks touching the walls stay inside despite round-off", "[setup][lattice]") {
  // Irregular box sizes: the lattice fills one dimension exactly, so the outermost disks touch the walls
  // and x + r rounds to lx or one ulp above it unless setup nudges them.
  for (int k = 0; k < 200; ++k) {
    Scene scene = scene_of({packed_species("crystal", 10 + k % 23, 0.5, PlacementKind::Lattice)});
    scene.lx = 0.5 + 0.00523 * k;
    scene.ly = 1.5 - 0.00471 * k;
    scene.species[0].placement.region = {0, 0, scene.lx, scene.ly};
    scene.species[0].placement.lattice = k % 2 ? LatticeKind::Square : LatticeKind::Hexagonal;
    Result<InitialState> r = build_initial_state(scene);
    INFO("k = " << k << (r ? std::string() : ": " + r.error().message));
    CHECK((r.ok() || contains(r.error().message, "do not fit")));  // a few narrow boxes really are too small
  }
}

TEST_CASE("a lattice of mixed radii is spaced for the largest", "[setup][lattice]") {
  SpeciesSpec s = random_species("grains", 400, 0.01, 0.02);
  s.placement.kind = PlacementKind::Lattice;
  s.placement.region = {0, 0, 1, 0.9};
  const InitialState state = build_ok(scene_of({s}));
  CHECK(state.size() == 400);
  CHECK(brute_force_overlaps(state, false) == 0);
}

TEST_CASE("a periodic hexagonal lattice tiles the box when the count allows it", "[setup][lattice]") {
  // 20 x 24 sites: rows ly/24 apart, sites lx/20 apart, nearly the ideal ratio sqrt(3)/2 (0.833 vs 0.866).
  SpeciesSpec s = packed_species("crystal", 480, 0.85, PlacementKind::Lattice);
  const InitialState state = build_ok(scene_of({s}, BoundaryKind::Periodic));
  // A tiling has every disk's nearest neighbour at about the same distance, across the boundary too.
  double nearest_min = 1, nearest_max = 0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    double best = 1;
    for (std::size_t j = 0; j < state.size(); ++j) {
      if (j == i) continue;
      best = std::min(best, std::hypot(min_image(state.x[j] - state.x[i], 1, true),
                                       min_image(state.y[j] - state.y[i], 1, true)));
    }
    nearest_min = std::min(nearest_min, best);
    nearest_max = std::max(nearest_max, best);
  }
  CHECK(nearest_max - nearest_min < 1e-12);
  CHECK(nearest_min >= 2 * state.radius[0]);
}

TEST_CASE("a lattice too dense for its region is refused with how many fit", "[setup][lattice]") {
  SpeciesSpec s = packed_species("crystal", 1000, 0.93, PlacementKind::Lattice);  // above hexagonal 0.9069
  const std::string e = build_error(scene_of({s}));
  INFO(e);
  // The loader's form (docs/scene-format.md), without a line: this scene was made in code.
  CHECK(contains(e, "test.toml: error: species[0].count (species 'crystal'): 1000 disks of radius"));
  CHECK(contains(e, "do not fit on a hexagonal lattice in region [0, 1] x [0, 1]: at most "));
  CHECK(contains(e, ". Fix: reduce count or radius, or enlarge the region."));

  s.placement.lattice = LatticeKind::Square;
  s.placement.packing_fraction = 0.8;  // above square pi/4 = 0.785
  CHECK(contains(build_error(scene_of({s})), "do not fit on a square lattice"));
}

TEST_CASE("explicit placement keeps the positions and order given, overlaps are refused", "[setup][explicit]") {
  SpeciesSpec s = random_species("cradle", 3, 0.1, 0.1);
  s.placement.kind = PlacementKind::Explicit;
  s.placement.positions = {{0.5, 0.5}, {0.3, 0.5}, {0.7, 0.5}};  // touching exactly: allowed
  s.velocity.kind = VelocityKind::List;
  s.velocity.list = {{0, 0}, {1, 0}, {0, 0}};
  const InitialState state = build_ok(scene_of({s}));
  CHECK(state.x == std::vector<double>{0.5, 0.3, 0.7});
  CHECK(state.vx == std::vector<double>{0, 1, 0});

  SpeciesSpec gas = random_species("gas", 2, 0.05, 0.05);
  gas.placement.kind = PlacementKind::Explicit;
  gas.placement.positions = {{0.2, 0.2}, {0.8, 0.8}};
  SpeciesSpec projectile = random_species("projectile", 1, 0.05, 0.05);
  projectile.placement.kind = PlacementKind::Explicit;
  projectile.placement.positions = {{0.85, 0.8}};
  const std::string e = build_error(scene_of({gas, projectile}));
  INFO(e);
  CHECK(contains(e, "test.toml: error: species[1].placement.positions[0] (species 'projectile'): disk 2 overlaps "
                    "disk 1 (species[0].placement.positions[1], species 'gas'): centres (0.85, 0.8) and (0.8, 0.8)"));
  CHECK(contains(e, "distance 0.05"));
  CHECK(contains(e, "contact distance 0.1"));
  CHECK(contains(e, ". Fix: move them apart (centres at least 0.1 apart) or reduce the radii."));
}

TEST_CASE("setup's errors about a scene file name its line and key", "[setup][explicit][lattice]") {
  // docs/scene-format.md promises FILE:LINE:COL, the key and "Fix:" for every scene error, those found
  // when the disks are placed included.
  const std::string explicit_list = "[[species]]\nname = \"gas\"\nradius = 0.1\n[species.placement]\n"
                                    "kind = \"explicit\"\npositions = [[0.3, 0.5],\n             [0.35, 0.5]]\n"
                                    "[stop]\ntime = 1.0\n";
  const std::string e = build_error(ede::parse_scene_text(explicit_list, "list.toml").value());
  INFO(e);
  CHECK(contains(e, "list.toml:7:14: error: species[0].placement.positions[1] (species 'gas'): disk 1 overlaps disk 0 "
                    "(species[0].placement.positions[0], line 6, species 'gas')"));
  CHECK(contains(e, "Fix: move them apart"));
  const std::string lattice = "[[species]]\nname = \"gas\"\ncount = 100\nradius = 0.1\n[species.placement]\n"
                              "kind = \"lattice\"\n[stop]\ntime = 1.0\n";
  const std::string l = build_error(ede::parse_scene_text(lattice, "lattice.toml").value());
  INFO(l);
  CHECK(contains(l, "lattice.toml:3:9: error: species[0].count (species 'gas'): 100 disks of radius 0.1 do not fit"));
  CHECK(contains(l, "at most 20 fit. Fix: reduce count or radius, or enlarge the region."));
  // A count set by --set has no line in the file: the message leaves the line out, as the loader does.
  const std::string o = build_error(ede::parse_scene_text(lattice, "lattice.toml", {{"species.gas.count=200"}}).value());
  CHECK(contains(o, "lattice.toml: error: species[0].count (species 'gas'): 200 disks"));
}

TEST_CASE("masses: fixed, or density times area", "[setup]") {
  SpeciesSpec s = random_species("gas", 200, 0.01, 0.02);
  s.mass.kind = MassSpec::Kind::PerArea;
  s.mass.value = 3;
  SpeciesSpec t = random_species("heavy", 10, 0.01, 0.01);
  t.mass.value = 25;
  const InitialState state = build_ok(scene_of({s, t}));
  for (std::size_t i = 0; i < state.size(); ++i) {
    const double expected = i < 200 ? 3 * kPi * state.radius[i] * state.radius[i] : 25.0;
    CHECK(state.mass[i] == expected);
  }
}

TEST_CASE("velocity rules: zero, speed, vector and list", "[setup][velocity]") {
  SpeciesSpec zero = random_species("zero", 50, 0.01, 0.01);
  zero.velocity.kind = VelocityKind::Zero;
  SpeciesSpec speed = random_species("speed", 2000, 0.005, 0.005);
  speed.velocity.kind = VelocityKind::Speed;
  speed.velocity.speed = 2.5;
  SpeciesSpec vector = random_species("vector", 5, 0.01, 0.01);
  vector.velocity.kind = VelocityKind::Vector;
  vector.velocity.vector = {0.5, -7};
  const InitialState s = build_ok(scene_of({zero, speed, vector}));
  double mean_vx = 0, mean_vy = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.species[i] == 0) {
      CHECK(s.vx[i] == 0);
      CHECK(s.vy[i] == 0);
    } else if (s.species[i] == 1) {
      CHECK(std::hypot(s.vx[i], s.vy[i]) == Approx(2.5).epsilon(1e-15));
      mean_vx += s.vx[i] / 2000;
      mean_vy += s.vy[i] / 2000;
    } else {
      CHECK(s.vx[i] == 0.5);
      CHECK(s.vy[i] == -7);
    }
  }
  // Random directions: each mean component has standard error 2.5 / sqrt(2 * 2000) = 0.04; 5 sigma.
  CHECK(std::abs(mean_vx) < 0.2);
  CHECK(std::abs(mean_vy) < 0.2);
}

TEST_CASE("Maxwell-Boltzmann velocities: mean kinetic energy kT per disk for every mass", "[setup][velocity]") {
  // In 2D each disk's kinetic energy (m/2)(vx^2 + vy^2) is kT times an Exp(1) variable: mean kT, standard
  // deviation kT. With n disks the mean has standard error kT / sqrt(n); tolerance 5 of it. The variance of
  // vx alone is kT / m (standard error kT / m * sqrt(2 / n)).
  const double kT = 1.7;
  const std::int64_t n = 20000;
  SpeciesSpec light = random_species("light", n, 0.001, 0.001);
  light.velocity.temperature = kT;
  light.mass.value = 1;
  SpeciesSpec heavy = random_species("heavy", n, 0.001, 0.001);
  heavy.velocity.temperature = kT;
  heavy.mass.value = 4;
  const InitialState s = build_ok(scene_of({light, heavy}, BoundaryKind::Periodic));
  for (std::int32_t k : {0, 1}) {
    const double m = k == 0 ? 1.0 : 4.0;
    double energy = 0, vx2 = 0, vx = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s.species[i] != k) continue;
      energy += 0.5 * s.mass[i] * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
      vx2 += s.vx[i] * s.vx[i];
      vx += s.vx[i];
    }
    INFO("mass " << m);
    CHECK(std::abs(energy / n - kT) < 5 * kT / std::sqrt(double(n)));
    CHECK(std::abs(vx2 / n - kT / m) < 5 * (kT / m) * std::sqrt(2.0 / n));
    CHECK(std::abs(vx / n) < 5 * std::sqrt(kT / m / n));
  }
}

TEST_CASE("setup refuses invalid scenes with messages naming the species and the fix", "[setup][errors]") {
  SpeciesSpec s = random_species("gas", 10, 0.01, 0.01);
  SpeciesSpec bad = s;
  bad.radius.min = 0;
  bad.radius.max = 0;
  CHECK(contains(build_error(scene_of({s, bad})), "test.toml: species 'gas' (index 1): the radius range [0, 0]"));

  bad = s;
  bad.placement.region = {0, 0, 2, 1};
  CHECK(contains(build_error(scene_of({bad})), "must be a non-empty rectangle inside the box [0, 1] x [0, 1]"));

  bad = s;
  bad.placement.kind = PlacementKind::Explicit;
  CHECK(contains(build_error(scene_of({bad})), "placement.positions has 0 entries but count is 10"));

  bad = s;
  bad.velocity.kind = VelocityKind::List;
  bad.velocity.list = {{1, 2}};
  CHECK(contains(build_error(scene_of({bad})), "velocity.list has 1 entries but count is 10"));

  bad = packed_species("gas", 10, 0.5, PlacementKind::Random);
  bad.placement.packing_fraction.reset();
  CHECK(contains(build_error(scene_of({bad})),
                 "placement.packing_fraction, which must be in (0, 1) but is not given"));

  bad = s;
  bad.mass.value = -1;
  CHECK(contains(build_error(scene_of({bad})), "the mass -1 must be finite and > 0"));

  bad = s;
  bad.mass.value = 1e308;  // finite, but two of them sum past the largest double
  CHECK(contains(build_error(scene_of({bad})), "whose sum overflows a double"));
  bad.mass.value = 8e307;  // the sum 1.6e308 is finite: accepted
  CHECK(build_initial_state(scene_of({bad})).ok());

  bad = s;
  bad.radius = {0.3, 0.3, false};
  bad.placement.region = {0, 0, 0.5, 1};
  CHECK(contains(build_error(scene_of({bad})), "a disk of radius 0.3 does not fit in the region"));

  CHECK(contains(build_error(scene_of({})), "the scene has no disks"));
  bad = s;
  bad.count = 100000001;
  CHECK(contains(build_error(scene_of({bad})), "at most 10^8"));
}

TEST_CASE("check_initial_state: boxes, numbers, overlaps across the periodic boundary", "[setup][check]") {
  InitialState s;
  s.species_names = {"gas", "wall"};
  CHECK(contains(check_initial_state(s, BoundaryKind::Walls, "hand").error().message,
                 "hand: the initial state has no disks"));

  s.add(0.05, 0.5, 0, 0, 0.1, 1, 0);  // sticks out of the left wall; fine when periodic
  s.add(0.5, 0.5, 0, 0, 0.1, 1, 1);
  const std::string walls = check_initial_state(s, BoundaryKind::Walls, "hand").error().message;
  CHECK(contains(
      walls, "hand: disk 0 (gas) at (0.05, 0.5) with radius 0.1 is not inside the walled box [0, 1] x [0, 1]"));
  CHECK(check_initial_state(s, BoundaryKind::Periodic, "hand").ok());

  s.add(0.97, 0.52, 0, 0, 0.1, 1, 1);  // overlaps disk 0 through the periodic boundary (distance 0.085)
  const std::string across = check_initial_state(s, BoundaryKind::Periodic, "hand").error().message;
  INFO(across);
  CHECK(contains(across, "hand: disks 0 (gas) and 2 (wall) overlap"));

  InitialState t;
  t.add(1.0, 0.5, 0, 0, 0.1, 1, 0);  // x == lx: outside [0, lx) in a periodic box
  CHECK(contains(check_initial_state(t, BoundaryKind::Periodic, "f").error().message, "wrap it into the box"));
  t.x[0] = 0.5;
  t.mass[0] = 0;
  CHECK(contains(check_initial_state(t, BoundaryKind::Periodic, "f").error().message, "has mass 0"));
  t.mass[0] = 1;
  t.vy[0] = std::nan("");
  CHECK(contains(check_initial_state(t, BoundaryKind::Periodic, "f").error().message, "non-finite"));
  t.vy[0] = 0;
  t.radius[0] = 0.6;
  CHECK(contains(check_initial_state(t, BoundaryKind::Periodic, "f").error().message, "its own image"));
  t.radius[0] = 0.1;
  CHECK(check_initial_state(t, BoundaryKind::Periodic, "f").ok());
}

TEST_CASE("check_initial_state finds every overlap in a large state (grid against all pairs)", "[setup][check]") {
  // 3000 random disks, some overlapping: the grid-based check must agree with the all-pairs count.
  Rng rng(11);
  InitialState s;
  for (int i = 0; i < 3000; ++i)
    s.add(rng.uniform01(), rng.uniform01(), 0, 0, 0.001 + 0.004 * rng.uniform01(), 1, 0);
  const int pairs = brute_force_overlaps(s, true);
  REQUIRE(pairs > 1);
  const std::string e = check_initial_state(s, BoundaryKind::Periodic, "f").error().message;
  CHECK(contains(e, "(" + std::to_string(pairs - 1) + " other overlapping pairs too)"));
}
