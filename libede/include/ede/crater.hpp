// Crater metrics: what an impact did to a bed of disks, measured from a log (docs/crater.md).
//
// Two layers. The geometry (displaced disks, surface profiles, depth, width, area) is a set of pure
// functions on plain arrays in double: two states of the same disks, a bed mask, and lengths; they know
// nothing of logs, so tests build states by hand and check exact answers. The log layer (the energy walk
// and measure_crater) replays a log to get those states: the initial one and the one at the chosen time.
// Rejected: metrics computed by an engine sink during the run. DESIGN.md keeps analysis out of the engine,
// and a metric defined on a log can be recomputed with other settings without running the physics again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/log.hpp"

namespace ede {

// ---- geometry on plain arrays ---------------------------------------------------------------------

// One state of the disks: centres and radii, one entry per disk, in the log's order. The two states
// given to the functions below are the same disks in the same order (before and after the impact).
struct DiskPositions {
  std::vector<double> x, y, r;
  std::size_t size() const { return x.size(); }
};

// The box the disks live in: [0, lx] x [0, ly]. With periodic boundaries a displacement is taken with the
// minimum image (so a disk that moved more than half a box length is undercounted).
struct CraterBox {
  double lx = 1, ly = 1;
  bool periodic = false;
};

// A length in box units, or in bed radii (value x r_bed, r_bed the mean radius of the bed disks before).
struct CraterLength {
  double value = 0;
  bool in_bed_radii = false;
};

// The lengths the analysis uses; the defaults are multiples of r_bed, so they mean the same for any grain size.
struct CraterSettings {
  CraterLength displacement_threshold{0.5, true};  // "displaced" means moved by more than this
  CraterLength bin_width{2, true};                 // profile bins (rounded so that they tile [0, lx])
  CraterLength drop_threshold{1, true};            // the crater is where the surface fell by more than this
  CraterLength link_gap{2, true};                  // the widest rim gap that still links two bed disks
  bool exclude_detached = true;  // the surface ignores bed disks not linked to the bed's body (ejecta)
};

// The settings with every default filled in: the numbers actually used, for reports.
struct CraterLengths {
  double bed_radius = 0;  // r_bed
  double displacement_threshold = 0, bin_width = 0, drop_threshold = 0, link_gap = 0;
  std::size_t bins = 0;
  bool exclude_detached = true;
};

// Fails if no disk is marked as bed, the arrays disagree in size, a length is not a finite number > 0
// (a threshold may be 0), or the box is not positive.
Result<CraterLengths> resolve_crater_lengths(const DiskPositions& before, const std::vector<bool>& is_bed,
                                             const CraterBox& box, const CraterSettings& settings);

// The bed disks (is_bed) whose centre moved by more than `threshold` between the two states, ascending.
std::vector<std::uint32_t> displaced_disks(const DiskPositions& before, const DiskPositions& after,
                                           const std::vector<bool>& is_bed, const CraterBox& box, double threshold);

// The bed's body in one state: the bed disks connected to the bottom of the bed. Two bed disks are linked
// when the gap between their rims is at most `link_gap` (centre distance <= r_i + r_j + link_gap); the body
// is every linked cluster holding a disk whose bottom (y - r) lies within `link_gap` of the lowest bottom
// of any bed disk. Disks outside it (ejecta in flight, a grain resting alone on the projectile) are
// "detached". Returns one flag per disk (false for non-bed disks). Cost O(N) with a uniform grid.
std::vector<bool> bed_body(const DiskPositions& state, const std::vector<bool>& is_bed, const CraterBox& box,
                           double link_gap);

// The surface profile h(x) over `bins` equal bins tiling [0, lx]: bin k covers [k w, (k + 1) w) with
// w = lx / bins (a centre at exactly lx, or outside the box, counts in the nearest end bin). h of a bin is
// the highest top (y + r) of the counted disks whose centre lies in it; a bin with none has h = 0, the
// bottom of the box (there is no bed material above the floor in that column).
struct SurfaceProfile {
  double bin_width = 0;
  std::vector<double> height;        // h per bin
  std::vector<std::uint32_t> disks;  // counted disks with their centre in the bin
  std::size_t detached = 0;          // bed disks left out as detached
  double centre(std::size_t k) const { return (double(k) + 0.5) * bin_width; }
};

// `counted`: the disks that make the surface (the bed's body, or all bed disks).
SurfaceProfile surface_profile(const DiskPositions& state, const std::vector<bool>& counted, double lx,
                               std::size_t bins);

// The crater, from the profiles before and after (same bins). drop(k) = h_before(k) - h_after(k).
struct CraterMetrics {
  double depth = 0;             // max_k drop(k); 0 or negative if the surface nowhere fell
  std::size_t deepest_bin = 0;  // where drop is largest (the leftmost of equal maxima)
  double deepest_x = 0;         // that bin's centre
  double depth_below_mean = 0;  // mean_k h_before(k) - min_k h_after(k): depth below the initial mean level
  bool has_crater = false;      // drop(deepest) > drop_threshold
  // The crater region: the contiguous run of bins around the deepest one with drop > drop_threshold,
  // [left, right) in x; empty (left == right == deepest_x) when there is no crater.
  std::size_t first_bin = 0, last_bin = 0;  // inclusive; meaningful when has_crater
  double left = 0, right = 0;
  double width = 0;          // right - left
  double area = 0;           // sum over the crater region of w * drop(k): the area between the profiles there
  double removed_area = 0;   // sum over all bins of w * max(drop, 0)
  double raised_area = 0;    // sum over all bins of w * max(-drop, 0): rims and ejecta deposits
};

// Fails if the profiles have different bins or none.
Result<CraterMetrics> crater_metrics(const SurfaceProfile& before, const SurfaceProfile& after,
                                     double drop_threshold);

// Everything above in one call.
struct CraterReport {
  CraterLengths lengths;
  std::vector<std::uint32_t> displaced;  // bed disks moved by more than the displacement threshold
  std::size_t bed_disks = 0;
  SurfaceProfile before, after;
  CraterMetrics metrics;
};

Result<CraterReport> analyze_crater(const DiskPositions& before, const DiskPositions& after,
                                    const std::vector<bool>& is_bed, const CraterBox& box,
                                    const CraterSettings& settings);

// ---- from a log -----------------------------------------------------------------------------------

// The kinetic energy over a logged run, from one walk over its events.
//
// E(n) is the kinetic energy of the state after the first n events, summed exactly as ede::kinetic_energy
// sums it (engine.hpp); E0 = E(0). The crossing is the first n with E(n) <= fraction * E0 (both in double,
// as the engine's stop test). The walk keeps a running sum updated by each event's energy change and
// confirms every candidate crossing with the full sum, so the answer is exactly what summing the replayed
// states gives; the curve points use the running sum (relative error ~1e-15).
struct EnergyFractionCurve {
  double initial_energy = 0;  // E0
  double fraction = 0.1;      // the fraction asked for
  bool reached = false;
  std::uint64_t event = 0;    // reached: the n above (events applied); else the log's event count
  double time = 0;            // reached: the time of event n; else the log's end
  double end_time = 0;        // the log's end (the final time of a complete log, else its last event)
  double end_fraction = 0;    // E(all events) / E0
  std::vector<double> t, f;   // the curve: E / E0 after every event with time <= t, on a uniform grid of [0, end]
};

// `points` >= 2 grid points. Fails if the log cannot be replayed or E0 is 0.
Result<EnergyFractionCurve> energy_fraction_curve(const Log& log, double fraction,
                                                  std::size_t points = 501);

// Which disks are the bed. `name` empty: the species named "bed" if there is one, else every species
// with more than one disk. Fails naming the species the log has if `name` is not one of them, or if the
// default finds nothing.
struct BedSelection {
  std::vector<bool> is_bed;
  std::vector<std::string> species;  // the bed's species names
  std::string reason;                // how they were chosen, for reports
  std::size_t disks = 0;
};
Result<BedSelection> select_bed(const Log& log, const std::string& name);

// A crater measured from a log: the initial state against the state at the chosen time.
struct CraterRequest {
  std::optional<Time> at;       // measure at this time (exact in the log's type) instead of the energy criterion
  bool at_end = false;          // measure at the log's end instead of the energy criterion
  std::optional<Time> before;   // the reference ("before") state at this time instead of the log's start
  double energy_fraction = 0.1;  // otherwise: when this fraction of E0 remains, else at the log's end
  std::string bed_species;      // see select_bed
  CraterSettings settings;
  std::size_t curve_points = 501;
};

enum class CraterTimeSource { EnergyFraction, LogEnd, Requested };

struct CraterMeasurement {
  BedSelection bed;
  CraterTimeSource source = CraterTimeSource::EnergyFraction;
  double time = 0;              // when the "after" state is taken
  double before_time = 0;       // when the "before" state is taken
  std::uint64_t events = 0;     // events applied in that state
  double energy_fraction = 0;   // E / E0 of that state (full sum); NaN under gravity
  std::string when;             // the choice of time in words
  // Under gravity the kinetic energy changes between collisions (and a bed at rest under a falling
  // projectile starts with none): no fraction, no curve; the time must be asked for.
  bool has_energy = true;
  EnergyFractionCurve energy;
  CraterBox box;
  CraterReport report;
};

// Fails if the log cannot be replayed, `at` is after its end, or the bed or the settings are invalid.
Result<CraterMeasurement> measure_crater(const Log& log, const CraterRequest& request = {});

const char* to_string(CraterTimeSource);

// ---- scans: many runs measured alike ----------------------------------------------------------------
// A scan runs a scene for several values of one parameter and several seeds, and measures every log the
// same way; these turn the measurements into the scan's table. Rejected: leaving the averages to each
// front end, whose tables would then disagree in their last digits.

// The metrics of a measurement as numbers, in the order of a scan's CSV columns: count (displaced disks),
// depth, width, area, depth_below_mean, deepest_x, removed_area, raised_area, detached (after the impact).
const std::vector<std::string>& crater_metric_names();
std::vector<double> crater_metric_values(const CraterMeasurement& m);

// The mean of n values and its standard error, s / sqrt(n) with s the sample standard deviation (n - 1);
// the error is NaN for n < 2.
struct MeanAndError {
  std::size_t n = 0;
  double mean = 0;
  double error = std::numeric_limits<double>::quiet_NaN();
};
MeanAndError mean_and_error(const std::vector<double>& values);

// The runs of one value of a scan.
struct CraterScanGroup {
  std::size_t runs = 0;
  std::vector<MeanAndError> metrics;   // one per crater_metric_names(), over the runs
  std::size_t at_log_end = 0;          // runs measured at their log's end (CraterTimeSource::LogEnd)
  std::size_t requested = 0;           // runs measured at a time asked for
  double first_time = std::numeric_limits<double>::infinity();   // the earliest measuring time
  double last_time = -std::numeric_limits<double>::infinity();   // the latest
};

// groups[v] summarises the runs k with value_of_run[k] == v, for v < values (runs and value_of_run have
// one entry per run).
std::vector<CraterScanGroup> group_crater_scan(const std::vector<CraterMeasurement>& runs,
                                               const std::vector<std::size_t>& value_of_run, std::size_t values);

// A run of a scan as the numbers its table keeps (what a sweep's row carries from the run's process to
// the table): the metrics in crater_metric_values' order, and when it was measured and why.
struct CraterScanRun {
  std::vector<double> metrics;
  CraterTimeSource source = CraterTimeSource::EnergyFraction;
  double time = 0;
};
CraterScanRun crater_scan_run(const CraterMeasurement& m);
// The same grouping from those numbers (group_crater_scan of the measurements is this of crater_scan_run).
std::vector<CraterScanGroup> group_crater_scan(const std::vector<CraterScanRun>& runs,
                                               const std::vector<std::size_t>& value_of_run, std::size_t values);

// Where a scan value (a TOML value, as typed) sits on a plot's axis: a number is itself, an array of
// numbers its Euclidean length (a velocity vector gives the speed); NaN for anything else.
double scan_axis_position(const std::string& value);

}  // namespace ede
