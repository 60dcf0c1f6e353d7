// g(r) per species pair from states, streamed over a log's frames (structure.hpp has the normalisation).
// One pass over the pairs within r_max with the cell grid; counts and the ideal-gas expectation are summed
// over frames, so the average of g over frames weights each frame by its ideal count (equal for a fixed
// box and N). Rejected: averaging g frame by frame, which gives noisy small-r bins the same weight.
#include <cmath>
#include <string>

#include "analysis/structure_cells.hpp"
#include "ede/structure.hpp"

namespace ede {

namespace {

double mean_radius(const State& s) {
  double sum = 0;
  for (std::size_t i = 0; i < s.size(); ++i) sum += s.radius[i];
  return s.size() ? sum / double(s.size()) : 0;
}

// The region the centres occupy: the box (periodic) or the box shrunk by the mean radius on every side.
void centre_region(const State& s, double& lx, double& ly) {
  const double shrink = s.boundary == BoundaryKind::Periodic ? 0 : 2 * mean_radius(s);
  lx = s.lx - shrink;
  ly = s.ly - shrink;
}

// integral over [r1, r2] of 2 pi r gamma(r) dr (structure.hpp).
double shell_integral(double r1, double r2, double lx, double ly, bool periodic) {
  const double a = lx * ly;
  const double p2 = r2 * r2 - r1 * r1;
  if (periodic) return M_PI * a * p2;
  const double p3 = r2 * r2 * r2 - r1 * r1 * r1, p4 = r2 * r2 * r2 * r2 - r1 * r1 * r1 * r1;
  return M_PI * a * p2 - 4.0 / 3.0 * (lx + ly) * p3 + 0.5 * p4;
}

Status check_options(const State& s, const PairCorrelationOptions& o) {
  if (!(o.r_max > o.r_min) || o.r_min < 0 || o.bins == 0)
    return Error{"g(r): need 0 <= r_min < r_max and bins >= 1 (got r_min " + std::to_string(o.r_min) + ", r_max " +
                 std::to_string(o.r_max) + ")"};
  double lx, ly;
  centre_region(s, lx, ly);
  const double limit = s.boundary == BoundaryKind::Periodic ? 0.5 * std::min(lx, ly) : std::min(lx, ly);
  if (o.r_max > limit)
    return Error{"g(r): r_max " + std::to_string(o.r_max) + " is beyond " + std::to_string(limit) +
                 (s.boundary == BoundaryKind::Periodic ? " (half the shorter side of the periodic box)"
                                                       : " (the shorter side of the region the centres fill)") +
                 "; choose a smaller r_max"};
  const auto n_species = std::int32_t(s.species_names.size());
  for (const std::int32_t sp : {o.species_a, o.species_b})
    if (sp >= n_species) return Error{"g(r): species index " + std::to_string(sp) + " is not in the state"};
  return Ok{};
}

}  // namespace

Result<std::vector<double>> frame_times(const Log& log, const FrameTimes& f) {
  const double start = double(log.info().start_time), end = double(log.info().end_time);
  const double from = f.from.value_or(f.to.value_or(end)), to = f.to.value_or(f.frames > 1 ? end : from);
  if (f.frames == 0) return Error{"frames must be >= 1"};
  if (!(from >= start && to <= end && from <= to))
    return Error{log.info().path + ": frame times " + std::to_string(from) + " to " + std::to_string(to) +
                 " are not within the log's " + std::to_string(start) + " to " + std::to_string(end)};
  std::vector<double> t(f.frames);
  for (std::size_t k = 0; k < f.frames; ++k)
    t[k] = f.frames == 1 ? from : from + (to - from) * double(k) / double(f.frames - 1);
  return t;
}

Status add_pair_correlation(const State& s, const PairCorrelationOptions& o, PairCorrelation& acc) {
  if (Status c = check_options(s, o); !c) return c;
  const bool periodic = s.boundary == BoundaryKind::Periodic;
  if (acc.r_lo.empty()) {
    acc.r_lo.resize(o.bins);
    acc.r_hi.resize(o.bins);
    const double w = (o.r_max - o.r_min) / double(o.bins);
    for (std::size_t k = 0; k < o.bins; ++k) {
      acc.r_lo[k] = o.r_min + w * double(k);
      acc.r_hi[k] = k + 1 == o.bins ? o.r_max : o.r_min + w * double(k + 1);
    }
    acc.count.assign(o.bins, 0);
    acc.ideal.assign(o.bins, 0);
  }
  const auto in = [](std::int32_t sp, std::int32_t want) { return want < 0 || sp == want; };
  std::size_t na = 0, nb = 0, nab = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    na += in(s.species[i], o.species_a);
    nb += in(s.species[i], o.species_b);
    nab += in(s.species[i], o.species_a) && in(s.species[i], o.species_b);
  }
  structure::Points p = structure::points_of(s);
  std::vector<std::int32_t> sp = s.species;
  const structure::CellGrid grid(p, o.r_max);
  const double inv_w = double(o.bins) / (o.r_max - o.r_min);
  grid.for_pairs(o.r_max, [&](std::size_t i, std::size_t j, double, double, double r2) {
    const double r = std::sqrt(r2);
    if (r < o.r_min) return;
    const auto k = std::min(o.bins - 1, std::size_t((r - o.r_min) * inv_w));
    const int c = int(in(sp[i], o.species_a) && in(sp[j], o.species_b)) +
                  int(in(sp[j], o.species_a) && in(sp[i], o.species_b));
    acc.count[k] += c;
  });
  double lx, ly;
  centre_region(s, lx, ly);
  const double area = lx * ly;
  // Ordered pairs (i in a, j in b, i != j): N_a N_b minus the disks in both selections.
  const double pairs = double(na) * double(nb) - double(nab);
  for (std::size_t k = 0; k < o.bins; ++k)
    acc.ideal[k] += pairs / (area * area) * shell_integral(acc.r_lo[k], acc.r_hi[k], lx, ly, periodic);
  if (acc.frames == 0) {
    acc.n_a = na;
    acc.n_b = nb;
    acc.area = area;
    acc.density_b = double(nb) / area;
  }
  ++acc.frames;
  return Ok{};
}

void finish_pair_correlation(PairCorrelation& acc) {
  acc.g.resize(acc.count.size());
  for (std::size_t k = 0; k < acc.count.size(); ++k) acc.g[k] = acc.ideal[k] > 0 ? acc.count[k] / acc.ideal[k] : 0;
}

Result<PairCorrelation> pair_correlation(const State& s, const PairCorrelationOptions& o) {
  PairCorrelation acc;
  if (Status a = add_pair_correlation(s, o, acc); !a) return a.error();
  finish_pair_correlation(acc);
  return acc;
}

Result<PairCorrelation> pair_correlation(const Log& log, const PairCorrelationOptions& o, const FrameTimes& f) {
  auto times = frame_times(log, f);
  if (!times) return times.error();
  PairCorrelation acc;
  for (const double t : times.value()) {
    auto s = log.state_at(t);
    if (!s) return s.error();
    if (Status a = add_pair_correlation(s.value(), o, acc); !a) return Error{log.info().path + ": " + a.error().message};
  }
  finish_pair_correlation(acc);
  return acc;
}

}  // namespace ede
