// check_run_can_finish, scene_warnings and estimated_memory_bytes; see run_checks.hpp.
#include "run/run_checks.hpp"

#include <cmath>

#include "ede/number_text.hpp"
#include "ede/simulation.hpp"
#include "run/scale_checks.hpp"

namespace ede {

namespace {

constexpr double kRefusedSamples = 1e12;  // ~a day at 1e7 samples/s, for the samples alone
constexpr double kWarnedSamples = 1e9;

std::string num(double v) { return exact_text(v, ScalarKind::Double); }

// The checks in double do not cover a float run, which overflows near 3.4e38: a mass, an energy, a
// momentum or the sum of the two heaviest masses (the collision rule divides by it: past the range two
// disks would pass through each other with no impulse, finitely, so the finite guard would not notice).
// Computed in float as the engine will, from the values converted to float as the engine converts them.
Status check_fits_float(const Scene& scene, const InitialState& s) {
  float heaviest = 0, second = 0;
  std::size_t a = 0, b = 0;
  float energy = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const float m = float(s.mass[i]), vx = float(s.vx[i]), vy = float(s.vy[i]);
    const float e = 0.5f * m * (vx * vx + vy * vy);
    if (!std::isfinite(m) || !std::isfinite(e) || !std::isfinite(m * vx) || !std::isfinite(m * vy))
      return Error{scene.source_name + ": disk " + std::to_string(i) + " (species '" + s.species_name_of(i) +
                   "') has mass " + num(s.mass[i]) + " and velocity [" + num(s.vx[i]) + ", " + num(s.vy[i]) +
                   "]: with engine.scalar = \"float\" its mass, energy or momentum overflows a float (largest "
                   "3.4e38). Fix: scale the units so that masses and speeds are near 1, or run in double."};
    energy += e;
    if (m > heaviest) second = heaviest, b = a, heaviest = m, a = i;
    else if (m > second) second = m, b = i;
  }
  if (s.size() > 1 && !std::isfinite(heaviest + second))
    return Error{scene.source_name + ": disks " + std::to_string(a) + " and " + std::to_string(b) + " have masses " +
                 num(double(heaviest)) + " and " + num(double(second)) +
                 " whose sum overflows a float (engine.scalar = \"float\"): the collision rule divides by it, so "
                 "they would pass through each other. Fix: scale all masses down (only their ratios matter), or "
                 "run in double."};
  if (!std::isfinite(energy))
    return Error{scene.source_name + ": the total kinetic energy of the initial state overflows a float "
                 "(engine.scalar = \"float\"). Fix: scale the units (masses and speeds near 1), or run in double."};
  return Ok{};
}

}  // namespace

Status check_run_can_finish(const Scene& scene, const InitialState& s) {
  double energy = 0, px = 0, py = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double m = s.mass[i], vx = s.vx[i], vy = s.vy[i];
    const double e = 0.5 * m * (vx * vx + vy * vy);
    if (!std::isfinite(e) || !std::isfinite(m * vx) || !std::isfinite(m * vy))
      return Error{scene.source_name + ": disk " + std::to_string(i) + " (species '" + s.species_name_of(i) +
                   "') has mass " + num(m) + " and velocity [" + num(vx) + ", " + num(vy) +
                   "]: its energy or momentum overflows a double, so every number of the run would be infinite. "
                   "Fix: scale the units so that masses and speeds are within a few orders of magnitude of 1."};
    energy += e, px += m * vx, py += m * vy;
  }
  if (!std::isfinite(energy) || !std::isfinite(px) || !std::isfinite(py))
    return Error{scene.source_name + ": the total kinetic energy or momentum of the initial state overflows a double "
                 "(too many disks too heavy or too fast). Fix: scale the units (masses and speeds near 1)."};
  if (scene.scalar == ScalarKind::Float)
    if (Status f = check_fits_float(scene, s); !f) return f;
  if (Status f = check_state_scales(scene, s); !f) return f;
  if (scene.sample_interval && scene.stop.time) {
    const double samples = *scene.stop.time / *scene.sample_interval;
    if (!(samples <= kRefusedSamples))
      return Error{scene.source_name + ": sampling.interval = " + num(*scene.sample_interval) + " with stop.time = " +
                   num(*scene.stop.time) + " asks for " + num(samples) +
                   " samples, more than any run can take (the samples alone would take days or forever). Fix: "
                   "sample less often (a larger sampling.interval) or stop earlier."};
  }
  if (scene.sample_collisions && scene.stop.collisions_per_particle) {
    const double samples = *scene.stop.collisions_per_particle / *scene.sample_collisions;
    if (!(samples <= kRefusedSamples))
      return Error{scene.source_name + ": sampling.collisions_per_disk = " + num(*scene.sample_collisions) +
                   " with stop.collisions_per_particle = " + num(*scene.stop.collisions_per_particle) + " asks for " +
                   num(samples) + " samples, more than any run can take. Fix: sample less often (a larger "
                   "sampling.collisions_per_disk) or stop earlier."};
  }
  return Ok{};
}

std::vector<std::string> scene_warnings(const Scene& scene) {
  std::vector<std::string> w;
  if (scene.sample_interval && scene.stop.time) {
    const double samples = *scene.stop.time / *scene.sample_interval;
    if (samples > kWarnedSamples && samples <= kRefusedSamples)
      w.push_back(scene.source_name + ": sampling.interval = " + num(*scene.sample_interval) + " gives " + num(samples) +
                  " samples up to stop.time: the samples alone may take hours. A larger interval is faster.");
  }
  if (scene.sample_interval && !scene.stop.time)
    w.push_back(scene.source_name + ": sampling.interval without stop.time: the number of samples depends on how far "
                "the run gets; if it is tiny against the time between events, the run crawls. Consider stop.time.");
  return w;
}

std::uint64_t estimated_memory_bytes(const Scene& scene, bool with_log) {
  std::uint64_t disks = 0;
  for (const SpeciesSpec& sp : scene.species)
    disks += sp.count > 0 ? std::uint64_t(sp.count) : std::uint64_t(sp.placement.positions.size());
  const std::uint64_t per_disk = scene.scalar == ScalarKind::Double || scene.scalar == ScalarKind::Float
                                     ? (with_log ? kBytesPerDiskWithLog : kBytesPerDiskNoLog)
                                     : 2 * (with_log ? kBytesPerDiskWithLog : kBytesPerDiskNoLog);
  return disks * per_disk + (std::uint64_t(16) << 20);  // plus the program itself and the log's buffers
}

}  // namespace ede
