// Enskog's 2D viscosity as the reference beside a measured one (viscosity.cpp, viscosity_sheared.cpp):
// for a log of equal hard disks at a measured kT; NaN with the reason where the formula does not apply.
#pragma once

#include <string>

#include "ede/log.hpp"

namespace ede::stress {

struct EnskogReference {
  double sigma = 0, mass = 0;  // the disks' diameter and mass (NaN for a mixture)
  double packing_fraction = 0, g_contact = 0, enskog = 0, dilute = 0;  // NaN where not applicable
  std::string note;  // what the reference is, or why there is none
};
EnskogReference enskog_reference(const Log& log, const State& s, double area, double kT);

}  // namespace ede::stress
