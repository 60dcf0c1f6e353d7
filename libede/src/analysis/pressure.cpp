// measure_pressure; see pressure.hpp for the physics. This file chooses the window, turns the pass's
// bin sums (pressure_pass.cpp) into pressures per bin and per block, and judges the error bars
// (block_average.cpp). Every observable goes through the same path: per-bin values, blocks as means of
// bins, the mean +- standard error of the blocks, and the blocking analysis of the bins.
// Rejected: one error method per observable (e.g. Poisson counting for the wall impulses): the block
// error makes no assumption about the statistics of the events, and the checks say when it fails.
#include "ede/pressure.hpp"

#include <cmath>
#include <limits>

#include "log/log_stats.hpp"
#include "ede/number_text.hpp"
#include "analysis/pressure_pass.hpp"
#include "replay/log_impl.hpp"
#include "analysis/sheared_guard.hpp"

namespace ede {

namespace {

PressureSeries series_of(const std::vector<double>& bins, std::size_t per_block) {
  PressureSeries s;
  s.block = coarse_grain(bins, per_block);
  s.stats = block_stats(s.block);
  s.blocking = blocking_analysis(bins);
  return s;
}

// The window: explicit ends, or the end of the equilibration (capped at half the run) to the log's end.
Status choose_window(const LogReader& log, const LogDisks& disks, const PressureOptions& o, PressureReport& r) {
  r.end_time = disks.end_time;
  auto counts = count_logged_kinds(log);
  if (!counts) return counts.error();
  const std::uint64_t pairs = counts.value().of(EventKind::Pair);
  r.mean_free_time = pairs ? double(disks.count) * disks.end_time / (2.0 * double(pairs))
                           : std::numeric_limits<double>::infinity();
  r.t1 = o.to.value_or(disks.end_time);
  if (o.from) {
    r.t0 = *o.from;
  } else {
    r.default_start = true;
    const double skip = o.equilibration_mean_free_times * r.mean_free_time;
    r.t0 = std::min(skip, r.t1 / 2);
    if (!(skip <= r.t1 / 2))
      r.warnings.push_back("the run is shorter than " + brief(2 * o.equilibration_mean_free_times) +
                           " mean free times: the window starts at half the run (t = " + brief(r.t0) +
                           "), and the gas may not have reached equilibrium by then; give --from to choose");
  }
  if (!std::isfinite(r.t0) || !std::isfinite(r.t1) || r.t0 < 0)
    return Error{"the window's ends must be finite times >= 0"};
  if (r.t1 > disks.end_time)
    return Error{log.path() + ": the window ends at t = " + brief(r.t1) +
                 ", after the end of the log (t = " + brief(disks.end_time) + ")"};
  if (!(r.t0 < r.t1))
    return Error{"the window (" + brief(r.t0) + ", " + brief(r.t1) +
                 "] is empty: it must start before it ends"};
  return Ok{};
}

void fill_geometry(const LogHeaderInfo& h, const LogDisks& d, PressureReport& r) {
  r.disks = d.count;
  r.boundary = h.boundary;
  r.scalar = h.scalar;
  r.lx = h.lx, r.ly = h.ly;
  r.area = h.lx * h.ly;
  r.mean_radius = d.count ? d.radius_sum / double(d.count) : 0;
  r.virial_area = r.has_walls() ? r.area - r.mean_radius * (h.lx + h.ly) : r.area;
  r.packing_fraction = d.disk_area / r.area;
}

// Per-bin values of every observable, then blocks and errors.
void fill_series(const PressureBins& b, PressureReport& r) {
  const std::size_t m = b.size(), per = r.bins_per_block;
  const double dt = double((b.t1 - b.t0) / (long double)m);
  const double n = double(r.disks);
  const double length[4] = {r.ly, r.ly, r.lx, r.lx};
  std::vector<double> kT(m), virial(m), wall_mean(m), difference(m), z_virial(m), z_wall(m);
  std::array<std::vector<double>, 4> wall;
  for (auto& w : wall) w.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    const double kin = double(b.kinetic[k] / dt);
    kT[k] = kin / n;
    virial[k] = double((kin + b.virial[k] / (2 * dt)) / r.virial_area);
    z_virial[k] = virial[k] * r.area / kin;
    long double total = 0;
    for (std::size_t w = 0; w < 4; ++w) {
      wall[w][k] = double(b.wall_impulse[k][w] / (length[w] * dt));
      total += b.wall_impulse[k][w];
    }
    wall_mean[k] = double(total / (2 * (r.lx + r.ly) * dt));
    z_wall[k] = wall_mean[k] * r.area / kin;
    difference[k] = wall_mean[k] - virial[k];
  }
  r.kT = series_of(kT, per);
  r.virial = series_of(virial, per);
  r.z_virial = series_of(z_virial, per);
  if (r.has_walls()) {
    for (std::size_t w = 0; w < 4; ++w) r.wall[w] = series_of(wall[w], per);
    r.wall_mean = series_of(wall_mean, per);
    r.wall_minus_virial = series_of(difference, per);
    r.z_wall = series_of(z_wall, per);
  }
}

void fill_blocks_and_totals(const PressureBins& b, PressureReport& r) {
  const std::size_t per = r.bins_per_block;
  r.block_t0.clear(), r.block_t1.clear();
  r.block_pair_collisions.assign(r.blocks, 0), r.block_wall_collisions.assign(r.blocks, 0);
  long double wall[4] = {}, virial = 0, kinetic = 0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    r.block_pair_collisions[k / per] += b.pairs[k];
    r.block_wall_collisions[k / per] += b.walls[k];
    for (int w = 0; w < 4; ++w) wall[w] += b.wall_impulse[k][std::size_t(w)];
    virial += b.virial[k], kinetic += b.kinetic[k];
  }
  for (std::size_t k = 0; k < r.blocks; ++k) {
    r.block_t0.push_back(double(b.t0 + (b.t1 - b.t0) * (long double)k / (long double)r.blocks));
    r.block_t1.push_back(double(b.t0 + (b.t1 - b.t0) * (long double)(k + 1) / (long double)r.blocks));
    r.totals.pair_collisions += r.block_pair_collisions[k];
    r.totals.wall_collisions += r.block_wall_collisions[k];
  }
  for (int w = 0; w < 4; ++w) r.totals.wall_impulse[std::size_t(w)] = double(wall[w]);
  r.totals.virial_sum = double(virial);
  r.totals.kinetic_integral = double(kinetic);
  r.totals.kinetic_start = double(b.kinetic_start);
  r.totals.kinetic_end = double(b.kinetic_end);
}

// Is the block error to be trusted? Blocks too short for the correlations show as a positive lag-1
// correlation well above its noise (~1/sqrt(B)), as a blocking plateau above the block error by more than
// the block error's own uncertainty (1/sqrt(2 (B - 1)) relative) and the plateau's, or as blocking errors
// still rising at the coarsest level. Falling ones (anticorrelated bins: wall hits of a dilute gas come
// more regularly than a Poisson process) make the block error an upper bound: no warning.
void check_series(const std::string& name, const PressureSeries& s, PressureReport& r) {
  const double b = double(s.stats.blocks);
  if (s.stats.lag1 > 3 / std::sqrt(b))
    r.warnings.push_back(name + ": the block values are correlated (lag-1 correlation " + brief(s.stats.lag1) +
                         " for " + std::to_string(s.stats.blocks) + " blocks): use fewer, longer blocks");
  const BlockingAnalysis& fp = s.blocking;
  if (fp.trend == BlockingTrend::Rising)
    r.warnings.push_back(name + ": the blocking analysis finds no plateau, its errors still rise at the "
                                "longest blocks: the error may be underestimated; use a longer window");
  if (fp.trend != BlockingTrend::Plateau) return;
  const double err = s.stats.error;
  const double slack = 2 * std::hypot(err / std::sqrt(2 * (b - 1)), fp.levels[fp.plateau].error_of_error);
  if (fp.error > err + slack)
    r.warnings.push_back(name + ": the blocking analysis gives a larger error (" + brief(fp.error) +
                         ") than the " + std::to_string(s.stats.blocks) + " blocks (" + brief(err) +
                         "): use fewer, longer blocks");
}

void check_report(PressureReport& r) {
  const double k0 = r.totals.kinetic_start, k1 = r.totals.kinetic_end;
  if (std::fabs(k1 - k0) > 1e-9 * std::fabs(k0))
    r.warnings.push_back("the kinetic energy changed by " + brief(100 * (k1 - k0) / k0) +
                         "% over the window (restitution < 1 or actions): the state is not stationary, "
                         "the pressures are window averages and the virial pressure is the collisional "
                         "stress, not an equilibrium pressure");
  if (r.has_walls()) check_series("wall pressure", r.wall_mean, r);
  check_series("virial pressure", r.virial, r);
}

}  // namespace

double henderson_z(double phi) { return (1 + phi * phi / 8) / ((1 - phi) * (1 - phi)); }

double PressureReport::ideal() const { return double(disks) * kT.stats.mean / area; }
double PressureReport::henderson() const { return henderson_z(packing_fraction) * ideal(); }
double PressureReport::expected_area() const { return has_walls() ? virial_area : area; }

Result<PressureReport> measure_pressure(const Log& opened, const PressureOptions& o) {
  if (std::string why = sheared_refusal(opened, "pressure"); !why.empty()) return Error{why};
  const std::shared_ptr<const LogReader> log = reader_of(opened);
  if (log->header().gx != 0 || log->header().gy != 0)
    return Error{log->path() + ": the run is under gravity: its pressure varies with height (hydrostatics), "
                 "and the wall and virial estimates here assume a uniform gas"};
  if (o.blocks < 2) return Error{"at least 2 blocks are needed for an error estimate"};
  if (o.bins_per_block < 1 || o.blocks * o.bins_per_block > 10'000'000)
    return Error{"blocks x bins per block must be between 2 and 10^7"};
  auto disks = log_disks(log);
  if (!disks) return disks.error();
  if (disks.value().count == 0) return Error{log->path() + ": the log has no disks"};
  PressureReport r;
  fill_geometry(log->header(), disks.value(), r);
  if (r.virial_area <= 0) return Error{log->path() + ": the disks are too large for the box"};
  if (Status s = choose_window(*log, disks.value(), o, r); !s) return s.error();
  r.blocks = o.blocks, r.bins_per_block = o.bins_per_block;
  auto bins = accumulate_pressure(log, r.t0, r.t1, o.blocks * o.bins_per_block);
  if (!bins) return bins.error();
  r.t0 = double(bins.value().t0), r.t1 = double(bins.value().t1);  // as the log's scalar type holds them
  fill_series(bins.value(), r);
  fill_blocks_and_totals(bins.value(), r);
  check_report(r);
  return r;
}

}  // namespace ede
