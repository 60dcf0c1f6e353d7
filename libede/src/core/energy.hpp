// Kinetic energy and momentum of a state (energy.cpp), for the engine, replay and the analyses alike.
#pragma once

#include "core/particles.hpp"

namespace ede {

// Sums over a state, accumulated in long double whatever T is: from the records' velocities, or (the
// overloads with a time) from the velocities at time t, which differ under gravity.
// The kinetic energy includes the rotational one, sum I w^2 / 2, for rough disks (omega not empty).
template <class T>
double kinetic_energy(const Particles<T>& p);
template <class T>
double rotational_energy(const Particles<T>& p);  // sum I w^2 / 2 alone
template <class T>
void momentum(const Particles<T>& p, double& px, double& py);
template <class T>
double kinetic_energy(const Particles<T>& p, T t);
template <class T>
void momentum(const Particles<T>& p, T t, double& px, double& py);

}  // namespace ede
