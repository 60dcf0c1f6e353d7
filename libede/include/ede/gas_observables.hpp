// Gas observables: what the velocities of a gas at one time say, per species and for the whole gas.
//
// A GasSnapshot is the velocities of every disk at one time (in double, whatever the log's scalar type)
// with the per-disk constants (mass, species); log_series.hpp makes them from a log. From it: speeds and
// kinetic energies of a selection, per-species means, the temperature, and the speed classes of the
// GasLab model. The temperature is 2D equipartition, kT = <m v^2 / 2> (two degrees of freedom of kT/2
// each, k = 1); it counts any bulk flow as heat, which is right for a gas at rest in its box.
// Averages may be pooled over several snapshots (GasAverages::add), e.g. several times of one run.
// Rejected: computing these inside the tools, where they could not be tested without a log.
// (One part of ede/analysis.hpp, which includes them all.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ede {

struct GasSnapshot {
  double time = 0;
  std::vector<double> vx, vy, mass;
  std::vector<std::int32_t> species;       // index into species_names
  std::vector<std::string> species_names;

  std::size_t size() const { return vx.size(); }
  double speed(std::size_t i) const;           // sqrt(vx^2 + vy^2), correctly rounded
  double kinetic_energy(std::size_t i) const;  // m (vx^2 + vy^2) / 2
};

constexpr std::int32_t kAllSpecies = -1;

// Speeds or kinetic energies of the disks of one species (or of all, kAllSpecies), in id order.
std::vector<double> speeds(const GasSnapshot& s, std::int32_t species = kAllSpecies);
std::vector<double> kinetic_energies(const GasSnapshot& s, std::int32_t species = kAllSpecies);
std::vector<double> masses(const GasSnapshot& s, std::int32_t species = kAllSpecies);

struct SpeciesStats {
  std::string name;             // the species' name, or "all"
  std::uint64_t n = 0;          // disks (times snapshots, when pooled)
  double mass_min = 0, mass_max = 0;
  double mean_speed = 0;
  double mean_kinetic_energy = 0;  // <m v^2 / 2>
  double kT = 0;                   // 2D equipartition: equal to mean_kinetic_energy
  // Standard errors of the two means (sample standard deviation / sqrt(n)): valid for independent disks;
  // pooled snapshots closer than a few mean free times are correlated and make them too small.
  double mean_speed_error = 0, mean_kinetic_energy_error = 0;
};

// Sums over disks and snapshots, per species; stats() gives one entry per species in order, then "all".
class GasAverages {
 public:
  void add(const GasSnapshot& s);
  std::vector<SpeciesStats> stats() const;

 private:
  struct Sums {
    std::uint64_t n = 0;
    double mass_min = 0, mass_max = 0;
    long double speed = 0, speed2 = 0, energy = 0, energy2 = 0;
    void add(double m, double v, double e);
  };
  std::vector<std::string> names_;
  std::vector<Sums> per_species_;
  Sums all_;
};

// The per-species statistics of one snapshot (GasAverages of it alone).
std::vector<SpeciesStats> species_stats(const GasSnapshot& s);

// Temperature of a selection: kT = <m v^2 / 2>; 0 for an empty selection.
double temperature(const GasSnapshot& s, std::int32_t species = kAllSpecies);
double mean_speed(const GasSnapshot& s, std::int32_t species = kAllSpecies);

// The GasLab speed classes against a reference mean speed (the gas's initial one): slow below
// 0.5 v_ref, fast above 1.5 v_ref, medium in between (both bounds included).
struct SpeedClasses {
  std::uint64_t slow = 0, medium = 0, fast = 0;
  double slow_percent = 0, medium_percent = 0, fast_percent = 0;
};
SpeedClasses speed_classes(const GasSnapshot& s, double reference_speed, std::int32_t species = kAllSpecies);

}  // namespace ede
