// Internal tier (README.md here): the engine's interface (EngineApi, make_engine, EngineOptions,
// ResumePoint, sinks) and the particle arrays it runs on.
#pragma once

#include "core/initial_state.hpp"
#include "core/particles.hpp"
#include "core/scalar_dispatch.hpp"
#include "engine/engine.hpp"
#include "core/sink.hpp"
