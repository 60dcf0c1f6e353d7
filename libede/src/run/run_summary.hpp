// summarize: a RunSummary (ede/simulation.hpp) from an engine's state and counters alone, so ede-sim,
// ede-bench and tests report the same numbers the same way.
#pragma once

#include "ede/simulation.hpp"
#include "engine/engine.hpp"

namespace ede {

template <class T>
RunSummary summarize(const EngineApi<T>& engine, double momentum_initial_x, double momentum_initial_y);

}  // namespace ede
