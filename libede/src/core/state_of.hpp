// state_of: a public State (ede/state.hpp) from the engine's or replay's Particles<T> at a time.
//
// Positions and velocities at `time` come from the shared drift functions (Particles::x_at, ...), exactly
// as the state CSV has always computed them. A __float128 state is rounded to long double, the widest type
// a State holds (Simulation::write_state_csv keeps all 36 digits of such a run).
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include "core/particles.hpp"
#include "ede/state.hpp"

namespace ede {

template <class T>
using ColumnScalar = std::conditional_t<std::is_same_v<T, float> || std::is_same_v<T, double>, T, long double>;

template <class T>
constexpr ScalarKind scalar_kind_of() {
  if constexpr (std::is_same_v<T, float>) return ScalarKind::Float;
  if constexpr (std::is_same_v<T, double>) return ScalarKind::Double;
  if constexpr (std::is_same_v<T, long double>) return ScalarKind::LongDouble;
  return ScalarKind::Float128;
}

template <class T>
State state_of(const Particles<T>& p, T time, std::uint64_t events, double lx, double ly, BoundaryKind boundary,
               const std::vector<std::string>& species_names) {
  using C = ColumnScalar<T>;
  const std::size_t n = p.size();
  std::vector<C> x(n), y(n), vx(n), vy(n), r(n), m(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = C(p.x_at(i, time));
    y[i] = C(p.y_at(i, time));
    vx[i] = C(p.vx_at(i, time));
    vy[i] = C(p.vy_at(i, time));
    r[i] = C(p.disk[i].r);
    m[i] = C(p.mass(i));
  }
  State s;
  s.time = Time(time);
  s.events = events;
  s.scalar = scalar_kind_of<C>();
  s.lx = lx, s.ly = ly, s.boundary = boundary;
  s.x = Column(std::move(x)), s.y = Column(std::move(y)), s.vx = Column(std::move(vx));
  s.vy = Column(std::move(vy)), s.radius = Column(std::move(r)), s.mass = Column(std::move(m));
  s.species = p.species_column();
  s.species_names = species_names;
  if (!p.omega.empty()) {
    std::vector<C> w(n), inertia(n);
    for (std::size_t i = 0; i < n; ++i) w[i] = C(p.omega[i]), inertia[i] = C(p.inertia[i]);
    s.omega = Column(std::move(w)), s.inertia = Column(std::move(inertia));
  }
  return s;
}

}  // namespace ede
