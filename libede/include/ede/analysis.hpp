// Analysis of runs, one include for all of it: each part has its header, by what it serves.
//
//   distributions.hpp    histograms, the 2D Maxwell-Boltzmann law, the Kolmogorov-Smirnov test
//   gas_observables.hpp  a gas at one time (GasSnapshot): speeds, energies, temperature, per-species means
//   block_average.hpp    the mean of a correlated series and its error: blocks, Flyvbjerg-Petersen
//   log_series.hpp       series over time and snapshots, from a log (energy, collision counts)
//   log_reports.hpp      what the analysis commands report: distributions, species, energy with Haff's
//                        law, collisions over time
//   disk_frame.hpp       the disks of one state as a picture shows them, and frame times
//   kinetic_theory.hpp   kinetic-theory references (Enskog's rate, Haff's tau, kT in the centre-of-mass frame)
//
// Two layers. Pure functions on plain numbers (histograms, KS tests, averages of a GasSnapshot) know
// nothing of logs and are tested on hand-made samples. Functions of a Log walk or seek the log once and
// feed them. Every figure a user makes comes from a log: nothing here reruns the physics. Pressure,
// craters, structure, transport and collision statistics have headers of their own (ede/pressure.hpp,
// ede/crater.hpp, ede/structure.hpp, ede/transport.hpp, ede/collision_stats.hpp).
// Rejected: one header of 445 lines mixing all of it (a reader looking for the KS test read past drawing
// frames); a program may still include this one and get every part.
#pragma once

#include "ede/block_average.hpp"
#include "ede/disk_frame.hpp"
#include "ede/distributions.hpp"
#include "ede/gas_observables.hpp"
#include "ede/kinetic_theory.hpp"
#include "ede/log_reports.hpp"
#include "ede/log_series.hpp"
