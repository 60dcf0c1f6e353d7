// InitialState: the disks at t = 0, in double, one entry per disk, species contiguous and in scene order.
//
// Produced by setup from a Scene (or built by hand in tests), consumed by the engine, which converts it to
// its own scalar type. Plain vectors: this is an exchange format, not the engine's hot layout.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ede {

struct InitialState {
  double lx = 1, ly = 1;
  std::vector<double> x, y, vx, vy, radius, mass;
  std::vector<std::int32_t> species;      // index into species_names
  std::vector<std::string> species_names;
  // Rough or spinning disks only (Scene::rotates; else both empty): angular velocity and moment of inertia
  // per disk. An engine that needs them and finds them empty takes omega = 0 and I = m r^2 / 2.
  std::vector<double> omega, inertia;
  std::string note;  // what setup did beyond the scene's words (growth: the packing fraction reached), or empty

  std::size_t size() const { return x.size(); }
  // Disk i's species name for messages ("species K" when its index names none: a state not yet checked).
  std::string species_name_of(std::size_t i) const {
    const std::int32_t k = species[i];
    if (k >= 0 && std::size_t(k) < species_names.size()) return species_names[std::size_t(k)];
    return "species " + std::to_string(k);
  }
  void add(double px, double py, double pvx, double pvy, double r, double m, std::int32_t s) {
    x.push_back(px);
    y.push_back(py);
    vx.push_back(pvx);
    vy.push_back(pvy);
    radius.push_back(r);
    mass.push_back(m);
    species.push_back(s);
  }
};

}  // namespace ede
