// Analysis of runs: distributions and the Maxwell-Boltzmann test, gas observables per species, block
// averages, series over time from a log (energy, collisions), the reports the analysis commands print
// (distribution, species, energy with Haff's law, collisions), and frames for pictures. Pressure and
// craters have headers of their own (ede/pressure.hpp, ede/crater.hpp).
//
// Two layers. Pure functions on plain numbers (histograms, KS tests, averages of a GasSnapshot) know
// nothing of logs and are tested on hand-made samples. Functions of a Log walk or seek the log once and
// feed them. Every figure a user makes comes from a log: nothing here reruns the physics.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/kinetic_theory.hpp"
#include "ede/log.hpp"

namespace ede {

// ==== Distributions ==============================================================================
// Distributions: histograms with given bins, the 2D Maxwell-Boltzmann law, and the Kolmogorov-Smirnov test.
//
// Pure functions of samples (doubles), no log and no state: the analysis tools feed them speeds or
// energies taken from a replayed log. In 2D at temperature kT a disk of mass m has the speed density
// p(v) = (m v / kT) exp(-m v^2 / 2kT) and the kinetic-energy density p(E) = exp(-E/kT) / kT: E = m v^2 / 2
// is exponential with mean kT whatever the mass, so a sample of mixed masses is tested on its energies, and
// for one mass a test on speeds gives the same statistic (KS is invariant under the monotone map v -> E).
// The KS p-value uses the asymptotic Kolmogorov distribution with Stephens' small-n correction; it
// assumes independent samples and a law fixed in advance (see docs/analysis.md for the caveats).
// Rejected: fitting with chi-square on the histogram, whose result depends on the binning the user chose.

// Counts of samples in bins [edges[k], edges[k+1]); the last bin is closed [edges[K-1], edges[K]].
struct Histogram {
  std::vector<double> edges;         // K + 1 strictly increasing edges
  std::vector<std::uint64_t> count;  // K counts
  std::uint64_t outside = 0;         // samples in no bin (below, above, or NaN)

  std::size_t bins() const { return count.size(); }
  std::uint64_t samples() const;     // every sample given, inside or not
};

// K bins of equal width from lo to hi (K >= 1, lo < hi); the last edge is exactly hi.
std::vector<double> uniform_edges(double lo, double hi, std::size_t bins);
// The histogram of `samples` in the given bins (edges as uniform_edges makes them, or any increasing list).
Histogram make_histogram(const std::vector<double>& samples, std::vector<double> edges);
// count / (samples * width) per bin: integrates to the fraction of samples inside the bins (1 when none
// falls outside); all zero for an empty sample.
std::vector<double> densities(const Histogram& h);

// The 2D Maxwell-Boltzmann law for one mass (kT > 0, m > 0); zero below 0.
double mb_speed_density(double v, double mass, double kT);
double mb_speed_cdf(double v, double mass, double kT);  // 1 - exp(-m v^2 / 2kT)
double mb_energy_density(double e, double kT);          // exp(-E/kT) / kT
double mb_energy_cdf(double e, double kT);              // 1 - exp(-E/kT)

enum class Quantity { Speed, Energy };
const char* to_string(Quantity);

// The Maxwell-Boltzmann law of a population of disks at one temperature: for speeds, a mixture of the
// single-mass densities weighted by the fraction of disks of each mass; for energies, exponential.
struct MaxwellBoltzmann {
  struct Share {
    double mass = 1;
    double fraction = 1;
  };
  double kT = 1;
  std::vector<Share> masses;  // fractions sum to 1

  double density(Quantity q, double x) const;
  double cdf(Quantity q, double x) const;
  // The mean density over [lo, hi]: (cdf(hi) - cdf(lo)) / (hi - lo), what a histogram bin should show.
  double bin_density(Quantity q, double lo, double hi) const;
};
// The law for a sample whose disks have these masses (one entry per disk), grouped by distinct mass.
MaxwellBoltzmann maxwell_boltzmann_for(const std::vector<double>& masses, double kT);

// P(K > lambda) for the Kolmogorov distribution: 2 sum_{j>=1} (-1)^(j-1) exp(-2 j^2 lambda^2), with the
// Jacobi-transformed series for small lambda where that one converges slowly.
double kolmogorov_q(double lambda);

struct KsResult {
  double statistic = 0;  // D = sup |F_n(x) - F(x)|
  double p_value = 1;    // asymptotic, with Stephens' correction
  std::size_t n = 0;
};

// The exact KS statistic of a sample against a continuous CDF (the sample is copied and sorted).
double ks_statistic(std::vector<double> sample, const std::function<double(double)>& cdf);
// Q((sqrt(n) + 0.12 + 0.11 / sqrt(n)) D) (Stephens 1970); 1 for n = 0.
double ks_p_value(double statistic, std::size_t n);
KsResult ks_test(std::vector<double> sample, const std::function<double(double)>& cdf);
// Kinetic energies against the exponential law of mean kT: the MB test for any mix of masses.
KsResult ks_test_mb_energies(std::vector<double> energies, double kT);

// ==== Gas observables ============================================================================
// Gas observables: what the velocities of a gas at one time say, per species and for the whole gas.
//
// A GasSnapshot is the velocities of every disk at one time (in double, whatever the log's scalar type)
// with the per-disk constants (mass, species); log_series.hpp makes them from a log. From it: speeds and
// kinetic energies of a selection, per-species means, the temperature, and the speed classes of the
// GasLab model. The temperature is 2D equipartition, kT = <m v^2 / 2> (two degrees of freedom of kT/2
// each, k = 1); it counts any bulk flow as heat, which is right for a gas at rest in its box.
// Averages may be pooled over several snapshots (GasAverages::add), e.g. several times of one run.
// Rejected: computing these inside the tools, where they could not be tested without a log.

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

// ==== Block averages =============================================================================
// Block averaging: the mean of a time series and its standard error when successive values are correlated.
//
// A series of equal-length time bins is cut into B blocks; the block means are close to independent when a
// block is much longer than the correlation time, and the standard error of the mean is then the sample
// standard deviation of the block means over sqrt(B). Two checks come with it: the lag-1 autocorrelation
// of the block means (near 0 when blocks are independent; its noise is ~1/sqrt(B)), and the blocking
// analysis of Flyvbjerg and Petersen (J. Chem. Phys. 91, 461 (1989)) on the fine bins: the series is
// halved again and again by averaging neighbours, the naive error estimate grows while blocks are shorter
// than the correlation time and levels off once they are longer; the plateau is the error.
// Rejected: estimating the integrated autocorrelation time from the fine series directly (windowing and
// cut-off choices, and it needs the whole autocorrelation function) for a quantity as short-correlated as
// a hard-disk gas's pressure, where blocking is simpler and says plainly when it has not converged.

struct BlockStats {
  std::size_t blocks = 0;
  double mean = 0;
  double error = 0;  // standard error of the mean: sample standard deviation (n - 1) / sqrt(B)
  double lag1 = 0;   // lag-1 autocorrelation of the block means (0 when they are all equal)
};

// Mean, standard error and lag-1 autocorrelation of a series of block means (at least 2).
BlockStats block_stats(const std::vector<double>& block_means);

// The means of consecutive groups of `per_block` values (a shorter last group is dropped).
std::vector<double> coarse_grain(const std::vector<double>& fine, std::size_t per_block);

struct BlockingLevel {
  std::size_t blocks = 0;       // values in the series at this level
  double error = 0;             // sqrt(c0 / (n - 1)): the standard error if the values were independent
  double error_of_error = 0;    // error / sqrt(2 (n - 1))
};

// Without a plateau the estimates either keep rising (correlations longer than the coarsest blocks: the
// error is underestimated) or keep falling (anticorrelated values, e.g. wall hits more regular than a
// Poisson process: the coarsest estimate is an upper bound).
enum class BlockingTrend { Plateau, Rising, Falling };

struct BlockingAnalysis {
  std::vector<BlockingLevel> levels;  // level 0 is the series itself; each next level halves it
  // The plateau: the first level with whose error every coarser level with at least min_blocks values
  // agrees within two of that level's error bars. converged: at least two coarser levels confirm it (one
  // is not enough: with few blocks a change by sqrt(2) per level, the signature of blocks shorter than
  // the correlation time, hides in the noise of the coarsest level).
  std::size_t plateau = 0;
  bool converged = false;
  BlockingTrend trend = BlockingTrend::Rising;  // Plateau when converged
  double error = 0;                             // levels[plateau].error
};

// Flyvbjerg-Petersen blocking of a series of equal-length bins.
BlockingAnalysis blocking_analysis(const std::vector<double>& series, std::size_t min_blocks = 16);

// ==== Series over time, from a log ===============================================================
// Log series: observables of a run on a time grid, and snapshots at given times, from its event log.
//
// log_series walks the events once, in order, keeping a mirror of the state just before the event at hand:
// the kinetic energy of every disk, computed from its velocity (events carry only the velocities after
// them). An event replaces its disks' energies in running sums (long double), so the total and per-species energies on a grid of any fineness cost
// O(events + grid points), not one replay per point. The value at a grid time t is that of the state
// after every event with time <= t, as Replay::seek_time(t) defines it, so it equals the sum over the
// replayed state at t up to the rounding of the running sums. Pair and wall collisions are counted on
// the same walk. An action (reversing every velocity) resynchronises the mirror from the replayed state.
// for_each_snapshot gives the velocities at a few times through Replay::seek_time, forward only: each
// seek continues from the last, or jumps to a later keyframe when that is cheaper.
// Rejected: one seek_time per grid point for the energy series: O(points x (keyframe + events since it)),
// hundreds of times slower on the fine grids the energy curves need.
// Times are doubles; in a float or long double log a grid time means that value converted to the log's
// type (exact for long double, rounded for float).

// What a log says without replaying it: its size, its end and its collision counts (from the kinds column).
struct LogOverview {
  std::size_t disks = 0;
  double end_time = 0;  // the time the run reached, rounded down to a double (so it is within the log)
  std::uint64_t pair_events = 0, wall_events = 0;
  // The mean time between two pair collisions of one disk over the whole run: N t_end / (2 pairs);
  // infinity without pair collisions.
  double mean_free_time() const {
    return pair_events ? double(disks) * end_time / (2.0 * double(pair_events)) : std::numeric_limits<double>::infinity();
  }
};
Result<LogOverview> log_overview(const Log& log);

// t0, t0 + dt, t0 + 2 dt, ... (each computed as t0 + k dt, so no error accumulates), none above t1; empty
// if t1 < t0, dt <= 0, or the grid would have more than max_points points.
std::vector<double> time_grid(double t0, double t1, double dt, std::size_t max_points = 10'000'000);
// The same grid with t1 itself appended when the grid stops short of it (both ends included); empty when
// time_grid is.
std::vector<double> time_grid_to(double t0, double t1, double dt, std::size_t max_points = 10'000'000);

struct LogSeries {
  std::vector<double> time;
  std::vector<std::string> species_names;
  std::vector<std::uint64_t> species_count;            // disks per species
  std::vector<double> kinetic_energy;                  // total, at each time
  std::vector<std::vector<double>> species_energy;     // [species][k]: total kinetic energy of the species
  std::vector<std::uint64_t> pair_collisions;          // pair events with time <= t (cumulative)
  std::vector<std::uint64_t> wall_collisions;          // wall events with time <= t (cumulative)

  std::uint64_t disks() const;
  double collisions_per_particle(std::size_t k) const;  // 2 pair_collisions / N
  double mean_kinetic_energy(std::size_t k) const;      // per disk
  double species_mean_energy(std::size_t s, std::size_t k) const;
};

// The series at the given times (non-decreasing, within [0, end of the log]).
Result<LogSeries> log_series(const Log& log, const std::vector<double>& times);

// The state's velocities at each of the given times (non-decreasing, within the log), one snapshot at a
// time; the snapshot passed to f is reused between calls.
Status for_each_snapshot(const Log& log, const std::vector<double>& times,
                         const std::function<void(const GasSnapshot&)>& f);

// ==== Reports from a log =========================================================================
// What the analysis commands report, one call each, returning plain structs: the tools print them, and
// the Python module and the live view read the same fields. Each walks or seeks the log through the
// functions above. Times are doubles within the log, as for log_series; a species is an index into the
// log's species names (species_index), or kAllSpecies.
// Rejected: leaving these compositions in the tools, where every front end would write them again and no
// test could reach them without running a program.

// The index of the species called `name`; "" means every disk (kAllSpecies). The error lists the species.
Result<std::int32_t> species_index(const LogInfo& info, const std::string& name);

// The speeds or kinetic energies of the selected disks at the given times (pooled: each time adds its
// disks again), against 2D Maxwell-Boltzmann at the temperature of the sample itself, kT = <m v^2 / 2>,
// with the initial state (t = 0) in the same bins beside it. The KS test runs on kinetic energies
// (exponential with mean kT for any mix of masses). The bins are `bins` equal bins from 0 to the largest
// value of the sample or of the initial state (to 1 if both are 0). kT is fitted from the same sample,
// which makes p somewhat too large; pooled times closer than a few mean free times see nearly the same
// disks, and p is then approximate.
struct DistributionRequest {
  std::vector<double> times;       // one time, or several to pool (non-decreasing, within the log)
  std::int32_t species = kAllSpecies;
  Quantity quantity = Quantity::Speed;
  std::size_t bins = 40;           // at least 1
  std::size_t curve_points = 400;  // intervals of the law's curve for figures
};

struct DistributionReport {
  std::size_t disks = 0;                         // selected disks at one time
  std::size_t samples = 0;                       // values in the histogram: disks x times
  double kT = 0;                                 // of the sample
  KsResult ks;                                   // the sample's energies against exp(-E/kT) / kT
  double initial_kT = 0;                         // of the selected disks at t = 0 (0: at rest, no test)
  KsResult initial_ks;                           // against the law at initial_kT
  MaxwellBoltzmann law;                          // at kT, for the selection's masses
  Histogram histogram, initial;                  // the same bins
  std::vector<double> density, initial_density;  // densities() of the two
  std::vector<double> law_density;               // law.bin_density per bin: what each bin should show
  std::vector<double> curve_x, curve_density;    // the law at curve_points + 1 points from 0 to the last edge
};

// Fails if a time is outside the log, bins is 0, or the selected disks are at rest (kT = 0).
Result<DistributionReport> measure_distribution(const Log& log, const DistributionRequest& request);

// species_stats at each time (one snapshot each): every species, then "all"; or one species alone.
struct SpeciesTable {
  double time = 0;
  std::vector<SpeciesStats> rows;
};
Result<std::vector<SpeciesTable>> species_tables(const Log& log, const std::vector<double>& times,
                                                 std::int32_t species = kAllSpecies);

// The kinetic energy (total and per species) on a grid, with Haff's law for an inelastic run.
//
// The grid runs from `from` to `to` (default: the whole log), both included: every `every` (default 1/20
// of the whole run's mean free time, N t_end / 2 pairs, or 1/1000 of the range without collisions), or at
// `points` evenly spaced times. E(0) is always the energy at t = 0, whatever the range.
// Haff's law for a homogeneous cooling gas of equal disks (2D): each collision loses on average
// (1 - xi^2) kT (the collision-weighted mean of (g.n)^2 is 4 kT / m for Maxwell-Boltzmann velocities), so
// dT/dt = -(1 - xi^2) omega T / 2 with the collision frequency omega proportional to sqrt(T):
//   E(t) / E(0) = (1 + t / tau)^-2,  tau = 4 / ((1 - xi^2) omega0),
// and the collisions per disk grow as C(t) = omega0 tau ln(1 + t / tau). The first grid time t1 > 0 at
// which the log reaches C1 = 2 collisions per disk (about 2N collisions: a 2% statistical error; the last
// grid time if it never does) gives omega0 exactly within the model, with no fitted curve:
//   omega0 = 4 (exp((1 - xi^2) C1 / 4) - 1) / ((1 - xi^2) t1).
struct EnergyCurveRequest {
  std::optional<double> from, to;     // the range (default: 0 and the end of the log)
  std::optional<double> every;        // the spacing (> 0)
  std::optional<std::size_t> points;  // instead of every: this many points (2 at least; fewer count as 2)
  std::size_t max_points = 5'000'000;
};

struct EnergyCurve {
  LogSeries series;                                         // on the grid
  double restitution = std::numeric_limits<double>::quiet_NaN();  // xi of the log's scene; NaN if unreadable
  double spacing = 0;                                       // the grid's spacing (0 with points)
  bool default_spacing = false;                             // chosen by the rule above
  double mean_free_time = 0;                                // of the whole run
  double initial_energy = 0;                                // E(0)
  double haff_tau = std::numeric_limits<double>::quiet_NaN();  // Haff's cooling time; NaN if elastic
  double haff_calibration = 0;                              // C1: the collisions per disk omega0 came from
  // Haff's tau from Enskog's collision rate at t = 0 (ede/kinetic_theory.hpp), computed before looking at
  // the curve, with its stated uncertainty; NaN if elastic or not applicable (a mixture: see enskog_note).
  // haff_ratio uses it when it is finite, else haff_tau.
  double enskog_tau = std::numeric_limits<double>::quiet_NaN();
  double enskog_tau_error = std::numeric_limits<double>::quiet_NaN();
  double enskog_rate0 = std::numeric_limits<double>::quiet_NaN();  // omega_E(0) per disk
  std::string enskog_note;                                  // why there is no enskog_tau

  double ratio(std::size_t k) const;       // E(t_k) / E(0); NaN if E(0) = 0
  double haff_ratio(std::size_t k) const;  // (1 + t_k / tau)^-2 (tau: enskog_tau, else haff_tau); NaN without
  double max_drift() const;                // max over the grid of |E / E(0) - 1| (0 if E(0) = 0)
};

// Fails on a range outside the log, a spacing <= 0, or a grid of more than max_points points.
Result<EnergyCurve> energy_curve(const Log& log, const EnergyCurveRequest& request = {});

// Collisions over time: the counts of log_series; per interval since the time before, the pair collision
// rate per disk, 2 (pairs(t_k) - pairs(t_k-1)) / (N (t_k - t_k-1)), and the mean free time 1 / rate
// (infinity for a rate of 0), both NaN at the first time and after an empty interval; and the speed
// classes at each time against the mean speed at the first time (the initial one when the times start at
// 0). Wall collisions are counted apart and take no part in the rate (kinetic theory's mean free time is
// the time between collisions with other disks).
struct CollisionSeries {
  LogSeries series;
  double reference_speed = 0;
  std::vector<SpeedClasses> classes;
  std::vector<double> rate, mean_free_time;
  // Enskog's rate per disk for each interval (the mean of omega_E at its ends; NaN where rate is, or for
  // a mixture) and the reference at the first time (ede/kinetic_theory.hpp).
  std::vector<double> enskog_rate;
  EnskogReference enskog;
};
Result<CollisionSeries> collision_series(const Log& log, const std::vector<double>& times);

// ==== Frames: the disks as a picture shows them ==================================================
// What a picture or a live view of one state needs, in double: positions (wrapped into a periodic box),
// radii, speeds, the displacement from an initial state, the species; and what stands out: the GasLab
// speed classes against the initial mean speed, the marked disks (a projectile), the top of a displacement
// colour scale. The colours are the front end's. Rejected: a frame per scalar type (the drawing code
// would exist three times) and the front ends computing these from a State each in their own way.

struct DiskFrame {
  Time time = 0;
  double lx = 1, ly = 1;
  bool periodic = false;
  std::vector<std::string> species_names;  // the log's, all of them
  std::vector<double> x, y, r, speed;
  std::vector<double> displacement;        // from the initial state (periodic: the nearest image's)
  std::vector<std::int32_t> species;
  double initial_mean_speed = 0;           // the mean speed of these disks in the initial state
  // Wall segments (ax, ay, bx, by) to draw; disk_frame leaves it empty (a State carries none), a reader
  // of a log fills it from the log's scene (ede-render does).
  std::vector<std::array<double, 4>> segments;

  std::size_t size() const { return x.size(); }
};

// The disks of `state` (one species, or all) with their displacements from `initial`, the same run at an
// earlier time (usually its start).
DiskFrame disk_frame(const State& state, const State& initial, std::int32_t species = kAllSpecies);

enum class SpeedClass { Slow, Medium, Fast };
// Slow below 0.5 v_ref, fast above 1.5 v_ref, medium in between (as speed_classes counts).
SpeedClass speed_class(double speed, double reference_speed);

// The disks of the named species; with no names, those of every species that has exactly one disk in the
// frame (a projectile), unless every species has one disk. Fails naming the species for an unknown name.
Result<std::vector<bool>> marked_disks(const DiskFrame& frame, const std::vector<std::string>& species_names);
// The top of a displacement colour scale: the 95th percentile of the unmarked disks' displacements (a
// projectile and a few ejecta would leave the rest pale), or the mean radius if they have not moved.
double displacement_scale(const DiskFrame& frame, const std::vector<bool>& marked);

// Times from t0 to t1 for frames, each a value of the scalar type within [t0, t1] (t0 and t1 are): `count`
// evenly spaced, both ends included (one: t0); or t0 + k every (each computed from k, not accumulated) up
// to t1. Empty if t1 < t0, count is 0, every <= 0, or there would be more than max_count.
std::vector<Time> evenly_spaced_times(Time t0, Time t1, std::size_t count, ScalarKind scalar);
std::vector<Time> times_every(Time t0, Time t1, Time every, ScalarKind scalar, std::size_t max_count);

}  // namespace ede
