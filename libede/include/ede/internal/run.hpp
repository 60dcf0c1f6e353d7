// Internal tier (README.md here): one way to make a run from a scene or a state, its engine and log writer,
// and what a log's header records of a run (log_run_info, for a study that writes a log of its own engine).
#pragma once

#include "ede/internal/engine.hpp"
#include "run/log_run_info.hpp"
#include "run/run_plan.hpp"
