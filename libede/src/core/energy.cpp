// Kinetic energy and momentum of a state, summed in long double so the sum's rounding does not hide the
// engine's own (the energy-conservation tests compare against 1e-12 relative). For __float128 that sum
// is coarser than the state: tests of its round-off sum in __float128 themselves.
#include "core/energy.hpp"

namespace ede {
namespace {
// The sum of I w^2 / 2 (0 for smooth disks, whose omega is empty).
template <class T>
long double rotational_sum(const Particles<T>& p) {
  long double sum = 0;
  for (std::size_t i = 0; i < p.omega.size(); ++i) {
    const long double w = p.omega[i];
    sum += 0.5L * (long double)p.inertia[i] * (w * w);
  }
  return sum;
}
}  // namespace
template <class T>
double rotational_energy(const Particles<T>& p) {
  return double(rotational_sum(p));
}
template double rotational_energy<float>(const Particles<float>&);
template double rotational_energy<double>(const Particles<double>&);
template double rotational_energy<long double>(const Particles<long double>&);
#if EDE_HAVE_FLOAT128
template double rotational_energy<__float128>(const Particles<__float128>&);
#endif

template <class T>
double kinetic_energy(const Particles<T>& p) {
  long double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const long double vx = p.disk[i].vx, vy = p.disk[i].vy;
    sum += 0.5L * (long double)p.mass(i) * (vx * vx + vy * vy);
  }
  return double(sum + rotational_sum(p));  // + 0 exactly for smooth disks
}

template <class T>
void momentum(const Particles<T>& p, double& px, double& py) {
  long double sx = 0, sy = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    sx += (long double)p.mass(i) * p.disk[i].vx;
    sy += (long double)p.mass(i) * p.disk[i].vy;
  }
  px = double(sx);
  py = double(sy);
}

template <class T>
double kinetic_energy(const Particles<T>& p, T t) {
  long double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const long double vx = p.vx_at(i, t), vy = p.vy_at(i, t);
    sum += 0.5L * (long double)p.mass(i) * (vx * vx + vy * vy);
  }
  return double(sum + rotational_sum(p));
}

template <class T>
void momentum(const Particles<T>& p, T t, double& px, double& py) {
  long double sx = 0, sy = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    sx += (long double)p.mass(i) * p.vx_at(i, t);
    sy += (long double)p.mass(i) * p.vy_at(i, t);
  }
  px = double(sx);
  py = double(sy);
}

template double kinetic_energy<float>(const Particles<float>&, float);
template double kinetic_energy<double>(const Particles<double>&, double);
template double kinetic_energy<long double>(const Particles<long double>&, long double);
template void momentum<float>(const Particles<float>&, float, double&, double&);
template void momentum<double>(const Particles<double>&, double, double&, double&);
template void momentum<long double>(const Particles<long double>&, long double, double&, double&);
template double kinetic_energy<float>(const Particles<float>&);
template double kinetic_energy<double>(const Particles<double>&);
template double kinetic_energy<long double>(const Particles<long double>&);
template void momentum<float>(const Particles<float>&, double&, double&);
template void momentum<double>(const Particles<double>&, double&, double&);
template void momentum<long double>(const Particles<long double>&, double&, double&);
#if EDE_HAVE_FLOAT128
template double kinetic_energy<__float128>(const Particles<__float128>&);
template double kinetic_energy<__float128>(const Particles<__float128>&, __float128);
template void momentum<__float128>(const Particles<__float128>&, double&, double&);
template void momentum<__float128>(const Particles<__float128>&, __float128, double&, double&);
#endif

}  // namespace ede
