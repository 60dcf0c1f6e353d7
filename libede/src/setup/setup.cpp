// build_initial_state: the orchestration of setup, species by species in scene order.
//
// 1. Check what setup relies on (a Scene may be built in code, not only by the loader), with messages
//    naming the file, the species (name and index) and the fix.
// 2. Draw the radii of every species, each from its own stream Rng::for_stream(seed, species index), so
//    the placement grid's cells can be one largest diameter wide for everything placed.
// 3. Place species by species into one shared grid: later species avoid earlier ones. Random and lattice
//    species are then reordered along a Hilbert curve (positions quantised to 2^32 x 2^32 over the box,
//    ties by placement order) so that disks near in space are near in memory, which the engine's cell
//    lists and caches like; explicit species keep the order given (a velocity list refers to it).
// 3b. With [grow]: the radii were scaled first so that placement works at a low packing fraction; the
//    placed disks of every species then grow together (setup/grow.hpp) and each species is re-ordered
//    along the curve. Velocities are drawn after this, so growth changes no species' random stream.
// 4. Masses and velocities in the final order; then check_initial_state on the whole result.
// Each stream draws radii, then positions, then velocities, and depends on nothing of later species (the
// curve order uses the box, not the grid, whose cell size depends on every species): adding a species
// leaves the disks of the ones before it bit for bit unchanged.
// Rejected: one generator for the whole scene (adding or resizing a species would change every later one)
// and a Morton order (simpler, but its jumps between quadrants put far-apart disks next to each other).
#include "setup/setup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/rng.hpp"
#include "setup/grow.hpp"
#include "setup/placement_grid.hpp"
#include "setup/setup_lattice.hpp"
#include "setup/setup_random_placement.hpp"
#include "setup/setup_velocities.hpp"

namespace ede {

namespace {

using setup_detail::number_text;
using setup_detail::PlacementGrid;

constexpr double kPi = 3.14159265358979323846;
constexpr std::int64_t kMaxDisks = 100000000;

std::string species_where(const Scene& scene, std::size_t k) {
  return scene.source_name + ": species '" + scene.species[k].name + "' (index " + std::to_string(k) + "): ";
}

// The loader's form for an error found here about one key of species k (docs/scene-format.md):
// "FILE:LINE:COL: error: species[k].KEY (species 'NAME'): " (no line when the value was not in the file).
std::string key_where(const Scene& scene, std::size_t k, const std::string& key, SourceSpot spot) {
  std::string where = scene.source_name;
  if (spot.line) where += ":" + std::to_string(spot.line) + ":" + std::to_string(spot.column);
  return where + ": error: species[" + std::to_string(k) + "]." + key + " (species '" + scene.species[k].name + "'): ";
}

bool finite_positive(double v) { return std::isfinite(v) && v > 0; }
bool finite_nonnegative(double v) { return std::isfinite(v) && v >= 0; }

// --- 1. checks -------------------------------------------------------------------------------------------

Status check_box_and_counts(const Scene& scene) {
  if (!finite_positive(scene.lx) || !finite_positive(scene.ly)) {
    return Error{scene.source_name + ": the box size must be finite and positive (lx = " + number_text(scene.lx) +
                 ", ly = " + number_text(scene.ly) + "); give lx > 0 and ly > 0"};
  }
  std::int64_t total = 0;
  for (std::size_t k = 0; k < scene.species.size(); ++k) {
    const std::int64_t count = scene.species[k].count;
    if (count < 0) {
      return Error{species_where(scene, k) + "count is " + std::to_string(count) + "; give a count >= 0"};
    }
    total += std::min(count, kMaxDisks + 1);
    if (total > kMaxDisks) {
      return Error{scene.source_name +
                   ": more than 10^8 disks in all; ede handles at most 10^8, reduce the counts"};
    }
  }
  if (total == 0) {
    return Error{scene.source_name + ": the scene has no disks; give at least one species a count >= 1"};
  }
  return Ok{};
}

Status check_radius(const Scene& scene, std::size_t k) {
  const SpeciesSpec& s = scene.species[k];
  if (s.radius.from_packing) {
    const std::optional<double>& phi = s.placement.packing_fraction;
    if (s.placement.kind == PlacementKind::Explicit) {
      return Error{species_where(scene, k) +
                   "the radius comes from a packing fraction, which needs random or "
                   "lattice placement (explicit positions have no region to fill); give the radius"};
    }
    if (!phi || !std::isfinite(*phi) || *phi <= 0 || *phi >= 1) {
      return Error{species_where(scene, k) +
                   "the radius comes from placement.packing_fraction, which must be "
                   "in (0, 1)" +
                   (phi ? " (got " + number_text(*phi) + ")" : std::string(" but is not given")) +
                   "; give a packing fraction or a radius"};
    }
    return Ok{};
  }
  if (!finite_positive(s.radius.min) || !std::isfinite(s.radius.max) || s.radius.max < s.radius.min) {
    return Error{species_where(scene, k) + "the radius range [" + number_text(s.radius.min) + ", " +
                 number_text(s.radius.max) + "] is not valid; radii must be finite, > 0, and min <= max"};
  }
  return Ok{};
}

Status check_mass(const Scene& scene, std::size_t k) {
  const MassSpec& m = scene.species[k].mass;
  if (finite_positive(m.value)) return Ok{};
  return Error{species_where(scene, k) + (m.kind == MassSpec::Kind::Fixed ? "the mass " : "the areal density ") +
               number_text(m.value) + " must be finite and > 0"};
}

Status check_placement(const Scene& scene, std::size_t k) {
  const SpeciesSpec& s = scene.species[k];
  const PlacementSpec& p = s.placement;
  if (p.kind == PlacementKind::Explicit) {
    if (std::int64_t(p.positions.size()) != s.count) {
      return Error{species_where(scene, k) + "placement.positions has " + std::to_string(p.positions.size()) +
                   " entries but count is " + std::to_string(s.count) + "; give one [x, y] per disk"};
    }
    for (std::size_t i = 0; i < p.positions.size(); ++i) {
      if (!std::isfinite(p.positions[i][0]) || !std::isfinite(p.positions[i][1])) {
        return Error{species_where(scene, k) + "placement.positions[" + std::to_string(i) + "] is not finite"};
      }
    }
    return Ok{};
  }
  const Region& g = p.region;
  const bool finite = std::isfinite(g.x0) && std::isfinite(g.x1) && std::isfinite(g.y0) && std::isfinite(g.y1);
  if (!finite || g.x0 >= g.x1 || g.y0 >= g.y1 || g.x0 < 0 || g.y0 < 0 || g.x1 > scene.lx || g.y1 > scene.ly) {
    return Error{species_where(scene, k) + "placement.region [" + number_text(g.x0) + ", " + number_text(g.x1) +
                 "] x [" + number_text(g.y0) + ", " + number_text(g.y1) +
                 "] must be a non-empty rectangle inside the box [0, " + number_text(scene.lx) + "] x [0, " +
                 number_text(scene.ly) + "]"};
  }
  return Ok{};
}

Status check_velocity(const Scene& scene, std::size_t k) {
  const SpeciesSpec& s = scene.species[k];
  const VelocitySpec& v = s.velocity;
  const std::string where = species_where(scene, k);
  switch (v.kind) {
    case VelocityKind::Zero:
      return Ok{};
    case VelocityKind::Speed:
      if (finite_nonnegative(v.speed)) return Ok{};
      return Error{where + "velocity.speed " + number_text(v.speed) + " must be finite and >= 0"};
    case VelocityKind::Vector:
      if (std::isfinite(v.vector[0]) && std::isfinite(v.vector[1])) return Ok{};
      return Error{where + "velocity.vector must be finite"};
    case VelocityKind::Maxwell:
      if (finite_nonnegative(v.temperature)) return Ok{};
      return Error{where + "velocity.temperature " + number_text(v.temperature) + " must be finite and >= 0"};
    case VelocityKind::List:
      if (std::int64_t(v.list.size()) != s.count) {
        return Error{where + "velocity.list has " + std::to_string(v.list.size()) + " entries but count is " +
                     std::to_string(s.count) + "; give one [vx, vy] per disk"};
      }
      for (std::size_t i = 0; i < v.list.size(); ++i) {
        if (!std::isfinite(v.list[i][0]) || !std::isfinite(v.list[i][1])) {
          return Error{where + "velocity.list[" + std::to_string(i) + "] is not finite"};
        }
      }
      return Ok{};
  }
  return Ok{};
}

Status check_scene(const Scene& scene) {
  if (Status st = check_box_and_counts(scene); !st) return st;
  for (std::size_t k = 0; k < scene.species.size(); ++k) {
    for (auto check : {check_radius, check_mass, check_placement, check_velocity}) {
      if (Status st = check(scene, k); !st) return st;
    }
  }
  return Ok{};
}

// --- 2. radii and masses ---------------------------------------------------------------------------------

std::vector<double> draw_radii(const SpeciesSpec& s, Rng& rng) {
  const std::size_t n = std::size_t(s.count);
  if (s.radius.from_packing) {
    const double r = std::sqrt(*s.placement.packing_fraction * s.placement.region.area() / (double(n) * kPi));
    return std::vector<double>(n, r);
  }
  if (s.radius.min == s.radius.max) return std::vector<double>(n, s.radius.min);
  std::vector<double> radii(n);
  for (double& r : radii) r = rng.uniform(s.radius.min, s.radius.max);
  return radii;
}

std::vector<double> masses(const MassSpec& spec, const std::vector<double>& radii) {
  std::vector<double> m(radii.size(), spec.value);
  if (spec.kind == MassSpec::Kind::PerArea) {
    for (std::size_t i = 0; i < m.size(); ++i) m[i] = spec.value * kPi * radii[i] * radii[i];
  }
  return m;
}

// --- 3. placement and order ------------------------------------------------------------------------------

struct Disks {
  std::vector<double> x, y, r;
};

// The distance along a Hilbert curve through a 2^32 x 2^32 grid (Wikipedia's xy2d, with n - 1 - v as ~v).
std::uint64_t hilbert_index(std::uint32_t qx, std::uint32_t qy) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << 31; s > 0; s >>= 1) {
    const std::uint32_t rx = (qx & s) ? 1 : 0, ry = (qy & s) ? 1 : 0;
    d += std::uint64_t(s) * std::uint64_t(s) * std::uint64_t((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        qx = ~qx;
        qy = ~qy;
      }
      std::swap(qx, qy);
    }
  }
  return d;
}

std::uint32_t quantise(double v, double length) {
  const double q = std::floor(v / length * 4294967296.0);
  return q <= 0 ? 0u : q >= 4294967295.0 ? 4294967295u : std::uint32_t(q);
}

void order_along_curve(Disks& d, double lx, double ly) {
  std::vector<std::uint64_t> key(d.x.size());
  for (std::size_t i = 0; i < key.size(); ++i) key[i] = hilbert_index(quantise(d.x[i], lx), quantise(d.y[i], ly));
  std::vector<std::size_t> order(key.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  for (std::vector<double>* v : {&d.x, &d.y, &d.r}) {
    std::vector<double> out(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) out[i] = (*v)[order[i]];
    v->swap(out);
  }
}

Status place_species(const Scene& scene, std::size_t k, PlacementGrid& grid, Rng& rng, Disks& d) {
  const SpeciesSpec& s = scene.species[k];
  const bool periodic = scene.boundary == BoundaryKind::Periodic;
  Status st = Ok{};
  switch (s.placement.kind) {
    case PlacementKind::Random:
    {
      setup_detail::RandomPlacement where{s.placement.region, scene.lx, scene.ly, periodic, {}, s.placement.sampling};
      for (const SegmentSpec& g : scene.physics.segments)
        where.segments.push_back(make_segment(g.from[0], g.from[1], g.to[0], g.to[1], g.restitution));
      st = setup_detail::place_random(where, d.r, grid, rng, d.x, d.y);
      break;
    }
    case PlacementKind::Lattice: {
      const double r_max = d.r.empty() ? 0.0 : *std::max_element(d.r.begin(), d.r.end());  // sites fit the largest
      st = setup_detail::place_lattice({s.placement.lattice, s.placement.region, scene.lx, scene.ly, periodic},
                                       r_max, s.count, d.x, d.y);
      if (!st)
        return Error{key_where(scene, k, "count", s.count_spot) + st.error().message +
                     ". Fix: reduce count or radius, or enlarge the region."};
      break;
    }
    case PlacementKind::Explicit:
      for (const auto& p : s.placement.positions) {
        d.x.push_back(p[0]);
        d.y.push_back(p[1]);
      }
      break;
  }
  if (!st) return Error{species_where(scene, k) + st.error().message};
  if (s.placement.kind != PlacementKind::Random) {  // random placement inserts each disk as it goes
    for (std::size_t i = 0; i < d.x.size(); ++i) grid.insert(d.x[i], d.y[i], d.r[i]);
  }
  if (s.placement.kind != PlacementKind::Explicit) order_along_curve(d, scene.lx, scene.ly);
  return Ok{};
}

// Random placement near jamming rejects most candidates: a bitmap of wholly blocked voxels, valid for the
// smallest radius of the scene, rejects them without the cell scan (same decisions, see blocked_voxels.hpp).
void enable_blocked_voxels(const Scene& scene, const std::vector<Disks>& disks, PlacementGrid& grid) {
  double r_min = 0, r_sum = 0;
  std::size_t count = 0, random = 0;
  for (std::size_t k = 0; k < disks.size(); ++k) {
    for (double r : disks[k].r) {
      r_min = count == 0 ? r : std::min(r_min, r);
      r_sum += r;
      ++count;
    }
    if (scene.species[k].placement.kind == PlacementKind::Random) random += disks[k].r.size();
  }
  if (random == 0) return;
  grid.enable_blocked_voxels(r_min, r_sum / double(count));
}

InitialState empty_state(const Scene& scene, std::size_t disks) {
  InitialState state;
  state.lx = scene.lx;
  state.ly = scene.ly;
  for (std::vector<double>* v : {&state.x, &state.y, &state.vx, &state.vy, &state.radius, &state.mass}) {
    v->reserve(disks);
  }
  state.species.reserve(disks);
  for (const SpeciesSpec& s : scene.species) state.species_names.push_back(s.name);
  return state;
}

// --- growth ([grow], setup/grow.hpp) --------------------------------------------------------------------

// pi / (2 sqrt 3): no arrangement of equal disks covers more of the plane.
constexpr double kHexagonalPacking = 0.90689968211710892;

// Scales every radius by one factor so that the disks cover grow_start_phi of the box: placement then
// works at a low density and growth takes them to the target. Refuses a target that equal disks cannot have.
Status scale_for_growth(const Scene& scene, std::vector<Disks>& disks) {
  const GrowSpec& g = *scene.grow;
  double area = 0, r_min = std::numeric_limits<double>::infinity(), r_max = 0;
  for (const Disks& d : disks)
    for (double r : d.r) {
      area += kPi * r * r;
      r_min = std::min(r_min, r);
      r_max = std::max(r_max, r);
    }
  if (g.packing_fraction && r_min == r_max && *g.packing_fraction > kHexagonalPacking)
    return Error{scene.source_name + ": grow.packing_fraction = " + number_text(*g.packing_fraction) +
                 " is above pi/(2 sqrt 3) = 0.9069, the densest packing of equal disks (the hexagonal lattice), "
                 "so no growth can reach it; give grow.packing_fraction <= 0.9069 (disordered disks jam near "
                 "0.84; above that use placement.kind = \"lattice\"), or grow.pressure = 1e6 to grow until jammed"};
  const double f = std::sqrt(setup_detail::grow_start_phi(g.packing_fraction.value_or(0)) * scene.lx * scene.ly / area);
  for (Disks& d : disks)
    for (double& r : d.r) r *= f;
  return Ok{};
}

// Runs the growth on every placed disk, writes the grown disks back (each species re-ordered along the
// curve, as placement orders them) and returns the line that the run's summary shows.
Result<std::string> grow_placed(const Scene& scene, std::vector<Disks>& disks) {
  setup_detail::GrowInput in;
  in.lx = scene.lx;
  in.ly = scene.ly;
  in.periodic = scene.boundary == BoundaryKind::Periodic;
  for (const Disks& d : disks) {
    in.x.insert(in.x.end(), d.x.begin(), d.x.end());
    in.y.insert(in.y.end(), d.y.begin(), d.y.end());
    in.r.insert(in.r.end(), d.r.begin(), d.r.end());
  }
  in.target_phi = scene.grow->packing_fraction.value_or(0);
  in.pressure = scene.grow->pressure.value_or(0);
  in.rate = scene.grow->rate;
  in.seed = scene.seed;
  auto grown = setup_detail::grow_disks(in);
  if (!grown) return Error{scene.source_name + ": [grow]: " + grown.error().message};
  const setup_detail::GrowResult& g = grown.value();
  std::size_t at = 0;
  for (Disks& d : disks) {
    for (std::size_t i = 0; i < d.x.size(); ++i, ++at) {
      d.x[i] = g.x[at];
      d.y[i] = g.y[at];
      d.r[i] = g.r[at];
    }
    order_along_curve(d, scene.lx, scene.ly);
  }
  return "grown from packing fraction " + number_text(g.phi_start, 6) + " to " + number_text(g.phi, 12) +
         (g.jammed ? " (jammed: Z = " + number_text(g.z, 6) + " > grow.pressure)" : std::string()) + " in " +
         std::to_string(g.collisions) + " collisions, " + std::to_string(g.events) + " events";
}

}  // namespace

Result<InitialState> build_initial_state(const Scene& scene) {
  if (Status st = check_scene(scene); !st) return st.error();
  const std::size_t n_species = scene.species.size();
  std::vector<Rng> streams;
  std::vector<Disks> disks(n_species);
  std::size_t total = 0;
  for (std::size_t k = 0; k < n_species; ++k) {
    streams.push_back(Rng::for_stream(scene.seed, k));
    disks[k].r = draw_radii(scene.species[k], streams[k]);
    total += disks[k].r.size();
  }
  if (scene.grow) {
    if (Status st = scale_for_growth(scene, disks); !st) return st.error();
  }
  double r_max = 0;
  for (const Disks& d : disks)
    for (double r : d.r) r_max = std::max(r_max, r);
  PlacementGrid grid(scene.lx, scene.ly, scene.boundary == BoundaryKind::Periodic, 2 * r_max, total);
  enable_blocked_voxels(scene, disks, grid);
  for (std::size_t k = 0; k < n_species; ++k) {
    if (Status st = place_species(scene, k, grid, streams[k], disks[k]); !st) return st.error();
  }
  InitialState state = empty_state(scene, total);
  if (scene.grow) {
    auto note = grow_placed(scene, disks);
    if (!note) return note.error();
    state.note = note.value();
  }
  for (std::size_t k = 0; k < n_species; ++k) {
    const Disks& d = disks[k];
    const std::vector<double> m = masses(scene.species[k].mass, d.r);
    std::vector<double> vx, vy;
    setup_detail::assign_velocities(scene.species[k].velocity, m, streams[k], vx, vy);
    for (std::size_t i = 0; i < d.x.size(); ++i)
      state.add(d.x[i], d.y[i], vx[i], vy[i], d.r[i], m[i], std::int32_t(k));
    if (scene.rotates()) setup_detail::assign_spins(scene.species[k], m, d.r, streams[k], state.omega, state.inertia);
  }
  if (Status st = check_initial_state(state, scene.boundary, scene.source_name, &scene); !st) return st.error();
  if (Status st = check_disks_clear_of_segments(state, scene.physics.segments, scene.source_name); !st)
    return st.error();
  return state;
}

}  // namespace ede
