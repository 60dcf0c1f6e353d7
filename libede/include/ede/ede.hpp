// ede: event-driven simulation of two-dimensional hard disks. The whole public API in one include.
//
//   scene.hpp       Scene: a run's definition as plain data; loading TOML with --set overrides
//   simulation.hpp  Simulation: run a scene (to its stop, or to a time), resume a killed run, summaries
//   log.hpp         Log: read an event log: info, the exact state at any time, events, verify, diff
//   live_run.hpp    LiveRun: a Simulation on a worker thread, paced, reversible (a live view's run)
//   state.hpp       State: every disk at one time, as columns in the run's precision; exact CSV
//   events.hpp      event kinds, counts, run statuses, Time, one event with its full data
//   analysis.hpp    distributions and Maxwell-Boltzmann tests, gas observables, block averages, series
//                   over time, the analysis reports, drawing frames (each its own header; this one has all)
//   pressure.hpp    pressure from the walls and from the virial, with error bars
//   crater.hpp      crater metrics from a log
//   error.hpp       Result<T> and ede::Exception
//   number_text.hpp numbers as text: exact (they read back to the same value) and short (%.6g)
//   version.hpp     ede::version()
//
// Build against it with CMake (find_package(ede) and target ede::ede) or pkg-config (ede); see
// examples/hello/ for a whole program in thirty lines.
#pragma once

#include "ede/analysis.hpp"
#include "ede/collision_stats.hpp"
#include "ede/crater.hpp"
#include "ede/error.hpp"
#include "ede/events.hpp"
#include "ede/kinetic_theory.hpp"
#include "ede/live_run.hpp"
#include "ede/log.hpp"
#include "ede/number_text.hpp"
#include "ede/pressure.hpp"
#include "ede/scene.hpp"
#include "ede/simulation.hpp"
#include "ede/state.hpp"
#include "ede/structure.hpp"
#include "ede/transport.hpp"
#include "ede/version.hpp"
#include "ede/viscosity.hpp"
