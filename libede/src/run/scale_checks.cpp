// check_scene_scales and check_state_scales; see scale_checks.hpp.
#include "run/scale_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "ede/number_text.hpp"

namespace ede {

namespace {

// A scalar type's range in powers of two: the largest finite value is just below 2^max_log2, the smallest
// normal one is 2^min_log2, eps is 2^-bits.
struct Range {
  ScalarKind kind;
  double max_log2, min_log2, bits;
};

template <class T>
Range range_of(ScalarKind kind) {
  using L = std::numeric_limits<T>;
  return {kind, double(L::max_exponent), double(L::min_exponent - 1), double(L::digits - 1)};
}

Range range(ScalarKind kind) {
  switch (kind) {
    case ScalarKind::Float: return range_of<float>(kind);
    case ScalarKind::LongDouble: return range_of<long double>(kind);
    case ScalarKind::Float128: return {kind, 16384, -16382, 112};  // IEEE binary128
    case ScalarKind::Double: break;
  }
  return range_of<double>(ScalarKind::Double);
}

// A power of two as people read it: 3 digits within double's range, a power of ten beyond.
std::string power_text(double log2_value) {
  if (std::abs(log2_value) < 1000) return general_text(std::exp2(log2_value), 3);
  return "1e" + std::to_string(std::lround(log2_value * std::log10(2.0)));
}

std::string type_text(const Range& r) { return std::string("engine.scalar = \"") + to_string(r.kind) + "\""; }
std::string largest_text(const Range& r) { return "largest " + power_text(r.max_log2); }
std::string smallest_text(const Range& r) { return "smallest normal number " + power_text(r.min_log2); }

// log2(a + b) for a, b given as log2 values.
double log2_sum(double a, double b) {
  const double hi = std::max(a, b), lo = std::min(a, b);
  return hi + std::log2(1 + std::exp2(lo - hi));
}

// The scales a run combines, as log2 values, with the words naming where each comes from.
struct Scales {
  std::string source;
  double box = 0;                      // log2 of the box's larger side
  double small = 0;                    // log2 of the smallest diameter
  std::string small_who;
  std::optional<double> speed;         // log2 of the largest speed, falling across the box included; none: at rest
  std::string speed_who;
  std::optional<double> heavy;         // log2 of the largest mass
  std::string heavy_who;
  std::optional<double> gravity;       // log2 |g|, when there is gravity
  std::optional<double> end;           // log2 of stop.time
  bool end_is_reached = false;         // stop.time is the only stop condition
};

// What does not fit, and whether changing the units (lengths, times, masses) would make it fit.
struct Misfit {
  std::string what;
  bool units = true;
  std::string fix;  // when the units do not matter: what else would
};

Misfit by_units(std::string what) {
  Misfit m;
  m.what = std::move(what);
  return m;
}

std::optional<Misfit> resolution_misfit(const Scales& s, const Range& r, std::optional<double> end) {
  double spread = s.box;  // log2 of L + 2 V t
  if (end && s.speed) spread = log2_sum(s.box, 1 + *s.speed + *end);
  if (spread - r.bits <= s.small + std::log2(kResolvedShareOfDiameter)) return std::nullopt;
  std::string what = "the position resolution eps (L + 2 V t) of a box of " + power_text(s.box);
  if (end && s.speed) what += " at speed " + power_text(*s.speed) + " when the clock reads stop.time = " + power_text(*end);
  return Misfit{what + " is " + power_text(spread - r.bits) + ", more than 1/64 of the smallest diameter (" + s.small_who +
                    "): the type no longer tells apart positions a fraction of a disk apart, and disks would overlap",
                false,
                end ? "stop earlier (a smaller stop.time), or make the smallest disks larger against the box"
                    : "make the smallest disks larger against the box"};
}

// The length checks alone: what setup (in double) and the engine both need before any speed exists.
std::optional<Misfit> length_misfit(const Scales& s, const Range& r) {
  if (2 * (s.box + 1) + 1 > r.max_log2 - 1)
    return by_units("the box's side " + power_text(s.box) + " squared (the contact test squares distances up to twice "
                  "it) overflows the type (" + largest_text(r) + "): distant pairs would get NaN contact times and "
                  "pass through each other");
  if (2 * s.small < r.min_log2 + r.bits)
    return by_units("the smallest diameter (" + s.small_who + ") squared, " + power_text(2 * s.small) +
                  ", comes within 2^" + std::to_string(int(r.bits)) + " of the type's " + smallest_text(r) +
                  ": contact distances would lose their digits to underflow and disks would overlap");
  return resolution_misfit(s, r, std::nullopt);
}

std::optional<Misfit> speed_misfit(const Scales& s, const Range& r) {
  const double v = *s.speed;
  if (2 * (v + 1) + 1 > r.max_log2 - 1 || 2 * ((s.box + 1) + (v + 1)) + 1 > r.max_log2 - 1)
    return by_units("the largest speed (" + s.speed_who + ") times the box's side " + power_text(s.box) +
                  " squared overflows the type (" + largest_text(r) +
                  "): contact times would be NaN, and disks would pass through each other");
  if (2 * (s.small + v - r.bits) < r.min_log2)
    return by_units("the smallest diameter (" + s.small_who + ") times the largest speed (" + s.speed_who + ") is " +
                  power_text(s.small + v) + ": at the approach speeds the engine resolves (eps of the largest) "
                  "the product dx.dv squared underflows the type (" + smallest_text(r) +
                  "), so approaching pairs would look receding and pass through each other");
  if (s.box - v > r.max_log2 - 1)
    return by_units("the time to cross the box, " + power_text(s.box) + " / " + power_text(v) + " (" + s.speed_who +
                  ") = " + power_text(s.box - v) + ", is beyond the type's " + largest_text(r) +
                  ": event times would be infinite, that is never, while disks move");
  if (s.small - v < r.min_log2 + r.bits)
    return by_units("the time to cross the smallest disk (" + s.small_who + ") at the largest speed (" + s.speed_who +
                  ") is " + power_text(s.small - v) + ", within 2^" + std::to_string(int(r.bits)) + " of the type's " +
                  smallest_text(r) + ": times between events would lose their digits");
  if (s.heavy && v - (*s.heavy + 1) < r.min_log2 + r.bits)
    return by_units("the impulse per unit mass between the heaviest disks (" + s.heavy_who + ") at the largest speed, " +
                  power_text(v - (*s.heavy + 1)) + ", comes within 2^" + std::to_string(int(r.bits)) +
                  " of the type's " + smallest_text(r) +
                  ": their collisions would change their velocities by nothing or by the wrong amount");
  return std::nullopt;
}

std::optional<Misfit> misfit(const Scales& s, const Range& r) {
  if (auto m = length_misfit(s, r)) return m;
  if (s.gravity && *s.gravity < r.min_log2 + r.bits)
    return by_units("gravity " + power_text(*s.gravity) + " comes within 2^" + std::to_string(int(r.bits)) +
                  " of the type's " + smallest_text(r) + ": it would be rounded away");
  if (s.end && *s.end > r.max_log2 - 1)
    return by_units("stop.time = " + power_text(*s.end) + " is beyond the type's " + largest_text(r) +
                  ": the clock would overflow before reaching it");
  if (!s.speed) return std::nullopt;
  if (auto m = speed_misfit(s, r)) return m;
  if (s.end && s.end_is_reached) return resolution_misfit(s, r, s.end);
  return std::nullopt;
}

// Setup works in double: a wider engine type still needs the lengths to fit a double.
std::optional<Misfit> misfit_in(const Scales& s, ScalarKind kind) {
  const Range r = range(kind);
  if (r.max_log2 > range(ScalarKind::Double).max_log2)
    if (auto m = length_misfit(s, range(ScalarKind::Double))) {
      m->what += " (in double, the type the disks are placed in whatever engine.scalar says)";
      return m;
    }
  return misfit(s, r);
}

Status check(const Scales& s, ScalarKind kind) {
  const auto m = misfit_in(s, kind);
  if (!m) return Ok{};
  std::optional<ScalarKind> wider;
  for (ScalarKind k : {ScalarKind::Double, ScalarKind::LongDouble})
    if (!wider && range(k).bits > range(kind).bits && !misfit_in(s, k)) wider = k;
  std::string fix;
  if (m->units)
    fix = "rescale the units so that the box, the radii, the speeds and the masses are within a few orders of "
          "magnitude of 1 (only their ratios matter to the motion)";
  else
    fix = m->fix;
  if (wider) fix += std::string(", or use engine.scalar = \"") + to_string(*wider) + "\"";
  else fix += " (no wider scalar type holds this run as it is)";
  return Error{s.source + ": with " + type_text(range(kind)) + ", " + m->what + ". Fix: " + fix + "."};
}

double log2_of(double v) { return std::log2(std::abs(v)); }

std::string disk_text(const InitialState& s, std::size_t i, const char* what, double value) {
  return "disk " + std::to_string(i) + ", species '" + s.species_name_of(i) + "', " + what + " " + general_text(value, 3);
}

void add_gravity(Scales& s, const Scene& scene, double box) {
  const double g = std::hypot(scene.physics.gravity[0], scene.physics.gravity[1]);
  if (g == 0) return;
  s.gravity = log2_of(g);
  const double falling = (1 + *s.gravity + box) / 2;  // log2 sqrt(2 g L): the speed of a fall across the box
  if (!s.speed || falling > *s.speed) {
    s.speed = falling;
    s.speed_who = "gravity " + general_text(g, 3) + " over the box: falling speed " + power_text(falling);
  }
}

}  // namespace

double scalar_epsilon(ScalarKind kind) { return std::exp2(-range(kind).bits); }
std::string largest_value_text(ScalarKind kind) { return power_text(range(kind).max_log2); }

Status check_scene_scales(const Scene& scene) {
  if (scene.species.empty()) return Ok{};  // a [start] state: its disks are checked once read
  Scales s;
  s.source = scene.source_name;
  s.box = log2_of(std::max(scene.lx, scene.ly));
  double smallest = std::numeric_limits<double>::infinity();
  for (const SpeciesSpec& sp : scene.species) {
    double r = sp.radius.min;
    if (sp.radius.from_packing && sp.placement.packing_fraction && sp.count > 0)
      r = std::sqrt(*sp.placement.packing_fraction * sp.placement.region.area() / (double(sp.count) * 3.141592653589793));
    if (r > 0 && std::isfinite(r) && r < smallest) {
      smallest = r;
      s.small_who = "species '" + sp.name + "', radius " + general_text(r, 3);
    }
  }
  if (!std::isfinite(smallest)) return Ok{};  // setup refuses such radii itself
  s.small = log2_of(2 * smallest);
  return check(s, scene.scalar);
}

Status check_state_scales(const Scene& scene, const InitialState& st) {
  if (st.size() == 0) return Ok{};
  Scales s;
  s.source = scene.source_name;
  s.box = log2_of(std::max(st.lx, st.ly));
  std::size_t small = 0, fast = 0, heavy = 0;
  double fastest = 0;
  for (std::size_t i = 0; i < st.size(); ++i) {
    if (st.radius[i] < st.radius[small]) small = i;
    if (st.mass[i] > st.mass[heavy]) heavy = i;
    const double v = std::hypot(st.vx[i], st.vy[i]);
    if (v > fastest) fastest = v, fast = i;
  }
  s.small = log2_of(2 * st.radius[small]);
  s.small_who = disk_text(st, small, "radius", st.radius[small]);
  s.heavy = log2_of(st.mass[heavy]);
  s.heavy_who = disk_text(st, heavy, "mass", st.mass[heavy]);
  if (fastest > 0) {
    s.speed = log2_of(fastest);
    s.speed_who = disk_text(st, fast, "speed", fastest);
  }
  add_gravity(s, scene, s.box);
  if (scene.stop.time) s.end = log2_of(*scene.stop.time);
  // The resolution at stop.time matters when the run goes that far; with another stop condition it may end
  // long before, and the check at its end judges the clock it reached.
  const StopSpec& stop = scene.stop;
  s.end_is_reached = stop.time && !stop.events && !stop.collisions_per_particle && !stop.energy_fraction;
  return check(s, scene.scalar);
}

}  // namespace ede
