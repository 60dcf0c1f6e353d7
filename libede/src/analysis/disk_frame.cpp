// Frames (ede/analysis.hpp): a State as a picture shows it, what stands out in it, and frame times.
//
// A frame is plain doubles: State columns read as double (exact for float and double runs), so the drawing
// and colouring code exists once. Displacements are taken before wrapping, then reduced to the nearest
// image in a periodic box (the log's positions are wrapped, crossings are not counted). Frame times are
// computed from their index in long double (Time) and rounded to the log's type, so the k-th frame of a
// movie is the same value however many came before. Rejected: accumulating t += dt, which drifts by a
// rounding per frame.
#include <algorithm>
#include <cmath>

#include "ede/analysis.hpp"

namespace ede {

namespace {

double wrap(double v, double l) {
  const double w = v - l * std::floor(v / l);
  return w >= l ? 0 : w;
}

std::vector<std::size_t> species_counts(const DiskFrame& f) {
  std::vector<std::size_t> n(f.species_names.size(), 0);
  for (const std::int32_t s : f.species) {
    if (s < 0) continue;
    if (std::size_t(s) >= n.size()) n.resize(std::size_t(s) + 1, 0);
    ++n[std::size_t(s)];
  }
  return n;
}

Time round_to(Time t, ScalarKind scalar) {
  switch (scalar) {
    case ScalarKind::Float: return Time(float(t));
    case ScalarKind::Double: return Time(double(t));
    case ScalarKind::LongDouble:
    case ScalarKind::Float128: break;
  }
  return t;
}

}  // namespace

DiskFrame disk_frame(const State& state, const State& initial, std::int32_t species) {
  DiskFrame f;
  f.time = state.time;
  f.lx = state.lx, f.ly = state.ly;
  f.periodic = state.boundary == BoundaryKind::Periodic;
  f.species_names = state.species_names;
  double initial_speeds = 0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (species != kAllSpecies && state.species[i] != species) continue;
    initial_speeds += std::hypot(initial.vx[i], initial.vy[i]);
    double x = state.x[i], y = state.y[i];
    double dx = x - initial.x[i], dy = y - initial.y[i];
    if (f.periodic) {
      x = wrap(x, f.lx), y = wrap(y, f.ly);
      dx -= f.lx * std::round(dx / f.lx), dy -= f.ly * std::round(dy / f.ly);
    }
    f.x.push_back(x);
    f.y.push_back(y);
    f.r.push_back(state.radius[i]);
    f.speed.push_back(std::hypot(state.vx[i], state.vy[i]));
    f.displacement.push_back(std::hypot(dx, dy));
    f.species.push_back(state.species[i]);
  }
  f.initial_mean_speed = f.size() ? initial_speeds / double(f.size()) : 0;
  return f;
}

SpeedClass speed_class(double speed, double reference_speed) {
  if (speed < 0.5 * reference_speed) return SpeedClass::Slow;
  if (speed > 1.5 * reference_speed) return SpeedClass::Fast;
  return SpeedClass::Medium;
}

Result<std::vector<bool>> marked_disks(const DiskFrame& f, const std::vector<std::string>& names) {
  std::vector<std::int32_t> chosen;
  for (const std::string& name : names) {
    const auto it = std::find(f.species_names.begin(), f.species_names.end(), name);
    if (it == f.species_names.end()) {
      std::string known;
      for (const std::string& s : f.species_names) known += (known.empty() ? "" : ", ") + s;
      return Error{"the log has no species '" + name + "'; its species are: " + known};
    }
    chosen.push_back(std::int32_t(it - f.species_names.begin()));
  }
  if (names.empty()) {
    const std::vector<std::size_t> n = species_counts(f);
    const bool all_single = std::all_of(n.begin(), n.end(), [](std::size_t k) { return k == 1; });
    for (std::size_t s = 0; s < n.size() && !all_single; ++s)
      if (n[s] == 1) chosen.push_back(std::int32_t(s));
  }
  std::vector<bool> marked(f.size(), false);
  for (std::size_t i = 0; i < f.size(); ++i)
    marked[i] = std::find(chosen.begin(), chosen.end(), f.species[i]) != chosen.end();
  return marked;
}

double displacement_scale(const DiskFrame& f, const std::vector<bool>& marked) {
  std::vector<double> d;
  double radius_sum = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!marked[i]) d.push_back(f.displacement[i]);
    radius_sum += f.r[i];
  }
  if (!d.empty()) {
    const std::size_t k = std::size_t(std::ceil(0.95 * double(d.size()))) - 1;
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(k), d.end());
    if (d[k] > 0) return d[k];
  }
  return f.size() ? radius_sum / double(f.size()) : 1.0;
}

std::vector<Time> evenly_spaced_times(Time t0, Time t1, std::size_t count, ScalarKind scalar) {
  std::vector<Time> out;
  if (count == 0 || !(t1 >= t0)) return out;
  for (std::size_t k = 0; k < count; ++k) {
    const Time fraction = count == 1 ? 0.0L : static_cast<Time>(k) / static_cast<Time>(count - 1);
    if (fraction <= 0) out.push_back(t0);
    else if (fraction >= 1) out.push_back(t1);
    else out.push_back(std::clamp(round_to(t0 + (t1 - t0) * fraction, scalar), t0, t1));
  }
  return out;
}

std::vector<Time> times_every(Time t0, Time t1, Time every, ScalarKind scalar, std::size_t max_count) {
  std::vector<Time> out;
  if (!(every > 0) || !(t1 >= t0) || !std::isfinite(double(t1 - t0))) return out;
  if (!(std::floor((t1 - t0) / every) < static_cast<Time>(max_count))) return out;
  for (std::size_t k = 0;; ++k) {
    const Time t = round_to(t0 + every * static_cast<Time>(k), scalar);
    if (t > t1) break;
    out.push_back(std::max(t, t0));
  }
  return out;
}

}  // namespace ede
