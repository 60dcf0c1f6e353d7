// Log series and snapshots (ede/analysis.hpp): log_overview, log_series, for_each_snapshot. Each entry point dispatches once on the log's scalar type;
// the walk itself runs in T, and the per-disk energies are computed exactly as kinetic_energy() computes
// them (long double products of the T velocities), so a running sum and a fresh sum over the replayed
// state agree to the rounding of the sums alone.
#include "ede/analysis.hpp"

#include <cmath>
#include <type_traits>

#include "analysis/step_potential.hpp"
#include "ede/number_text.hpp"
#include "log/log_stats.hpp"
#include "replay/log_impl.hpp"
#include "replay/replay.hpp"

namespace ede {

namespace {

template <class F>
decltype(auto) with_log_scalar(const LogReader& log, F&& f) {
  switch (log.header().scalar) {
    case ScalarKind::Float: return f.template operator()<float>();
    case ScalarKind::LongDouble: return f.template operator()<long double>();
    case ScalarKind::Double: break;
    case ScalarKind::Float128: break;  // never in a log (LogHeaderInfo::scalar)
  }
  return f.template operator()<double>();
}

// The largest double not above t.
template <class T>
double round_down(T t) {
  double d = double(t);
  if constexpr (std::is_same_v<T, long double>)
    if ((long double)d > t) d = std::nextafter(d, -std::numeric_limits<double>::infinity());
  return d;
}

template <class T>
Result<std::unique_ptr<Replay<T>>> replay_of(const std::shared_ptr<const LogReader>& log) {
  return Replay<T>::create(log);
}

std::string text(double v) { return exact_number(v); }

template <class T>
Status check_times(const LogReader& log, const std::vector<double>& times, T end) {
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k]) || times[k] < 0)
      return Error{log.path() + ": the time " + text(times[k]) + " is not a finite time >= 0"};
    if (k && times[k] < times[k - 1]) return Error{log.path() + ": the times must be in increasing order"};
  }
  if (!times.empty() && T(times.back()) > end)
    return Error{log.path() + ": the time " + text(times.back()) + " is after the end of the log (t = " +
                 text(double(end)) + ")"};
  return Ok{};
}

template <class T>
long double energy_of(T mass, T vx, T vy) {
  const long double x = vx, y = vy;
  return 0.5L * (long double)mass * (x * x + y * y);
}

// The walk of log_series: each disk's energy as of just before the next event, and their running sums.
template <class T>
class EnergyWalk {
 public:
  EnergyWalk(const Particles<T>& p, std::size_t species_count) : p_(p), species_sum_(species_count, 0) {
    resync();
  }

  // Replaces the disks of an event (post-event velocities) in the sums; an action resynchronises.
  void apply(const ReplayedEvent<T>& e) {
    switch (e.kind) {
      case EventKind::Pair:
        set(std::size_t(e.i), e.vix, e.viy, e.wi);
        set(std::size_t(e.j), e.vjx, e.vjy, e.wj);
        ++pairs_;
        break;
      case EventKind::Wall:
        set(std::size_t(e.i), e.vix, e.viy, e.wi);
        ++walls_;
        break;
      case EventKind::Segment:
      case EventKind::Thermostat: set(std::size_t(e.i), e.vix, e.viy, T(0)); break;
      case EventKind::Step:  // the potential energy takes what the kinetic energy gives
        potential_ -= set(std::size_t(e.i), e.vix, e.viy, T(0)) + set(std::size_t(e.j), e.vjx, e.vjy, T(0));
        break;
      case EventKind::Action: resync(); break;
      default: break;  // wraps move a disk, not its velocity
    }
  }

  // The energies at time t, the state being that after every event before t. Under gravity the velocities
  // change between events, so the sums are taken afresh from the replayed state at t (O(N) per point).
  void record(LogSeries& s, T t) const {
    if (p_.gx != T(0) || p_.gy != T(0)) {
      long double total = 0;
      std::vector<long double> per_species(species_sum_.size(), 0.0L);
      for (std::size_t i = 0; i < p_.size(); ++i) {
        const long double e = energy_of(p_.mass(i), p_.vx_at(i, t), p_.vy_at(i, t));
        total += e;
        per_species[std::size_t(p_.species_of(i))] += e;
      }
      s.kinetic_energy.push_back(double(total));
      for (std::size_t k = 0; k < per_species.size(); ++k) s.species_energy[k].push_back(double(per_species[k]));
    } else {
      s.kinetic_energy.push_back(double(total_));
      for (std::size_t k = 0; k < species_sum_.size(); ++k) s.species_energy[k].push_back(double(species_sum_[k]));
    }
    s.pair_collisions.push_back(pairs_);
    s.wall_collisions.push_back(walls_);
    if (stepped_) s.potential_energy.push_back(double(potential_));
  }

  // A stepped potential's energy at the walk's start (step_potential.hpp); the step events carry it on.
  void set_potential(long double u) { potential_ = u, stepped_ = true; }

 private:
  // Rough logs: a disk's energy includes I w^2 / 2 (smooth logs have no spins: + 0, exactly).
  long double spin_energy(std::size_t i, T w) const {
    if (p_.omega.empty()) return 0.0L;
    const long double x = w;
    return 0.5L * (long double)p_.inertia[i] * (x * x);
  }
  // Returns the change of the disk's energy.
  long double set(std::size_t i, T vx, T vy, T w) {
    const long double e = energy_of(p_.mass(i), vx, vy) + spin_energy(i, w);
    const long double delta = e - energy_[i];
    total_ += delta;
    species_sum_[std::size_t(p_.species_of(i))] += delta;
    energy_[i] = e;
    return delta;
  }

  // Every energy and sum afresh from the replayed state (which, in the callback, already includes the event).
  void resync() {
    energy_.assign(p_.size(), 0);
    total_ = 0;
    std::fill(species_sum_.begin(), species_sum_.end(), 0.0L);
    for (std::size_t i = 0; i < p_.size(); ++i) {
      energy_[i] = energy_of(p_.mass(i), p_.disk[i].vx, p_.disk[i].vy) +
                   spin_energy(i, p_.omega.empty() ? T(0) : p_.omega[i]);
      total_ += energy_[i];
      species_sum_[std::size_t(p_.species_of(i))] += energy_[i];
    }
  }

  const Particles<T>& p_;
  std::vector<long double> energy_;
  long double total_ = 0;
  std::vector<long double> species_sum_;
  std::uint64_t pairs_ = 0, walls_ = 0;
  long double potential_ = 0;
  bool stepped_ = false;
};

// The potential energy of the replayed state's positions under the steps of the log's scene (0 without).
template <class T>
Result<long double> start_potential(const LogReader& log, const Particles<T>& p) {
  const LogHeaderInfo& h = log.header();
  if (h.format_version < 3) return 0.0L;
  auto scene = parse_scene_text(h.scene_text, h.scene_name);
  if (!scene) return Error{log.path() + ": the scene in the log's header no longer loads: " + scene.error().message};
  std::vector<double> x(p.size()), y(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) x[i] = double(p.disk[i].x), y[i] = double(p.disk[i].y);
  const std::vector<std::int32_t> species = p.species_column();
  return (long double)step_potential_energy(
      scene.value().physics.steps,
      {x, y, species, h.species_names, double(h.lx), double(h.ly), h.boundary == BoundaryKind::Periodic});
}

template <class T>
Result<LogSeries> series_in(const std::shared_ptr<const LogReader>& log, const std::vector<double>& times) {
  auto made = replay_of<T>(log);
  if (!made) return made.error();
  Replay<T>& replay = *made.value();
  if (Status s = check_times(*log, times, replay.final_time()); !s) return s.error();
  if (Status s = replay.seek_event(0); !s) return s.error();
  const LogHeaderInfo& h = log->header();
  LogSeries out;
  out.species_names = h.species_names;
  out.species_count.assign(h.species_names.size(), 0);
  for (const std::uint32_t s : h.species) ++out.species_count[s];
  out.species_energy.resize(h.species_names.size());

  EnergyWalk<T> walk(replay.particles(), h.species_names.size());
  if (h.format_version >= 3) {
    auto u = start_potential(*log, replay.particles());
    if (!u) return u.error();
    walk.set_potential(u.value());
  }
  std::size_t k = 0;
  const auto record_before = [&](const T* event_time) {
    for (; k < times.size() && (!event_time || T(times[k]) < *event_time); ++k) {
      out.time.push_back(times[k]);
      walk.record(out, T(times[k]));
    }
  };
  Status s = replay.for_each_event(0, log->total_events(), [&](const ReplayedEvent<T>& e) {
    record_before(&e.time);
    walk.apply(e);
    return k < times.size();
  });
  if (!s) return s.error();
  record_before(nullptr);
  return out;
}

template <class T>
Status snapshots_in(const std::shared_ptr<const LogReader>& log, const std::vector<double>& times,
                    const std::function<void(const GasSnapshot&)>& f) {
  auto made = replay_of<T>(log);
  if (!made) return made.error();
  Replay<T>& replay = *made.value();
  if (Status s = check_times(*log, times, replay.final_time()); !s) return s;
  const Particles<T>& p = replay.particles();
  GasSnapshot snap;
  snap.species_names = log->header().species_names;
  const std::vector<T> masses = p.mass_column();
  snap.mass.assign(masses.begin(), masses.end());
  snap.species = p.species_column();
  snap.vx.resize(p.size());
  snap.vy.resize(p.size());
  for (const double t : times) {
    if (Status s = replay.seek_time(T(t)); !s) return s;
    snap.time = t;
    for (std::size_t i = 0; i < p.size(); ++i) {
      snap.vx[i] = double(p.vx_at(i, T(t)));
      snap.vy[i] = double(p.vy_at(i, T(t)));
    }
    f(snap);
  }
  return Ok{};
}

}  // namespace

Result<LogOverview> log_overview(const Log& opened) {
  const std::shared_ptr<const LogReader> log = reader_of(opened);
  auto counts = count_logged_kinds(*log);
  if (!counts) return counts.error();
  return with_log_scalar(*log, [&]<class T>() -> Result<LogOverview> {
    auto made = replay_of<T>(log);
    if (!made) return made.error();
    LogOverview o;
    o.disks = log->header().disks;
    o.end_time = round_down(made.value()->final_time());
    o.pair_events = counts.value().of(EventKind::Pair);
    o.wall_events = counts.value().of(EventKind::Wall);
    return o;
  });
}

std::vector<double> time_grid(double t0, double t1, double dt, std::size_t max_points) {
  std::vector<double> out;
  if (!(dt > 0) || !(t1 >= t0) || !std::isfinite(t0) || !std::isfinite(t1)) return out;
  const double steps = std::floor((t1 - t0) / dt);
  if (!(steps < double(max_points))) return out;
  for (std::size_t k = 0; k <= std::size_t(steps) + 1; ++k) {
    const double t = t0 + double(k) * dt;
    if (t > t1) break;
    out.push_back(t);
  }
  return out;
}

std::vector<double> time_grid_to(double t0, double t1, double dt, std::size_t max_points) {
  std::vector<double> out = time_grid(t0, t1, dt, max_points);
  if (!out.empty() && out.back() < t1) out.push_back(t1);
  return out;
}

std::uint64_t LogSeries::disks() const {
  std::uint64_t n = 0;
  for (const std::uint64_t c : species_count) n += c;
  return n;
}

double LogSeries::collisions_per_particle(std::size_t k) const {
  return disks() ? 2.0 * double(pair_collisions[k]) / double(disks()) : 0.0;
}

double LogSeries::mean_kinetic_energy(std::size_t k) const {
  return disks() ? kinetic_energy[k] / double(disks()) : 0.0;
}

double LogSeries::species_mean_energy(std::size_t s, std::size_t k) const {
  return species_count[s] ? species_energy[s][k] / double(species_count[s]) : 0.0;
}

Result<LogSeries> log_series(const Log& opened, const std::vector<double>& times) {
  const std::shared_ptr<const LogReader> log = reader_of(opened);
  return with_log_scalar(*log, [&]<class T>() { return series_in<T>(log, times); });
}

Status for_each_snapshot(const Log& opened, const std::vector<double>& times,
                         const std::function<void(const GasSnapshot&)>& f) {
  const std::shared_ptr<const LogReader> log = reader_of(opened);
  return with_log_scalar(*log, [&]<class T>() { return snapshots_in<T>(log, times, f); });
}

}  // namespace ede
