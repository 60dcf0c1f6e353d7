// Internal tier (README.md here): the engine class template, its effect policies, grid shapes and the
// checks before an engine starts, for binaries that instantiate an engine themselves (ede-bench-elastic,
// the study's textbook-root engines, the time-stepped baseline's grid).
#pragma once

#include "ede/internal/engine.hpp"
#include "engine/engine_checks.hpp"
#include "engine/engine_core.hpp"
