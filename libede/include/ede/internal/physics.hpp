// Internal tier (README.md here): the collision rules and the contact geometry the engine uses, wall
// segments included (make_segment, segment_distance).
#pragma once

#include "core/geometry.hpp"
#include "core/scalar_math.hpp"
#include "core/segment.hpp"
#include "engine/collide.hpp"
