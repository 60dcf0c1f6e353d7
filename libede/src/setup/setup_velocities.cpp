// Velocity rules: one short branch each; the random ones draw per disk, in disk order.
//
// Draws: Speed takes one unit_vector per disk, Maxwell one normal_pair per disk (vx from z0, vy from z1).
// Rejected: one shared normal stream across species (adding a species would change the others).
#include "setup/setup_velocities.hpp"

#include <cmath>

namespace ede::setup_detail {

void assign_velocities(const VelocitySpec& spec, const std::vector<double>& mass, Rng& rng,
                       std::vector<double>& vx, std::vector<double>& vy) {
  const std::size_t n = mass.size();
  vx.assign(n, 0.0);
  vy.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    switch (spec.kind) {
      case VelocityKind::Zero:
        break;
      case VelocityKind::Speed:
        rng.unit_vector(vx[k], vy[k]);
        vx[k] *= spec.speed;
        vy[k] *= spec.speed;
        break;
      case VelocityKind::Vector:
        vx[k] = spec.vector[0];
        vy[k] = spec.vector[1];
        break;
      case VelocityKind::Maxwell: {
        const double sigma = std::sqrt(spec.temperature / mass[k]);
        rng.normal_pair(vx[k], vy[k]);
        vx[k] *= sigma;
        vy[k] *= sigma;
        break;
      }
      case VelocityKind::List:
        vx[k] = spec.list[k][0];
        vy[k] = spec.list[k][1];
        break;
    }
  }
}

void assign_spins(const SpeciesSpec& species, const std::vector<double>& mass, const std::vector<double>& radius,
                  Rng& rng, std::vector<double>& omega, std::vector<double>& inertia) {
  for (std::size_t k = 0; k < mass.size(); ++k) {
    const double moment = species.inertia_factor * mass[k] * radius[k] * radius[k];
    double w = 0;
    if (species.spin.kind == SpinSpec::Kind::Value) w = species.spin.omega;
    if (species.spin.kind == SpinSpec::Kind::Maxwell) {
      double z0 = 0, z1 = 0;
      rng.normal_pair(z0, z1);
      w = z0 * std::sqrt(species.spin.temperature / moment);
    }
    omega.push_back(w);
    inertia.push_back(moment);
  }
}

}  // namespace ede::setup_detail
