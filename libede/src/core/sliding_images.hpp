// Where a Lees-Edwards box's sliding images are: the image above the box is shifted in x by
// images_offset(slide, t, lx) = fmod(slide t, lx), slide = T(rate) ly its x-velocity, the image below by
// minus it; in the run's scalar type T, one rounding (the product; fmod is exact). The engine's clock
// (engine/lees_edwards.hpp) and every reader that must pair disks as the run did (the log's states, the
// end-of-run overlap check, the stress walk) compute it here, so they agree with the run bit for bit.
#pragma once

#include "core/scalar_math.hpp"

namespace ede {

template <class T>
inline T image_slide(double shear_rate, T ly) {
  return T(shear_rate) * ly;
}

template <class T>
inline T images_offset(T slide, T t, T lx) {
  return ede::fmod(slide * t, lx);
}

}  // namespace ede
