// Scene loading: TOML text -> tree -> --set overrides -> checked Scene, plus the effective scene text.
//
// The tree is read top-down, one function per table, in the order a reader meets them in a file. Each
// function says what its keys mean and which values are allowed; reading and reporting are scene_keys'
// job. Checks across keys (count vs positions, radius vs packing fraction, region vs box, keys of another
// kind) sit where both keys are known. What needs the drawn disks (overlaps, disks fitting a region) is
// setup's job. Rejected: a generic schema driving the checks, which needed escape hatches for every one
// of those cross-key rules and ended up longer than the code it replaced.
#include "ede/scene.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/scene_keys.hpp"
#include "scene/scene_label.hpp"
#include "scene/scene_override.hpp"
#include "scene/scene_start.hpp"

namespace ede {
namespace {

using namespace scene_detail;

constexpr std::int64_t kMaxDisks = 100'000'000;
constexpr double kMaxPacking = 0.9069;  // just above pi / (2 sqrt 3) = 0.90690, the hexagonal packing

std::string region_text(const Region& r) {
  return "[" + number_text(r.x0) + ", " + number_text(r.y0) + ", " + number_text(r.x1) + ", " +
         number_text(r.y1) + "]";
}

[[noreturn]] void missing(const Reader& r, std::string_view key, std::string_view why,
                          std::string_view example) {
  r.fail(key, "missing; " + std::string(why), "add " + std::string(example));
}

// A key that only some kinds use is an error with any other kind: it would otherwise be silently ignored.
void reject_unless(const Reader& r, std::string_view key, bool used, std::string_view kind,
                   std::string_view users) {
  if (used || !r.has(key)) return;
  r.fail(key, "not used with kind = \"" + std::string(kind) + "\" (only with " + std::string(users) + ")",
         "remove it, or change kind");
}

void read_box(const Reader& top, Scene& scene) {
  const Reader box = top.section("box");
  box.check_keys(sections::box);
  const auto size =
      box.numbers("size", 2, "[Lx, Ly]", Bounds::positive()).value_or(std::vector<double>{1, 1});
  scene.lx = size[0];
  scene.ly = size[1];
  const std::size_t boundary = box.choice("boundary", {"walls", "periodic", "lees-edwards"}).value_or(0);
  scene.boundary = boundary == 0 ? BoundaryKind::Walls : BoundaryKind::Periodic;
  // Lees-Edwards: a periodic box whose images above and below slide; the rate is required with it and
  // means nothing without it.
  const auto rate = box.number("shear_rate", Bounds::non_negative(),
                               "give the shear rate (the x-velocity of the image above per unit height), >= 0");
  if (boundary == 2) {
    if (!rate) missing(box, "shear_rate", "a Lees-Edwards box slides at a shear rate", "shear_rate = 0.1");
    scene.shear_rate = *rate;
  } else if (rate) {
    box.fail("shear_rate", "only a Lees-Edwards box is sheared",
             "remove shear_rate, or set box.boundary = \"lees-edwards\"");
  }
}

constexpr std::string_view kXiFix = "use a value from 0 (perfectly inelastic) to 1 (elastic)";
constexpr std::string_view kBetaFix = "use a value from -1 (smooth, the default) to 1 (perfectly rough)";

// wall_restitution = 0.5, or { left = 1.0, bottom = 0.5 } for some walls (the others stay elastic).
void read_wall_restitution(const Reader& p, PhysicsSpec& out) {
  const toml::node* node = p.get("wall_restitution");
  if (!node || !node->is_table()) {
    out.wall_restitution = p.number("wall_restitution", Bounds::closed(0, 1), kXiFix).value_or(1);
    return;
  }
  const Reader w = p.section("wall_restitution");
  w.check_keys(sections::wall_restitution);
  const char* sides[] = {"left", "right", "bottom", "top"};
  for (int k = 0; k < 4; ++k) out.walls[std::size_t(k)] = w.number(sides[k], Bounds::closed(0, 1), kXiFix);
}

// [[physics.pairs]] species = ["bed", "projectile"], restitution = 0.5
PairRestitution read_pair(const toml::node& node, std::size_t i, const Reader& p, double default_xi) {
  const std::string path = "physics.pairs[" + std::to_string(i) + "]";
  const toml::table* table = node.as_table();
  if (!table) p.fail_node(&node, path, "expected a table", "write each pair as a [[physics.pairs]] table");
  const Reader r(*table, path, p.origin());
  r.check_keys(sections::pair);
  const toml::array* names = r.array("species");
  if (!names || names->size() != 2 || !names->get(0)->is_string() || !names->get(1)->is_string())
    r.fail("species", "expected two species names", "write species = [\"bed\", \"projectile\"]");
  const auto value = r.number("restitution", Bounds::closed(0, 1), kXiFix);
  const auto beta = r.number("roughness", Bounds::closed(-1, 1), kBetaFix);
  if (!value && !beta)
    missing(r, "restitution", "a pair needs its restitution (or its roughness)", "restitution = 0.5");
  return {names->get(0)->value<std::string>().value_or(""), names->get(1)->value<std::string>().value_or(""),
          value.value_or(default_xi), beta};
}

// [[physics.steps]] species = ["a", "a"] (or absent: every pair of species without an entry of its own),
// radius = [0.015, ...] increasing, energy = [-1.0, ...] one per radius, finite and not 0.
PairSteps read_steps(const toml::node& node, std::size_t i, const Reader& p) {
  const std::string path = "physics.steps[" + std::to_string(i) + "]";
  const toml::table* table = node.as_table();
  if (!table) p.fail_node(&node, path, "expected a table", "write each stepped potential as a [[physics.steps]] table");
  const Reader r(*table, path, p.origin());
  r.check_keys(sections::steps);
  PairSteps out;
  if (r.has("species")) {
    const toml::array* names = r.array("species");
    if (!names || names->size() != 2 || !names->get(0)->is_string() || !names->get(1)->is_string())
      r.fail("species", "expected two species names", "write species = [\"gas\", \"gas\"], or leave it out for every pair");
    out.a = names->get(0)->value<std::string>().value_or("");
    out.b = names->get(1)->value<std::string>().value_or("");
  }
  const toml::array* radii = r.array("radius");
  const toml::array* energies = r.array("energy");
  if (!radii || radii->empty())
    missing(r, "radius", "a stepped potential needs the distances of its steps", "radius = [0.015]");
  if (!energies || energies->size() != radii->size())
    r.fail(energies ? "energy" : "radius",
           "needs one energy per radius (" + std::to_string(radii->size()) + " radii, " +
               std::to_string(energies ? energies->size() : 0) + " energies)",
           "write energy = [...] with one value per radius: the energy change on entering that step");
  out.radius = *r.numbers("radius", radii->size(), "[r1, r2, ...]", Bounds::positive());
  out.energy = *r.numbers("energy", radii->size(), "[e1, e2, ...]", Bounds::any());
  for (std::size_t k = 0; k < out.radius.size(); ++k) {
    if (k > 0 && !(out.radius[k] > out.radius[k - 1]))
      r.fail_item("radius", k,
                  "the step radii must increase: " + number_text(out.radius[k]) + " follows " +
                      number_text(out.radius[k - 1]),
                  "list the radii from the innermost step outwards, each larger than the one before");
    if (out.energy[k] == 0)
      r.fail_item("energy", k, "a step of energy 0 changes nothing", "remove that step, or give it a non-zero energy");
  }
  return out;
}

// Steps between two species (empty names: the default for every pair), at most one entry per pair.
std::string steps_pair_text(const PairSteps& st) {
  return st.a.empty() ? std::string("every pair (no species given)") : "[\"" + st.a + "\", \"" + st.b + "\"]";
}
bool same_steps_pair(const PairSteps& x, const PairSteps& y) {
  return (x.a == y.a && x.b == y.b) || (x.a == y.b && x.b == y.a);
}

PhysicsSpec read_physics(const Reader& top) {
  const Reader p = top.section("physics");
  p.check_keys(sections::physics);
  PhysicsSpec out;
  out.restitution = p.number("restitution", Bounds::closed(0, 1), kXiFix).value_or(1);
  read_wall_restitution(p, out);
  out.tc = p.number("tc", Bounds::non_negative(), "use 0 (TC model off) or a positive time").value_or(0);
  if (const auto g = p.numbers("gravity", 2, "[gx, gy]", Bounds::any())) out.gravity = {(*g)[0], (*g)[1]};
  out.roughness = p.number("roughness", Bounds::closed(-1, 1), kBetaFix).value_or(-1);
  out.wall_roughness = p.number("wall_roughness", Bounds::closed(-1, 1), kBetaFix).value_or(-1);
  if (const toml::array* list = p.array("pairs"))
    for (std::size_t i = 0; i < list->size(); ++i) {
      const PairRestitution pair = read_pair(*list->get(i), i, p, out.restitution);
      for (std::size_t k = 0; k < out.pairs.size(); ++k) {
        const PairRestitution& q = out.pairs[k];
        if ((q.a == pair.a && q.b == pair.b) || (q.a == pair.b && q.b == pair.a))
          p.fail_item("pairs", i,
                      "the pair [\"" + pair.a + "\", \"" + pair.b + "\"] was already given by physics.pairs[" +
                          std::to_string(k) + "]; one would silently override the other",
                      "keep one [[physics.pairs]] entry per pair of species");
      }
      out.pairs.push_back(pair);
    }
  if (const toml::array* list = p.array("steps"))
    for (std::size_t i = 0; i < list->size(); ++i) {
      PairSteps st = read_steps(*list->get(i), i, p);
      for (std::size_t k = 0; k < out.steps.size(); ++k)
        if (same_steps_pair(out.steps[k], st))
          p.fail_item("steps", i,
                      "the steps of " + steps_pair_text(st) + " were already given by physics.steps[" +
                          std::to_string(k) + "]; one would silently override the other",
                      "keep one [[physics.steps]] entry per pair of species");
      out.steps.push_back(std::move(st));
    }
  return out;
}

// [walls]: straight wall segments inside the box. [[walls.segments]] from = [x, y], to = [x, y],
// restitution = 1 (the default); [[walls.polygons]] points = [[x, y], ...] (at least 2), closed = true
// (the default: the last point joins the first), restitution: one segment per side, in order.
void check_segment_ends(const Reader& r, std::string_view key, const SegmentSpec& s, const Scene& scene) {
  for (const auto& p : {s.from, s.to})
    if (p[0] < 0 || p[0] > scene.lx || p[1] < 0 || p[1] > scene.ly)
      r.fail(key, "the point (" + number_text(p[0]) + ", " + number_text(p[1]) + ") lies outside the box [0, " +
                      number_text(scene.lx) + "] x [0, " + number_text(scene.ly) + "]",
             "move it inside the box (the box's own sides are walls already)");
  if (s.from == s.to)
    r.fail(key, "a segment of zero length (both ends at (" + number_text(s.from[0]) + ", " + number_text(s.from[1]) + "))",
           "give two different end points, or remove the segment");
}

SegmentSpec read_segment(const toml::node& node, std::size_t i, const Reader& w, const Scene& scene) {
  const std::string path = "walls.segments[" + std::to_string(i) + "]";
  const toml::table* table = node.as_table();
  if (!table) w.fail_node(&node, path, "expected a table", "write each segment as a [[walls.segments]] table");
  const Reader r(*table, path, w.origin());
  r.check_keys(sections::segment);
  SegmentSpec s;
  const auto from = r.numbers("from", 2, "[x, y]", Bounds::any());
  if (!from) missing(r, "from", "a segment needs its two end points", "from = [0.5, 0.0]");
  const auto to = r.numbers("to", 2, "[x, y]", Bounds::any());
  if (!to) missing(r, "to", "a segment needs its two end points", "to = [0.5, 1.0]");
  s.from = {(*from)[0], (*from)[1]};
  s.to = {(*to)[0], (*to)[1]};
  s.restitution = r.number("restitution", Bounds::closed(0, 1), kXiFix).value_or(1);
  check_segment_ends(r, "to", s, scene);
  return s;
}

void read_polygon(const toml::node& node, std::size_t i, const Reader& w, Scene& scene) {
  const std::string path = "walls.polygons[" + std::to_string(i) + "]";
  const toml::table* table = node.as_table();
  if (!table) w.fail_node(&node, path, "expected a table", "write each polygon as a [[walls.polygons]] table");
  const Reader r(*table, path, w.origin());
  r.check_keys(sections::polygon);
  const auto points = r.pairs("points", "[x, y]");
  if (!points) missing(r, "points", "a polygon needs its corners", "points = [[0.2, 0.2], [0.8, 0.2], [0.5, 0.8]]");
  if (points->size() < 2) r.fail("points", "a polygon needs at least two points", "give two or more [x, y] points");
  const bool closed = r.has("closed") ? [&] {
    const toml::node* c = r.get("closed");
    if (!c->is_boolean()) r.fail("closed", "expected true or false", "write closed = true or closed = false");
    return c->value<bool>().value_or(true);
  }() : true;
  const double xi = r.number("restitution", Bounds::closed(0, 1), kXiFix).value_or(1);
  const std::size_t n = points->size(), sides = closed && n > 2 ? n : n - 1;
  for (std::size_t k = 0; k < sides; ++k) {
    SegmentSpec s;
    s.from = (*points)[k];
    s.to = (*points)[(k + 1) % n];
    s.restitution = xi;
    check_segment_ends(r, "points", s, scene);
    scene.physics.segments.push_back(s);
  }
}

void read_walls(const Reader& top, Scene& scene) {
  if (!top.has("walls")) return;
  const Reader w = top.section("walls");
  w.check_keys(sections::walls);
  if (const toml::array* list = w.array("segments"))
    for (std::size_t i = 0; i < list->size(); ++i) scene.physics.segments.push_back(read_segment(*list->get(i), i, w, scene));
  if (const toml::array* list = w.array("polygons"))
    for (std::size_t i = 0; i < list->size(); ++i) read_polygon(*list->get(i), i, w, scene);
  if (scene.physics.segments.empty()) return;
  if (scene.boundary == BoundaryKind::Periodic)
    w.fail_here("wall segments need box.boundary = \"walls\" (a segment across a periodic edge has no defined image)",
                "use box.boundary = \"walls\", or remove [walls]");
  if (scene.physics.has_gravity())
    w.fail_here("wall segments with gravity are not supported yet (a parabola against a slanted segment needs a "
                "quartic root the engine does not solve)",
                "remove physics.gravity, or the segments");
}

void read_engine(const Reader& top, Scene& scene) {
  const Reader e = top.section("engine");
  e.check_keys(sections::engine);
  switch (e.choice("scalar", {"float", "double", "long double", "long_double", "float128"}).value_or(1)) {
    case 0: scene.scalar = ScalarKind::Float; break;
    case 1: scene.scalar = ScalarKind::Double; break;
    case 4: scene.scalar = ScalarKind::Float128; break;
    default: scene.scalar = ScalarKind::LongDouble; break;
  }
#if !EDE_HAVE_FLOAT128
  if (scene.scalar == ScalarKind::Float128)
    e.fail("scalar", "this ede was built without the __float128 engine (EDE_FLOAT128 off, or a compiler without "
                     "GCC's libquadmath, such as Clang)",
           "use \"long double\", or build with GCC and -DEDE_FLOAT128=ON");
#endif
  scene.rebuild_interval = static_cast<std::uint64_t>(e.integer("rebuild_interval", 0).value_or(0));
}

LogSpec read_log(const Reader& top) {
  const Reader l = top.section("log");
  l.check_keys(sections::log);
  LogSpec out;
  if (const auto k = l.integer("keyframe_interval", 1)) out.keyframe_interval = static_cast<std::uint64_t>(*k);
  if (const auto c = l.integer("chunk_events", 16, 1 << 24)) out.chunk_events = static_cast<std::uint32_t>(*c);
  if (const auto z = l.integer("compression_level", 1, 22)) out.compression_level = static_cast<int>(*z);
  return out;
}

// Letters of any script (a non-ASCII byte: toml++ has checked the string is UTF-8, and names go to CSV
// and the log as UTF-8 unchanged), digits, '_' and '-'.
bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         static_cast<unsigned char>(c) >= 0x80;
}

std::string read_name(const Reader& sp) {
  const std::optional<std::string> name = sp.string("name");
  if (!name) missing(sp, "name", "every species needs a name", "name = \"gas\"");
  if (name->empty()) sp.fail("name", "the name is empty", "give a name such as \"gas\"");
  for (char c : *name) {
    if (!is_name_char(c)) {
      sp.fail("name",
              "invalid character " + user_quoted(std::string(1, c)) + " in the name " + user_quoted(*name),
              "use letters (of any script), digits, '_' and '-' only");
    }
  }
  return *name;
}

// "species 'gas'" for messages about a species, once its name is known to be a good one.
std::string species_label(const toml::table& species) {
  const toml::node* node = species.get("name");
  const std::string_view name = node && node->is_string() ? std::string_view(node->as_string()->get()) : "";
  if (name.empty() || !std::all_of(name.begin(), name.end(), is_name_char)) return {};
  return "species '" + std::string(name) + "'";
}

Region read_region(const Reader& p, const Scene& scene) {
  const auto v = p.numbers("region", 4, "[x0, y0, x1, y1]", Bounds::any());
  if (!v) return Region{0, 0, scene.lx, scene.ly};
  const Region r{(*v)[0], (*v)[1], (*v)[2], (*v)[3]};
  if (!(r.x0 < r.x1 && r.y0 < r.y1)) {
    p.fail("region", "the region " + region_text(r) + " is empty (x0 < x1 and y0 < y1 are needed)",
           "write [x0, y0, x1, y1] with the lower-left corner first");
  }
  if (r.x0 < 0 || r.y0 < 0 || r.x1 > scene.lx || r.y1 > scene.ly) {
    p.fail("region",
           "the region " + region_text(r) + " is outside the box " + region_text({0, 0, scene.lx, scene.ly}),
           "keep the region inside the box, or enlarge box.size");
  }
  return r;
}

PlacementSpec read_placement(const Reader& sp, const Scene& scene) {
  constexpr std::string_view kNames[] = {"random", "lattice", "explicit"};
  constexpr PlacementKind kKinds[] = {PlacementKind::Random, PlacementKind::Lattice, PlacementKind::Explicit};
  const Reader p = sp.section("placement");
  p.check_keys(sections::placement);
  const std::size_t k = p.choice("kind", {kNames[0], kNames[1], kNames[2]}).value_or(0);
  reject_unless(p, "region", k != 2, kNames[k], "\"random\" and \"lattice\"");
  reject_unless(p, "packing_fraction", k != 2, kNames[k], "\"random\" and \"lattice\"");
  reject_unless(p, "lattice", k == 1, kNames[k], "\"lattice\"");
  reject_unless(p, "sampling", k == 0, kNames[k], "\"random\"");
  reject_unless(p, "positions", k == 2, kNames[k], "\"explicit\"");
  PlacementSpec out;
  out.kind = kKinds[k];
  out.region = read_region(p, scene);
  out.packing_fraction = p.number("packing_fraction", Bounds{0, kMaxPacking, true, false},
                                  "use a fraction of the region's area in (0, 0.9069]");
  out.lattice = p.choice("lattice", {"hexagonal", "square"}).value_or(0) == 0 ? LatticeKind::Hexagonal
                                                                              : LatticeKind::Square;
  out.sampling = p.choice("sampling", {"region", "free-voxels"}).value_or(0) == 0 ? RandomSampling::Region
                                                                                  : RandomSampling::FreeVoxels;
  if (out.kind == PlacementKind::Explicit) {
    auto positions = p.pairs("positions", "[x, y]");
    if (!positions) {
      missing(p, "positions", "kind = \"explicit\" needs the disks' positions", "positions = [[0.5, 0.5]]");
    }
    if (positions->empty()) p.fail("positions", "the list is empty", "give at least one [x, y]");
    out.positions = std::move(*positions);
  }
  return out;
}

std::int64_t read_count(const Reader& sp, const PlacementSpec& placement) {
  const std::optional<std::int64_t> count = sp.integer("count", 1);
  if (placement.kind != PlacementKind::Explicit) {
    if (!count) missing(sp, "count", "the number of disks is required", "count = 1000");
    return *count;
  }
  const auto listed = static_cast<std::int64_t>(placement.positions.size());
  if (count && *count != listed) {
    sp.fail("count",
            "count = " + std::to_string(*count) + " but placement.positions lists " + std::to_string(listed) +
                " disks",
            "make them equal, or remove count (it defaults to the number of positions)");
  }
  return listed;
}

RadiusSpec read_radius_range(const Reader& r) {
  r.check_keys(sections::radius);
  const std::string_view fix = "give a positive radius in box units";
  const auto lo = r.number("min", Bounds::positive(), fix);
  const auto hi = r.number("max", Bounds::positive(), fix);
  if (!lo) missing(r, "min", "a radius range needs min and max", "min = 0.004");
  if (!hi) missing(r, "max", "a radius range needs min and max", "max = 0.006");
  if (*lo > *hi) {
    r.fail("max", "max = " + number_text(*hi) + " is less than min = " + number_text(*lo),
           "swap them, or make max >= min");
  }
  return {*lo, *hi, false};
}

RadiusSpec read_radius(const Reader& sp, const PlacementSpec& placement) {
  const toml::node* node = sp.get("radius");
  if (placement.packing_fraction) {
    if (node) {
      sp.fail("radius",
              "radius and placement.packing_fraction are both given; the packing fraction sets the radius",
              "remove one of them");
    }
    return {0, 0, true};
  }
  if (!node) {
    missing(sp, "radius", "the disks need a radius",
            "radius = 0.005, radius = { min = 0.004, max = 0.006 }, or placement.packing_fraction");
  }
  if (node->is_table()) return read_radius_range(sp.section("radius"));
  const double r =
      *sp.number("radius", Bounds::positive(), "give a positive radius in box units, e.g. 0.005");
  return {r, r, false};
}

MassSpec read_mass(const Reader& sp) {
  const auto mass = sp.number("mass", Bounds::positive(), "give a positive mass, e.g. 1.0");
  const auto density = sp.number("density", Bounds::positive(), "give a positive areal density, e.g. 1.0");
  if (mass && density) {
    sp.fail("density", "both mass and density are given",
            "keep mass (the same for every disk) or density (mass = density * pi * r^2), not both");
  }
  if (density) return {MassSpec::Kind::PerArea, *density};
  return {MassSpec::Kind::Fixed, mass.value_or(1)};
}

void read_velocity_values(const Reader& v, VelocitySpec& out, std::int64_t count) {
  switch (out.kind) {
    case VelocityKind::Zero: return;
    case VelocityKind::Speed:
      if (!v.has("speed")) missing(v, "speed", "kind = \"speed\" needs the speed", "speed = 1.0");
      out.speed = *v.number("speed", Bounds::non_negative());
      return;
    case VelocityKind::Vector: {
      const auto vec = v.numbers("vector", 2, "[vx, vy]", Bounds::any());
      if (!vec) missing(v, "vector", "kind = \"vector\" needs the velocity", "vector = [0.0, -5.0]");
      out.vector = {(*vec)[0], (*vec)[1]};
      return;
    }
    case VelocityKind::Maxwell:
      if (!v.has("temperature")) {
        missing(v, "temperature", "kind = \"maxwell\" needs the temperature kT", "temperature = 1.0");
      }
      out.temperature = *v.number("temperature", Bounds::positive());
      return;
    case VelocityKind::List: {
      auto list = v.pairs("values", "[vx, vy]");
      if (!list) missing(v, "values", "kind = \"list\" needs one [vx, vy] per disk", "values = [[1.0, 0.0]]");
      if (static_cast<std::int64_t>(list->size()) != count) {
        v.fail("values",
               "lists " + std::to_string(list->size()) + " velocities but the species has " +
                   std::to_string(count) + " disks",
               "give exactly one [vx, vy] per disk");
      }
      out.list = std::move(*list);
      return;
    }
  }
}

VelocitySpec read_velocity(const Reader& sp, std::int64_t count) {
  constexpr std::string_view kNames[] = {"zero", "speed", "vector", "maxwell", "list"};
  constexpr VelocityKind kKinds[] = {VelocityKind::Zero, VelocityKind::Speed, VelocityKind::Vector,
                                     VelocityKind::Maxwell, VelocityKind::List};
  constexpr std::string_view kKeys[] = {"", "speed", "vector", "temperature", "values"};
  const Reader v = sp.section("velocity");
  v.check_keys(sections::velocity);
  const std::size_t k = v.choice("kind", {kNames[0], kNames[1], kNames[2], kNames[3], kNames[4]}).value_or(0);
  for (std::size_t other = 1; other < std::size(kKeys); ++other) {
    reject_unless(v, kKeys[other], other == k, kNames[k], "\"" + std::string(kNames[other]) + "\"");
  }
  VelocitySpec out;
  out.kind = kKinds[k];
  read_velocity_values(v, out, count);
  return out;
}

// Rough disks: inertia_factor (I = f m r^2, default 0.5, a uniform disk), and the initial angular
// velocity: omega = w for every disk, or spin_temperature = kT (omega ~ N(0, kT / I) per disk), not both.
void read_rotation(const Reader& sp, SpeciesSpec& s) {
  s.inertia_factor = sp.number("inertia_factor", Bounds::positive(),
                               "give a positive factor f of I = f m r^2, e.g. 0.5 (a uniform disk) or 1 (a ring)")
                         .value_or(0.5);
  const auto omega = sp.number("omega", Bounds::any());
  const auto kt = sp.number("spin_temperature", Bounds::non_negative(), "give kT >= 0 of the rotation, e.g. 1.0");
  if (omega && kt)
    sp.fail("spin_temperature", "both omega and spin_temperature are given",
            "keep omega (the same angular velocity for every disk) or spin_temperature (drawn per disk), not both");
  if (omega) s.spin = {SpinSpec::Kind::Value, *omega, 0};
  if (kt) s.spin = {SpinSpec::Kind::Maxwell, 0, *kt};
}

// The Andersen thermostat: [thermostat] (every species, or those in `species`) or [species.thermostat] (one
// species, overriding [thermostat] for it; rate = 0 leaves it out). Both need kT > 0 and the rate.
std::optional<ThermostatSpec> read_thermostat(const Reader& parent, bool of_species) {
  if (!parent.has("thermostat")) return std::nullopt;
  if (!parent.get("thermostat")->is_table())
    parent.fail("thermostat", "expected a table", of_species ? "write [species.thermostat] with temperature and rate"
                                                             : "write [thermostat] with temperature and rate");
  const Reader t = parent.section("thermostat");
  t.check_keys(of_species ? sections::species_thermostat : sections::thermostat);
  ThermostatSpec out;
  const auto kt = t.number("temperature", Bounds::positive(), "give kT > 0, e.g. temperature = 1.0");
  if (!kt) missing(t, "temperature", "the thermostat's kT", "temperature = 1.0");
  const auto rate = t.number("rate", of_species ? Bounds::non_negative() : Bounds::positive(),
                             of_species ? "give the redraws per disk per unit time, >= 0 (0: not thermostatted)"
                                        : "give the redraws per disk per unit time, > 0, e.g. rate = 0.1");
  if (!rate) missing(t, "rate", "how often each disk's velocity is redrawn (per disk, per unit time)", "rate = 0.1");
  out.temperature = *kt;
  out.rate = *rate;
  if (const toml::array* names = t.array("species")) {
    for (std::size_t i = 0; i < names->size(); ++i) {
      const auto name = names->get(i)->value<std::string>();
      if (!name) t.fail_item("species", i, "expected a species name", "write species = [\"gas\"]");
      out.species.push_back(*name);
    }
    if (out.species.empty()) t.fail("species", "an empty list covers no disk", "list species, or leave the key out (every species)");
  }
  return out;
}

// Explicit positions: the centre inside the box, and with walls at least the smallest radius from them.
void check_positions(const Reader& sp, const SpeciesSpec& s, const Scene& scene) {
  const Reader p = sp.section("placement");
  const double margin = scene.boundary == BoundaryKind::Walls ? s.radius.min : 0;
  for (std::size_t i = 0; i < s.placement.positions.size(); ++i) {
    const auto [x, y] = s.placement.positions[i];
    const bool inside = x >= margin && y >= margin && x <= scene.lx - margin && y <= scene.ly - margin;
    if (inside) continue;
    p.fail_item("positions", i,
                "[" + number_text(x) + ", " + number_text(y) + "] puts the disk (radius " +
                    number_text(s.radius.min) + ") outside the box " +
                    region_text({0, 0, scene.lx, scene.ly}),
                "move it inside; with walls, keep the centre at least one radius from each wall");
  }
}

void check_unique_name(const Reader& sp, const std::string& name, const std::vector<SpeciesSpec>& earlier) {
  for (std::size_t j = 0; j < earlier.size(); ++j) {
    if (earlier[j].name != name) continue;
    sp.fail(
        "name",
        "duplicate species name " + user_quoted(name) + " (species[" + std::to_string(j) + "] has it too)",
        "give every species its own name");
  }
}

void check_total(const Reader& sp, std::int64_t count, const std::vector<SpeciesSpec>& earlier) {
  std::int64_t total = 0;
  for (const SpeciesSpec& e : earlier) total += e.count;  // each partial total is <= kMaxDisks: no overflow
  if (count <= kMaxDisks - total) return;
  const auto sum = static_cast<std::uint64_t>(total) + static_cast<std::uint64_t>(count);  // < 2^64
  sp.fail("count",
          "the scene would hold " + std::to_string(sum) + " disks in all, more than the limit of " +
              std::to_string(kMaxDisks),
          "use fewer disks: each costs a few hundred bytes, so 10^8 disks already need tens of GB of memory");
}

SourceSpot spot_of(const toml::node& node) {
  return {std::uint32_t(node.source().begin.line), std::uint32_t(node.source().begin.column)};
}

// Where setup's errors about this species point (SpeciesSpec::spot and the rest).
void record_spots(const toml::table& table, SpeciesSpec& s) {
  s.spot = spot_of(table);
  const toml::node* count = table.get("count");
  s.count_spot = count ? spot_of(*count) : s.spot;
  const toml::node* placement = table.get("placement");
  const toml::node* positions = placement && placement->is_table() ? placement->as_table()->get("positions") : nullptr;
  if (positions && positions->is_array())
    for (const toml::node& p : *positions->as_array()) s.position_spots.push_back(spot_of(p));
}

SpeciesSpec read_species(const toml::node& node, std::size_t i, const Reader& top, const Scene& scene) {
  const std::string path = "species[" + std::to_string(i) + "]";
  const toml::table* table = node.as_table();
  if (!table) {
    top.fail_node(&node, path, "expected a table, got " + describe(node),
                  "write each species as a [[species]] table");
  }
  const Reader sp(*table, path, top.origin(), species_label(*table));
  sp.check_keys(sections::species);
  SpeciesSpec s;
  s.name = read_name(sp);
  check_unique_name(sp, s.name, scene.species);
  s.placement = read_placement(sp, scene);
  s.count = read_count(sp, s.placement);
  check_total(sp, s.count, scene.species);
  s.radius = read_radius(sp, s.placement);
  s.mass = read_mass(sp);
  s.velocity = read_velocity(sp, s.count);
  read_rotation(sp, s);
  s.thermostat = read_thermostat(sp, true);
  if (s.placement.kind == PlacementKind::Explicit) check_positions(sp, s, scene);
  record_spots(*table, s);
  return s;
}

void read_all_species(const Reader& top, Scene& scene) {
  const toml::node* node = top.get("species");
  if (node && node->is_table()) {
    top.fail("species", "expected an array of tables, got a table", "write [[species]] with double brackets");
  }
  const toml::array* list = top.array("species");
  if (!list || list->empty()) {
    top.fail("species", "the scene has no species",
             "add a [[species]] table with a name, a count and a radius");
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    scene.species.push_back(read_species(*list->get(i), i, top, scene));
  }
}

// [grow]: a target packing fraction, a pressure (jamming), or both (whichever comes first). Only a bound
// that no arrangement of these radii could exceed is refused here; setup knows the radii and says more.
std::optional<GrowSpec> read_grow(const Reader& top, const Scene& scene) {
  if (!top.has("grow")) return std::nullopt;
  const Reader g = top.section("grow");
  g.check_keys(sections::grow);
  if (scene.start)
    top.fail("grow", "a scene with [start] takes its disks as they are from the state, so there is nothing to grow",
             "remove [grow], or replace [start] by [[species]]");
  GrowSpec out;
  out.packing_fraction = g.number("packing_fraction", Bounds::open(0, 1),
                                  "give the packing fraction to grow to, e.g. packing_fraction = 0.72");
  // Z above ~1e12 would need gaps below double's resolution near jamming: the growth could not end.
  out.pressure = g.number("pressure", Bounds{1, 1e12, true, false},
                          "give the reduced pressure Z = PA/(NkT) at which the disks count as jammed, e.g. 1e6");
  // Slower than 1e-5 needs ~10^6 collisions per disk and more: hours for 10^4 disks.
  out.rate = g.number("rate", Bounds{1e-5, 1, false, true}, "give a growth rate such as 1e-2 (fast) or 1e-4 (slow)")
                 .value_or(out.rate);
  if (!out.packing_fraction && !out.pressure)
    g.fail_here("neither packing_fraction nor pressure is given, so the growth would never stop",
                "add packing_fraction = 0.72 (a target) or pressure = 1e6 (grow until jammed), or both");
  return out;
}

StopSpec read_stop(const Reader& top) {
  const Reader s = top.section("stop");
  s.check_keys(sections::stop);
  StopSpec out;
  out.time = s.number("time", Bounds::positive());
  if (const auto events = s.integer("events", 1)) out.events = static_cast<std::uint64_t>(*events);
  out.collisions_per_particle = s.number("collisions_per_particle", Bounds::positive());
  out.energy_fraction = s.number("energy_fraction", Bounds::open(0, 1));
  if (!out.time && !out.events && !out.collisions_per_particle && !out.energy_fraction) {
    s.fail_here("no stop condition, so the run would never end",
                "add [stop] with time = 10.0, events = 1000000, collisions_per_particle = 50 or "
                "energy_fraction = 0.1");
  }
  return out;
}

// interval (a time) or collisions_per_disk (2 P / N between samples), not both.
void read_sampling(const Reader& top, Scene& scene) {
  const Reader s = top.section("sampling");
  s.check_keys(sections::sampling);
  scene.sample_interval = s.number("interval", Bounds::positive(), "give a positive time between samples, e.g. 0.1");
  scene.sample_collisions =
      s.number("collisions_per_disk", Bounds::positive(), "give a positive number of collisions per disk, e.g. 5");
  if (scene.sample_interval && scene.sample_collisions)
    s.fail("collisions_per_disk", "given with interval: samples are taken by time or by collisions per disk",
           "keep one of interval and collisions_per_disk");
}

ActionSpec read_action(const toml::node& node, std::size_t i, const Reader& top) {
  const std::string path = "actions[" + std::to_string(i) + "]";
  const toml::table* table = node.as_table();
  if (!table) {
    top.fail_node(&node, path, "expected a table, got " + describe(node),
                  "write each action as an [[actions]] table");
  }
  const Reader a(*table, path, top.origin());
  a.check_keys(sections::action);
  const auto time = a.number("time", Bounds::positive());
  const auto collisions = a.number("collisions_per_disk", Bounds::positive(), "give a positive number, e.g. 50");
  if (!time && !collisions)
    missing(a, "time", "an action needs the time (or the collisions per disk) at which it happens",
            "time = 5.0 (or collisions_per_disk = 50)");
  if (time && collisions)
    a.fail("collisions_per_disk", "given with time: an action happens at a time or after a number of collisions per disk",
           "keep one of time and collisions_per_disk");
  if (!a.choice("kind", {"reverse_velocities"})) {
    missing(a, "kind", "an action needs a kind", "kind = \"reverse_velocities\"");
  }
  return {time.value_or(0), ActionKind::ReverseVelocities, collisions};
}

// Time actions in time order, or collision actions in the order of their collisions per disk; a scene
// mixing both is refused (their relative order would depend on the run).
std::vector<ActionSpec> read_actions(const Reader& top) {
  std::vector<ActionSpec> out;
  if (const toml::array* list = top.array("actions")) {
    for (std::size_t i = 0; i < list->size(); ++i) out.push_back(read_action(*list->get(i), i, top));
    for (std::size_t i = 1; i < out.size(); ++i)
      if (out[i].collisions_per_disk.has_value() != out[0].collisions_per_disk.has_value())
        top.fail_node(list->get(i), "actions[" + std::to_string(i) + "]",
                      "mixes an action by collisions per disk with one by time (actions[0]): their order would depend on the run",
                      "give every action a time, or every action a collisions_per_disk");
  }
  const auto when = [](const ActionSpec& a) { return a.collisions_per_disk.value_or(a.time); };
  std::stable_sort(out.begin(), out.end(), [&](const ActionSpec& a, const ActionSpec& b) { return when(a) < when(b); });
  return out;
}

// No collision of this scene can lose energy (walls do not count in a periodic box).
bool elastic_in_effect(const Scene& scene) {
  const PhysicsSpec& ph = scene.physics;
  bool all = ph.restitution == 1;
  for (const PairRestitution& p : ph.pairs) all = all && p.value == 1;
  if (scene.boundary == BoundaryKind::Walls)
    for (int w = 0; w < 4; ++w) all = all && ph.wall(w) == 1;
  for (const SegmentSpec& s : ph.segments) all = all && s.restitution == 1;
  const auto keeps_energy = [](double beta) { return beta == -1 || beta == 1; };  // smooth, or perfectly rough
  all = all && keeps_energy(ph.roughness);
  for (const PairRestitution& p : ph.pairs) all = all && keeps_energy(ph.pair_roughness(p));
  if (scene.boundary == BoundaryKind::Walls) all = all && keeps_energy(ph.wall_roughness);
  return all;
}

// A species name in `key` of table r (a pair's, the thermostat's) is one of the scene's species.
void check_species_named(const Reader& r, std::string_view key, const std::string& name, const Scene& scene) {
  bool found = false;
  for (const SpeciesSpec& sp : scene.species) found = found || sp.name == name;
  if (found) return;
  std::string known;
  for (const SpeciesSpec& sp : scene.species) known += (known.empty() ? "" : ", ") + sp.name;
  r.fail(key, "there is no species '" + name + "'", "use the names of the species: " + known);
}

// The thermostat names real species and runs in the engines that have it: no gravity, segments or rotation.
void check_thermostat(const Reader& top, const Scene& scene) {
  if (!scene.thermostatted()) return;
  const Reader t = top.section("thermostat");
  if (scene.physics.thermostat && !scene.start)
    for (const std::string& name : scene.physics.thermostat->species) check_species_named(t, "species", name, scene);
  const auto refuse = [&](std::string_view what) {
    const std::string w(what);
    if (scene.physics.thermostat)
      t.fail_here("the thermostat with " + w + " is not supported yet", "remove the thermostat, or the " + w);
    top.fail("species", "a species' thermostat with " + w + " is not supported yet",
             "remove [species.thermostat], or the " + w);
  };
  if (scene.physics.has_gravity()) refuse("gravity");
  if (!scene.physics.segments.empty()) refuse("wall segments");
  if (scene.rotates()) refuse("rough or spinning disks");
  // The stepped engines have no thermostat clock and the thermostat engines no step table; combining the two
  // axes would double the engine table's thermostat rows for a case no issue asks for yet.
  if (scene.physics.has_steps()) refuse("square wells or shoulders ([[physics.steps]])");
}

// A Lees-Edwards box runs in one engine (the sheared one: smooth hard disks; restitution, the TC model and
// the thermostat, which draws about the flow, allowed); what that engine does not have is refused here,
// each with its reason. Gravity and wall segments are refused for every periodic box already
// (check_physics, read_walls).
void check_shear(const Reader& top, const Scene& scene) {
  if (!scene.sheared()) return;
  const Reader box = top.section("box");
  const auto refuse = [&](std::string_view what, std::string_view fix) {
    box.fail("boundary", "a Lees-Edwards box with " + std::string(what) + " is not supported yet", fix);
  };
  if (scene.rotates()) refuse("rough or spinning disks", "make the disks smooth (physics.roughness = -1, no species omega)");
  if (scene.physics.has_steps()) refuse("square wells or shoulders", "remove [[physics.steps]]");
  if (!scene.actions.empty())
    refuse("actions (time reversal does not retrace a sheared run: the images keep sliding the same way)",
           "remove the [[actions]]");
}

// [[physics.steps]]: real species, steps outside the hard core of the pair they act on, and not with the
// effects the stepped engines do not have (rough disks, wall segments).
void check_steps(const Reader& p, const Scene& scene) {
  const PhysicsSpec& ph = scene.physics;
  if (!ph.has_steps()) return;
  if (scene.rotates())
    p.fail("steps", "square wells and shoulders with rough or spinning disks are not supported yet",
           "make the disks smooth (physics.roughness = -1, no species omega), or remove [[physics.steps]]");
  if (!ph.segments.empty())
    p.fail("steps", "square wells and shoulders with wall segments are not supported yet",
           "remove the [walls] segments, or remove [[physics.steps]]");
  if (scene.start) return;  // the species come from the start state: the engine checks the radii
  const auto species = [&](const std::string& name) -> const SpeciesSpec* {
    for (const SpeciesSpec& sp : scene.species)
      if (sp.name == name) return &sp;
    return nullptr;
  };
  std::string known;
  for (const SpeciesSpec& sp : scene.species) known += (known.empty() ? "" : ", ") + sp.name;
  for (std::size_t i = 0; i < ph.steps.size(); ++i) {
    const PairSteps& st = ph.steps[i];
    for (const std::string& name : {st.a, st.b})
      if (!st.a.empty() && !species(name))
        p.fail_item("steps", i, "there is no species '" + name + "'", "use the names of the species: " + known);
    double contact = 0;  // the largest contact distance of the pairs these steps act on
    for (const SpeciesSpec& x : scene.species)
      for (const SpeciesSpec& y : scene.species) {
        const bool named = (x.name == st.a && y.name == st.b) || (x.name == st.b && y.name == st.a);
        if ((st.a.empty() || named) && !x.radius.from_packing && !y.radius.from_packing)
          contact = std::max(contact, x.radius.max + y.radius.max);
      }
    if (!(st.radius.front() > contact))
      p.fail_item("steps", i,
                  "the innermost step (radius " + number_text(st.radius.front()) +
                      ") lies inside the hard core: the disks touch at a distance of " + number_text(contact),
                  "give step radii larger than the sum of the two species' radii (distances between centres)");
  }
}

// Rules that span tables: pair restitution names real species; gravity needs walls (in a periodic box
// everything would fall forever) and cannot stop on kinetic energy (it changes between collisions).
void check_physics(const Reader& top, const Scene& scene) {
  const Reader p = top.section("physics");
  for (const PairRestitution& pair : scene.start ? std::vector<PairRestitution>{} : scene.physics.pairs)
    for (const std::string& name : {pair.a, pair.b}) check_species_named(p, "pairs", name, scene);
  check_steps(p, scene);
  if (scene.physics.has_gravity() && scene.boundary == BoundaryKind::Periodic)
    p.fail("gravity", "gravity needs walls: in a periodic box every disk would fall forever",
           "use box.boundary = \"walls\", or remove gravity");
  if (scene.physics.has_gravity() && scene.stop.energy_fraction)
    top.section("stop").fail("energy_fraction",
                             "with gravity the kinetic energy changes between collisions, so it cannot stop a run",
                             "stop on time (stop.time) or on events");
  if (scene.rotates() && scene.physics.has_gravity())
    p.fail("gravity", "rough or spinning disks under gravity are not supported yet",
           "remove gravity, or make the disks smooth (physics.roughness = -1, no species omega)");
  if (scene.rotates() && !scene.physics.segments.empty())
    p.fail("roughness", "rough or spinning disks with wall segments are not supported yet",
           "remove the [walls] segments, or make the disks smooth (physics.roughness = -1, no species omega)");
  check_thermostat(top, scene);
  check_shear(top, scene);
  const StopSpec& st = scene.stop;
  if (st.energy_fraction && !st.time && !st.events && !st.collisions_per_particle && elastic_in_effect(scene))
    top.section("stop").fail("energy_fraction",
                             "every collision is elastic (restitution 1 for pairs and walls), so the kinetic energy "
                             "never falls and the run would never end",
                             "make the collisions inelastic (physics.restitution < 1), or stop on time or events");
}

Scene scene_from_tree(const toml::table& root, const Origin& origin) {
  const Reader top(root, "", origin);
  top.check_keys(sections::root);
  Scene scene;
  scene.seed = static_cast<std::uint64_t>(top.integer("seed", 0).value_or(1));
  read_box(top, scene);
  scene.physics = read_physics(top);
  scene.physics.thermostat = read_thermostat(top, false);
  read_walls(top, scene);
  read_engine(top, scene);
  scene.log = read_log(top);
  scene.start = read_start(top);
  if (!scene.start) read_all_species(top, scene);
  scene.grow = read_grow(top, scene);
  scene.stop = read_stop(top);
  read_sampling(top, scene);
  scene.actions = read_actions(top);
  check_physics(top, scene);
  return scene;
}

// The tree as TOML, headed by comments saying where it came from; it reads back to the same Scene.
std::string effective_text(const toml::table& root, const Origin& origin) {
  std::ostringstream out;
  out << "# effective scene: " << user_quoted(scene_label(origin.source_name)) << "\n";
  for (const AppliedOverride& o : origin.overrides) {
    out << "# --set #" << o.number << " " << user_quoted(o.text) << "\n";
  }
  out << to_toml(root);
  return out.str();
}

std::string syntax_message(const toml::parse_error& e, const std::string& source_name) {
  const toml::source_position at = e.source().begin;
  std::string where = source_name;
  if (at.line > 0) where += ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
  return where + ": error: TOML syntax: " + std::string(e.description()) +
         ". Fix: correct the TOML at this position (the format is described in docs/scene-format.md).";
}

}  // namespace

Result<Scene> parse_scene_text(const std::string& text, const std::string& source_name,
                               const std::vector<Override>& overrides) {
  try {
    toml::table root = toml::parse(std::string_view(text), std::string_view(source_name));
    const Origin origin{source_name, apply_overrides(root, overrides, source_name)};
    Scene scene = scene_from_tree(root, origin);
    scene.source_name = source_name;
    scene.source_text = effective_text(root, origin);
    return scene;
  } catch (const toml::parse_error& e) {
    return Error{syntax_message(e, source_name)};
  } catch (const SceneError& e) {
    return Error{e.message};
  } catch (const std::exception& e) {  // std::bad_alloc on absurd input: still one message, no crash
    return Error{source_name + ": error: cannot load the scene (" + e.what() + ")."};
  }
}

// The largest scene file read: explicit positions for 10^6 disks take ~50 MB of TOML; anything past this
// is not a scene (a device, a log, a disk image) and is refused before it is read into memory.
constexpr std::uint64_t kMaxSceneBytes = std::uint64_t(64) << 20;

// The text of a scene file, refused with a message naming the file when it is not a regular file, too big,
// or binary (a NUL byte: a log, an image, an executable). Read in one bounded read, so a file that grows
// while being read (or a device that never ends) cannot take the memory.
Result<std::string> read_scene_bytes(const std::string& path) {
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(st)) {
    const bool exists = std::filesystem::exists(std::filesystem::symlink_status(path, ec));
    return Error{path + ": error: cannot " + (exists ? "read" : "find") +
                     " the scene file. Fix: check the path" + (exists ? " and the file's permissions." : "."),
                 ErrorKind::Io};
  }
  if (std::filesystem::is_directory(st))
    return Error{path + ": error: this is a directory, not a scene file. Fix: give the path of a .toml file."};
  if (!std::filesystem::is_regular_file(st))
    return Error{path + ": error: this is not a regular file (a device, a pipe or a socket), not a scene file. "
                        "Fix: save the scene to a .toml file and give its path."};
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxSceneBytes)
    return Error{path + ": error: the file has " + std::to_string(size) + " bytes, more than any scene (at most " +
                 std::to_string(kMaxSceneBytes >> 20) +
                 " MiB): is it a scene? Fix: give the .toml scene file (large explicit lists belong in fewer, "
                 "placed disks)."};
  std::ifstream in(path, std::ios::binary);
  // One byte more than the size stat gave (and never more than the limit allows): a file growing while it
  // is read is read up to there, never without bound.
  std::string text(std::size_t(std::min<std::uintmax_t>(ec ? kMaxSceneBytes : size, kMaxSceneBytes)) + 1, '\0');
  if (in) in.read(text.data(), std::streamsize(text.size()));
  if (in.bad() || (!in && !in.eof()))
    return Error{path + ": error: cannot read the scene file. Fix: check the file's permissions.", ErrorKind::Io};
  text.resize(std::size_t(in.gcount()));
  if (text.size() > kMaxSceneBytes)
    return Error{path + ": error: the file is larger than any scene (more than " + std::to_string(kMaxSceneBytes >> 20) +
                 " MiB). Fix: give the .toml scene file."};
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    return Error{path + ": error: byte " + std::to_string(nul) +
                 " is a NUL: this is a binary file (an event log? an image?), not a TOML scene. Fix: give the "
                 ".toml scene file; an event log is read by ede-replay, resumed by ede-sim --resume."};
  return text;
}

Result<Scene> load_scene_file(const std::string& path, const std::vector<Override>& overrides) {
  auto text = read_scene_bytes(path);
  if (!text) return text.error();
  return parse_scene_text(text.value(), path, overrides);
}

}  // namespace ede
