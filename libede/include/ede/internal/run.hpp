// Internal tier (README.md here): one way to make a run from a scene or a state, its engine and log writer.
#pragma once

#include "ede/internal/engine.hpp"
#include "run/run_plan.hpp"
