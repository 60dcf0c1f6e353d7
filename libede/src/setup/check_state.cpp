// check_initial_state: every disk on its own first (cheap, and the clearest message), then all pairs
// through the placement grid, so 10^6 disks take a fraction of a second.
//
// Overlap: distance < (ri + rj) (1 - 1e-12). The tolerance lets disks placed exactly in contact (a lattice
// at its densest, a hand-made Newton's cradle) through after the round-off of writing their positions.
// The message names the lowest-numbered overlapping pair (deterministic, whatever the grid's order) and
// how many pairs overlap in all, so a user fixing a file knows whether it is one slip or a systematic one.
// Rejected: an all-pairs loop (10^12 pair tests at 10^6 disks) and sorting by x (O(N sqrt N) in 2D).
#include <algorithm>
#include <cmath>

#include "setup/setup.hpp"
#include "setup/placement_grid.hpp"

namespace ede {

namespace {

using setup_detail::number_text;

constexpr std::size_t kMaxDisks = 100000000;
constexpr double kOverlapTolerance = 1e-12;

std::string disk_name(const InitialState& s, std::size_t i) {
  return "disk " + std::to_string(i) + " (" + s.species_name_of(i) + ")";
}

std::string point_text(double x, double y) { return "(" + number_text(x) + ", " + number_text(y) + ")"; }

Status check_shape(const InitialState& s, const std::string& source) {
  const std::size_t n = s.size();
  if (n == 0) return Error{source + ": the initial state has no disks; give at least one"};
  if (n > kMaxDisks) {
    return Error{source + ": the initial state has " + std::to_string(n) + " disks; ede handles at most 10^8"};
  }
  for (std::size_t len :
       {s.y.size(), s.vx.size(), s.vy.size(), s.radius.size(), s.mass.size(), s.species.size()}) {
    if (len != n)
      return Error{source + ": the initial state's columns differ in length (x has " + std::to_string(n) +
                   " entries, another " + std::to_string(len) + ")"};
  }
  if (!std::isfinite(s.lx) || !std::isfinite(s.ly) || s.lx <= 0 || s.ly <= 0) {
    return Error{source + ": the box size must be finite and positive (lx = " + number_text(s.lx) +
                 ", ly = " + number_text(s.ly) + ")"};
  }
  return Ok{};
}

std::string box_text(const InitialState& s) {
  return "[0, " + number_text(s.lx) + "] x [0, " + number_text(s.ly) + "]";
}

// Messages are built only on failure: this runs for every disk.
Status check_disk(const InitialState& s, std::size_t i, bool periodic, const std::string& source) {
  const double x = s.x[i], y = s.y[i], r = s.radius[i];
  const auto who = [&] { return source + ": " + disk_name(s, i); };
  if (s.species[i] < 0 || (!s.species_names.empty() && std::size_t(s.species[i]) >= s.species_names.size())) {
    return Error{who() + " has species index " + std::to_string(s.species[i]) + ", which names no species"};
  }
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(s.vx[i]) || !std::isfinite(s.vy[i])) {
    return Error{who() + " has a non-finite position or velocity: x = " + point_text(x, y) +
                 ", v = " + point_text(s.vx[i], s.vy[i])};
  }
  if (!std::isfinite(r) || r <= 0) return Error{who() + " has radius " + number_text(r) + "; radii must be > 0"};
  if (!std::isfinite(s.mass[i]) || s.mass[i] <= 0) {
    return Error{who() + " has mass " + number_text(s.mass[i]) + "; masses must be > 0"};
  }
  if (periodic) {
    if (x < 0 || x >= s.lx || y < 0 || y >= s.ly) {
      return Error{who() + " has its centre " + point_text(x, y) + " outside the periodic box " + box_text(s) +
                   " (centres must be in [0, lx) x [0, ly)); wrap it into the box"};
    }
    if (2 * r * (1 - kOverlapTolerance) > std::min(s.lx, s.ly)) {
      return Error{who() + " has radius " + number_text(r) + ", wider than the periodic box " + box_text(s) +
                   ": it would overlap its own image; reduce the radius or enlarge the box"};
    }
  } else if (x - r < 0 || x + r > s.lx || y - r < 0 || y + r > s.ly) {
    return Error{who() + " at " + point_text(x, y) + " with radius " + number_text(r) +
                 " is not inside the walled box " + box_text(s) +
                 " (x - r >= 0 and x + r <= lx, same in y); move it "
                 "inside or reduce its radius"};
  }
  return Ok{};
}

struct Overlap {
  std::size_t i = 0, j = 0;
  double distance = 0;
  std::size_t pairs = 0;
};

// Every overlapping pair counted once; the lowest (i, j) kept for the message.
Overlap find_overlaps(const InitialState& s, bool periodic) {
  double r_max = 0;
  for (double r : s.radius) r_max = std::max(r_max, r);
  setup_detail::PlacementGrid grid(s.lx, s.ly, periodic, 2 * r_max, s.size());
  for (std::size_t i = 0; i < s.size(); ++i) grid.insert(s.x[i], s.y[i], s.radius[i]);
  Overlap found;
  for (std::size_t i = 0; i < s.size(); ++i) {
    grid.any_near(s.x[i], s.y[i], [&](std::int32_t j32, double dx, double dy, double rj) {
      const std::size_t j = std::size_t(j32);
      const double contact = (s.radius[i] + rj) * (1 - kOverlapTolerance);
      if (j <= i || dx * dx + dy * dy >= contact * contact) return false;
      if (found.pairs++ == 0 || i < found.i || (i == found.i && j < found.j)) {
        found.i = i;
        found.j = j;
        found.distance = std::sqrt(dx * dx + dy * dy);
      }
      return false;
    });
  }
  return found;
}

Error overlap_error(const InitialState& s, const Overlap& o, const std::string& source) {
  const std::size_t i = o.i, j = o.j;
  const std::string others =
      o.pairs > 1 ? " (" + std::to_string(o.pairs - 1) + " other overlapping pairs too)" : std::string();
  return Error{source + ": disks " + std::to_string(i) + " (" + s.species_name_of(i) + ") and " + std::to_string(j) +
               " (" + s.species_name_of(j) + ") overlap: centres " + point_text(s.x[i], s.y[i]) + " and " +
               point_text(s.x[j], s.y[j]) + ", radii " + number_text(s.radius[i]) + " and " +
               number_text(s.radius[j]) + ", distance " + number_text(o.distance) + " < contact distance " +
               number_text(s.radius[i] + s.radius[j]) + others + "; move them apart or reduce the radii"};
}

// A disk of a scene's state by its key: species[k].placement.positions[m] for an explicit list (with the
// spot of that [x, y] in the file), else species[k] and its number among the species' disks.
struct DiskKey {
  std::string key;
  SourceSpot spot;
};

DiskKey disk_key(const Scene& scene, const InitialState& s, std::size_t i) {
  const std::size_t k = std::size_t(s.species[i]);
  const auto first = std::lower_bound(s.species.begin(), s.species.end(), s.species[i]) - s.species.begin();
  const std::size_t m = i - std::size_t(first);
  const SpeciesSpec& sp = scene.species[k];
  const std::string species = "species[" + std::to_string(k) + "]";
  if (sp.placement.kind == PlacementKind::Explicit)
    return {species + ".placement.positions[" + std::to_string(m) + "]",
            m < sp.position_spots.size() ? sp.position_spots[m] : SourceSpot{}};
  return {species + " (disk " + std::to_string(m) + " of its placement)", sp.spot};
}

// The overlap in the form of the scene loader's errors (docs/scene-format.md): FILE:LINE:COL, the key of
// the later disk, the other one's key and line, and the fix.
Error scene_overlap_error(const Scene& scene, const InitialState& s, const Overlap& o) {
  const std::size_t i = o.i, j = o.j;
  const DiskKey a = disk_key(scene, s, i), b = disk_key(scene, s, j);
  const SourceSpot at = b.spot.line ? b.spot : a.spot;
  std::string where = scene.source_name;
  if (at.line) where += ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
  const double contact = s.radius[i] + s.radius[j];
  return Error{where + ": error: " + b.key + " (species '" + s.species_name_of(j) + "'): disk " + std::to_string(j) +
               " overlaps disk " + std::to_string(i) + " (" + a.key +
               (a.spot.line ? ", line " + std::to_string(a.spot.line) : std::string()) + ", species '" +
               s.species_name_of(i) + "'): centres " + point_text(s.x[j], s.y[j]) + " and " +
               point_text(s.x[i], s.y[i]) + ", radii " + number_text(s.radius[j]) + " and " +
               number_text(s.radius[i]) + ", distance " + number_text(o.distance) + " < contact distance " +
               number_text(contact) +
               (o.pairs > 1 ? " (" + std::to_string(o.pairs - 1) + " other overlapping pairs too)" : std::string()) +
               ". Fix: move them apart (centres at least " + number_text(contact) +
               " apart) or reduce the radii."};
}

}  // namespace

// The collision rule divides by m_i + m_j: if the two heaviest masses sum past the largest double, every
// collision of those two computes no impulse and they pass through each other, finitely, so nothing
// downstream notices. Only ratios of masses matter to the dynamics, so rescaling is always possible.
static Status check_mass_sum(const InitialState& s, const std::string& source) {
  std::size_t a = 0, b = s.size() > 1 ? 1 : 0;
  if (s.mass[b] > s.mass[a]) std::swap(a, b);
  for (std::size_t i = 2; i < s.size(); ++i) {
    if (s.mass[i] > s.mass[a]) b = a, a = i;
    else if (s.mass[i] > s.mass[b]) b = i;
  }
  if (std::isfinite(s.mass[a] + s.mass[b])) return Ok{};
  return Error{source + ": " + disk_name(s, a) + " and " + disk_name(s, b) + " have masses " +
               number_text(s.mass[a]) + " and " + number_text(s.mass[b]) +
               " whose sum overflows a double: the collision rule divides by it, so they would pass through "
               "each other. Fix: scale all masses down (only their ratios matter to the motion)."};
}

Status check_initial_state(const InitialState& state, BoundaryKind boundary, const std::string& source_name,
                           const Scene* scene) {
  if (Status st = check_shape(state, source_name); !st) return st;
  const bool periodic = boundary == BoundaryKind::Periodic;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (Status st = check_disk(state, i, periodic, source_name); !st) return st;
  }
  if (state.size() > 1)
    if (Status st = check_mass_sum(state, source_name); !st) return st;
  const Overlap o = find_overlaps(state, periodic);
  if (o.pairs > 0)
    return scene && scene->species.size() == state.species_names.size() ? scene_overlap_error(*scene, state, o)
                                                                         : overlap_error(state, o, source_name);
  return Ok{};
}

}  // namespace ede
