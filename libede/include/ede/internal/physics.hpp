// Internal tier (README.md here): the collision rules and the contact geometry the engine uses.
#pragma once

#include "core/geometry.hpp"
#include "core/scalar_math.hpp"
#include "engine/collide.hpp"
