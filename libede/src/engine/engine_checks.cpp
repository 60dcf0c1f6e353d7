// What the engine requires of its input: sizes the queue can index, finite numbers, the disks inside the
// box and apart (check_initial_state: setup checked a scene's state already, but a state built in code
// reaches the engine directly), and a periodic box at least three cells wide.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "setup/setup.hpp"
#include "engine/engine_checks.hpp"

namespace ede {

namespace {
bool finite(double v) { return std::isfinite(v); }

// A stepped potential: named species exist, radii finite and increasing, energies finite, and every step
// outside the hard core of the disks it acts on (the largest radii of the two species).
Status check_steps(const InitialState& init, const EngineOptions& options) {
  const PhysicsSpec& ph = options.physics;
  if (!ph.has_steps()) return Ok{};
  if (uses_rotation(options) || !ph.segments.empty())
    return Error{"a stepped potential with rough or spinning disks or with wall segments is not supported yet"};
  const std::vector<std::string>& names = init.species_names;
  const std::size_t species = std::max<std::size_t>(names.size(), 1);
  std::vector<double> largest(species, 0);
  for (std::size_t i = 0; i < init.size(); ++i) {
    const std::size_t sp = i < init.species.size() ? std::size_t(init.species[i]) : 0;
    largest[std::min(sp, species - 1)] = std::max(largest[std::min(sp, species - 1)], init.radius[i]);
  }
  const auto index_of = [&](const std::string& name) {
    return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
  };
  for (const PairSteps& st : ph.steps) {
    if (st.radius.empty() || st.radius.size() != st.energy.size())
      return Error{"a stepped potential needs one energy per radius, and at least one step"};
    for (std::size_t k = 0; k < st.radius.size(); ++k)
      if (!finite(st.radius[k]) || !finite(st.energy[k]) || (k > 0 && !(st.radius[k] > st.radius[k - 1])))
        return Error{"a stepped potential's radii must be finite and increasing, its energies finite"};
    double contact = 0;
    if (st.a.empty()) {
      for (double r : largest) contact = std::max(contact, 2 * r);
    } else {
      for (const std::string& name : {st.a, st.b})
        if (index_of(name) >= names.size())
          return Error{"a stepped potential names species '" + name + "', which the initial state does not have"};
      contact = largest[index_of(st.a)] + largest[index_of(st.b)];
    }
    if (!(st.radius.front() > contact)) {
      std::ostringstream m;
      m << "a stepped potential's innermost step (radius " << st.radius.front()
        << ") lies inside the hard core of the disks it acts on (they touch at " << contact
        << "); give step radii larger than the sum of the two radii";
      return Error{m.str()};
    }
  }
  return Ok{};
}

// The largest distance at which two disks interact: the outermost step, or a largest diameter.
double interaction_radius(const PhysicsSpec& ph, double max_radius) {
  double reach = 2 * max_radius;
  for (const PairSteps& st : ph.steps)
    if (!st.radius.empty()) reach = std::max(reach, st.radius.back());
  return reach / 2;
}
}  // namespace

Status check_engine_input(const InitialState& init, const EngineOptions& options, GridShape& shape) {
  const std::size_t n = init.size();
  if (n == 0) return Error{"the initial state has no disks; add a species with count >= 1"};
  if (n >= kMaxQueueDisks) {
    std::ostringstream m;
    m << "the initial state has " << n << " disks; the engine supports fewer than " << kMaxQueueDisks;
    return Error{m.str()};
  }
  if (!(init.lx > 0) || !(init.ly > 0) || !finite(init.lx) || !finite(init.ly))
    return Error{"the box size must be positive and finite"};
  double max_radius = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!finite(init.x[i]) || !finite(init.y[i]) || !finite(init.vx[i]) || !finite(init.vy[i]) ||
        !(init.radius[i] > 0) || !finite(init.radius[i]) || !(init.mass[i] > 0) || !finite(init.mass[i])) {
      std::ostringstream m;
      m << "disk " << i << " has a non-finite value or a non-positive radius or mass";
      return Error{m.str()};
    }
    max_radius = std::max(max_radius, init.radius[i]);
  }
  const PhysicsSpec& ph = options.physics;
  bool in_range = ph.restitution >= 0 && ph.restitution <= 1;
  for (int w = 0; w < 4; ++w) in_range = in_range && ph.wall(w) >= 0 && ph.wall(w) <= 1;
  for (const PairRestitution& p : ph.pairs) {
    in_range = in_range && p.value >= 0 && p.value <= 1;
    for (const std::string& name : {p.a, p.b})
      if (std::find(init.species_names.begin(), init.species_names.end(), name) == init.species_names.end())
        return Error{"a pair restitution names species '" + name + "', which the initial state does not have"};
  }
  if (!in_range) return Error{"restitution coefficients must lie in [0, 1]"};
  bool beta_in_range = ph.roughness >= -1 && ph.roughness <= 1 && ph.wall_roughness >= -1 && ph.wall_roughness <= 1;
  for (const PairRestitution& p : ph.pairs) beta_in_range = beta_in_range && ph.pair_roughness(p) >= -1 && ph.pair_roughness(p) <= 1;
  if (!beta_in_range) return Error{"roughness coefficients (beta) must lie in [-1, 1]"};
  if (uses_rotation(options) && (ph.has_gravity() || !ph.segments.empty()))
    return Error{"rough or spinning disks under gravity or with wall segments are not supported yet; make them smooth"};
  if (uses_thermostat(options)) {
    if (uses_rotation(options) || ph.has_gravity() || !ph.segments.empty())
      return Error{"the thermostat with gravity, wall segments or rough disks is not supported yet; remove one of them"};
    if (ph.thermostat && !(ph.thermostat->temperature > 0 && finite(ph.thermostat->temperature) &&
                           ph.thermostat->rate > 0 && finite(ph.thermostat->rate)))
      return Error{"the thermostat's temperature and rate must be finite and > 0"};
    for (const SpeciesThermostat& t : options.species_thermostats)
      if (!(t.temperature > 0 && finite(t.temperature) && t.rate >= 0 && finite(t.rate)))
        return Error{"species '" + t.species + "': its thermostat's temperature must be finite and > 0, its rate finite and >= 0"};
    for (const std::string& name : ph.thermostat ? ph.thermostat->species : std::vector<std::string>{})
      if (std::find(init.species_names.begin(), init.species_names.end(), name) == init.species_names.end())
        return Error{"the thermostat names species '" + name + "', which the initial state does not have"};
  }
  if (uses_shear(options)) {
    if (!(*options.shear_rate >= 0) || !finite(*options.shear_rate))
      return Error{"the shear rate of a Lees-Edwards box must be finite and >= 0"};
    if (options.boundary != BoundaryKind::Periodic || options.algorithm == Algorithm::AllPairs)
      return Error{"a Lees-Edwards box is periodic and runs with the cell grid (not the all-pairs baseline)"};
    if (uses_rotation(options) || ph.has_steps() || !options.actions.empty())
      return Error{"a Lees-Edwards box with rough disks, steps or actions is not supported yet"};
  }
  if ((!init.omega.empty() && init.omega.size() != n) || (!init.inertia.empty() && init.inertia.size() != n))
    return Error{"the initial state's angular velocities or moments of inertia do not match its disk count"};
  for (std::size_t i = 0; i < init.omega.size(); ++i)
    if (!finite(init.omega[i]) || (i < init.inertia.size() && !(init.inertia[i] > 0 && finite(init.inertia[i]))))
      return Error{"disk " + std::to_string(i) + " has a non-finite angular velocity or a non-positive moment of inertia"};
  if (!std::isfinite(ph.gravity[0]) || !std::isfinite(ph.gravity[1])) return Error{"gravity must be finite"};
  if (ph.has_gravity() && options.boundary == BoundaryKind::Periodic)
    return Error{"gravity needs walls: in a periodic box every disk would fall forever"};
  if (ph.has_gravity() && options.stop.energy_fraction)
    return Error{"with gravity the kinetic energy changes between collisions: stop on time or events instead"};
  if (!(ph.tc >= 0) || !finite(ph.tc)) return Error{"tc must be finite and >= 0"};
  const bool periodic = options.boundary == BoundaryKind::Periodic;
  if (Status s = check_initial_state(init, options.boundary, "the initial state"); !s) return s;
  if (Status s = check_segments(ph.segments, init.lx, init.ly, options.boundary, ph.has_gravity(), "the physics"); !s)
    return s;
  if (Status s = check_disks_clear_of_segments(init, ph.segments, "the initial state"); !s) return s;
  if (Status s = check_steps(init, options); !s) return s;
  // With a stepped potential the cells must hold the outermost step as they hold a diameter.
  const double reach = interaction_radius(ph, max_radius);
  if (periodic && (init.lx < 3 * 2 * reach * (1 + 1e-6) || init.ly < 3 * 2 * reach * (1 + 1e-6))) {
    std::ostringstream m;
    m << "a periodic box must be at least three largest " << (ph.has_steps() ? "interaction ranges (outermost step)" : "diameters")
      << " wide on each side (largest " << (ph.has_steps() ? "range " : "diameter ") << 2 * reach << ", box " << init.lx
      << " x " << init.ly << "); enlarge the box or use walls";
    return Error{m.str()};
  }
  // A Lees-Edwards box keeps every disk in the cell lists (its scans across the sliding edge know no big
  // disks), as a stepped potential does.
  if (ph.has_steps() || uses_shear(options))
    shape = grid_shape_for(init.lx, init.ly, reach, init.size(), periodic, options.algorithm);  // no big disks
  else
    shape = engine_grid_for(init, periodic, options.algorithm);
  return Ok{};
}

}  // namespace ede
