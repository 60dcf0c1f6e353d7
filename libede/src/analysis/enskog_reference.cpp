// enskog_reference (enskog_reference.hpp): equal hard disks only; square wells, mixtures and inelastic
// collisions get NaN and the reason.
#include "analysis/enskog_reference.hpp"

#include <limits>
#include <numbers>

#include "ede/kinetic_theory.hpp"

namespace ede::stress {

EnskogReference enskog_reference(const Log& log, const State& s, double area, double kT) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  EnskogReference out;
  out.sigma = out.mass = out.packing_fraction = out.g_contact = out.enskog = out.dilute = nan;
  for (std::size_t i = 1; i < s.size(); ++i)
    if (s.radius[i] != s.radius[0] || s.mass[i] != s.mass[0]) {
      out.note = "not applicable: the disks differ in radius or mass (a mixture needs g_ij per pair of species)";
      return out;
    }
  if (s.size() == 0) return out;
  const double r = s.radius[0], m = s.mass[0];
  out.sigma = 2 * r, out.mass = m;
  out.packing_fraction = double(s.size()) * std::numbers::pi * r * r / area;
  const auto scene = log.scene();
  if (scene && scene.value().physics.has_steps()) {
    out.note = "not applicable: square wells or shoulders (Enskog's formula is for hard disks)";
    return out;
  }
  if (scene && !scene.value().physics.elastic()) {
    out.note = "not applicable: the collisions are inelastic (a granular gas's viscosity differs from Enskog's "
               "elastic one by terms in 1 - xi^2)";
    return out;
  }
  out.g_contact = henderson_contact_value(out.packing_fraction);
  out.enskog = enskog_viscosity(out.packing_fraction, out.sigma, out.g_contact, kT, m);
  out.dilute = dilute_viscosity(out.sigma, kT, m);
  out.note = "Enskog (Gass 1971) with Henderson's g(sigma) and the Sonine factor " +
             std::to_string(kViscositySonineFactor).substr(0, 6) + " on the kinetic part";
  return out;
}

}  // namespace ede::stress
