// energy_fraction_curve: the kinetic energy over a logged run, in one walk over its events.
//
// Each disk's energy is kept in long double, computed by the very expression ede::kinetic_energy sums; a
// pair or wall event changes one or two of them and the running total by the difference. Wraps and time
// reversal leave every speed as it was. Whenever the running total comes within 1e-9 (relative) of the
// threshold, the full sum of the replayed state decides and the running total restarts from it, so the
// crossing is exactly the one summing the replayed states gives, at O(1) per event elsewhere.
// Rejected: the full O(N) sum after every event (exact but O(N) per event), and sampling the state on a
// time grid (cheap but the crossing time only to the grid's resolution).
#include <cmath>
#include <limits>

#include "analysis/crater.hpp"
#include "engine/engine.hpp"
#include "replay/log_impl.hpp"
#include "replay/replay.hpp"

namespace ede {

namespace {

// Margin within which the running total defers to the full sum (its own error is ~1e-16 per event).
constexpr double kConfirmMargin = 1e-9;

template <class T>
long double disk_energy(const Particles<T>& p, std::size_t i) {
  const long double vx = p.disk[i].vx, vy = p.disk[i].vy;
  return 0.5L * (long double)p.mass(i) * (vx * vx + vy * vy);
}

template <class T>
long double full_sum(const Particles<T>& p, std::vector<long double>& e) {
  long double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) sum += e[i] = disk_energy(p, i);
  return sum;
}

template <class T>
Result<EnergyFractionCurve> walk(std::shared_ptr<const LogReader> log, double fraction, std::size_t points) {
  if (log->header().gx != 0 || log->header().gy != 0)
    return Error{log->path() + ": the run is under gravity, where the kinetic energy changes between collisions "
                 "and its fraction does not mark the end of the impact; measure at a time with --at T"};
  auto made = Replay<T>::create(log);
  if (!made) return made.error();
  Replay<T>& replay = *made.value();
  if (Status s = replay.seek_event(0); !s) return s.error();
  const Particles<T>& p = replay.particles();

  EnergyFractionCurve c;
  c.fraction = fraction;
  c.initial_energy = kinetic_energy(p);
  if (!(c.initial_energy > 0))
    return Error{log->path() + ": the initial kinetic energy is 0, so no fraction of it can be measured"};
  const double e0 = c.initial_energy, threshold = fraction * e0;
  std::vector<long double> e(p.size());
  long double sum = full_sum(p, e);
  c.end_time = double(replay.final_time());
  std::vector<double> grid(points);
  for (std::size_t k = 0; k < points; ++k) grid[k] = k + 1 == points ? c.end_time : c.end_time * double(k) / double(points - 1);
  std::size_t next = 0;
  const auto flush = [&](double before) {
    for (; next < points && grid[next] < before; ++next) c.t.push_back(grid[next]), c.f.push_back(double(sum) / e0);
  };
  c.reached = c.initial_energy <= threshold;

  const auto on_event = [&](const ReplayedEvent<T>& ev) {
    flush(double(ev.time));  // grid points before this event see the state before it
    if (ev.kind != EventKind::Pair && ev.kind != EventKind::Wall) return true;
    for (const std::int32_t k : {ev.i, ev.kind == EventKind::Pair ? ev.j : -1}) {
      if (k < 0) continue;
      const long double now = disk_energy(p, std::size_t(k));
      sum += now - e[std::size_t(k)];
      e[std::size_t(k)] = now;
    }
    if (!c.reached && double(sum) <= threshold * (1 + kConfirmMargin)) {
      sum = full_sum(p, e);
      if (kinetic_energy(p) <= threshold) {
        c.reached = true;
        c.event = replay.events_applied();
        c.time = double(ev.time);
      }
    }
    return true;
  };
  if (Status s = replay.for_each_event(0, log->total_events(), on_event); !s) return s.error();
  flush(std::numeric_limits<double>::infinity());
  c.end_fraction = kinetic_energy(p) / e0;
  if (!c.reached) c.event = replay.events_applied(), c.time = c.end_time;
  return c;
}

}  // namespace

Result<EnergyFractionCurve> energy_fraction_curve(const Log& opened, double fraction, std::size_t points) {
  std::shared_ptr<const LogReader> log = reader_of(opened);
  if (!(fraction > 0 && fraction <= 1))
    return Error{"the energy fraction must be in (0, 1], got " + std::to_string(fraction)};
  if (points < 2) return Error{"the energy curve needs at least 2 points"};
  switch (log->header().scalar) {
    case ScalarKind::Float: return walk<float>(std::move(log), fraction, points);
    case ScalarKind::LongDouble: return walk<long double>(std::move(log), fraction, points);
    case ScalarKind::Double: break;
    case ScalarKind::Float128: break;  // never in a log (LogHeaderInfo::scalar)
  }
  return walk<double>(std::move(log), fraction, points);
}

}  // namespace ede
