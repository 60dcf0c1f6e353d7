// measure_crater: a crater from a log: the initial state against the state at the chosen time.
//
// The time is either asked for (exact in the log's scalar type) or the first event after which the given
// fraction of the initial kinetic energy remains (energy_fraction_curve), else the log's end. The state at
// the crossing is taken after exactly that many events (Replay::seek_event), not "at its time", so events
// at the same instant that come later in the log are not included. Positions are drifted to the state's
// time by the shared drift function and only then converted to double for the geometry.
// Rejected: taking the state from the engine at its stop (ede-sim --final-state), which ties the metric
// to the scene's stop condition; from a log any time, and any fraction, can be measured.
// Under gravity there is no energy fraction (see CraterMeasurement::has_energy): the time is asked for.
#include <limits>

#include "analysis/crater.hpp"
#include "engine/engine.hpp"
#include "replay/log_impl.hpp"
#include "replay/replay.hpp"
#include "ede/number_text.hpp"
#include "core/scalar_dispatch.hpp"

namespace ede {

namespace {

template <class T>
DiskPositions positions(const Particles<T>& p, T t) {
  DiskPositions s;
  s.x.resize(p.size()), s.y.resize(p.size()), s.r.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    s.x[i] = double(p.x_at(i, t));
    s.y[i] = double(p.y_at(i, t));
    s.r[i] = double(p.disk[i].r);
  }
  return s;
}

}  // namespace

const char* to_string(CraterTimeSource s) {
  switch (s) {
    case CraterTimeSource::EnergyFraction: return "energy_fraction";
    case CraterTimeSource::LogEnd: return "log_end";
    case CraterTimeSource::Requested: return "requested";
  }
  return "?";
}

template <class T>
static Result<CraterMeasurement> measure_crater_in(const Log& opened, const CraterRequest& req) {
  const std::shared_ptr<const LogReader>& log = reader_of(opened);
  CraterMeasurement m;
  auto bed = select_bed(log->header(), req.bed_species);
  if (!bed) return Error{log->path() + ": " + bed.error().message};
  m.bed = std::move(bed).value();
  m.has_energy = log->header().gx == 0 && log->header().gy == 0;
  if (!m.has_energy && !req.at && !req.at_end)
    return Error{log->path() + ": the run is under gravity, where the kinetic energy changes between collisions "
                 "and its fraction does not mark the end of the impact; measure at a time with --at T (or --at end)"};
  if (m.has_energy) {
    auto energy = energy_fraction_curve(opened, req.energy_fraction, req.curve_points);
    if (!energy) return energy.error();
    m.energy = std::move(energy).value();
  }
  m.box = {log->header().lx, log->header().ly, log->header().boundary == BoundaryKind::Periodic};

  auto made = Replay<T>::create(log);
  if (!made) return made.error();
  Replay<T>& replay = *made.value();
  if (Status s = req.before ? replay.seek_time(T(*req.before)) : replay.seek_event(0); !s) return s.error();
  m.before_time = double(replay.time());
  const DiskPositions before = positions(replay.particles(), replay.time());

  const std::string f = brief(req.energy_fraction);
  if (req.at) {
    if (Status s = replay.seek_time(T(*req.at)); !s) return s.error();
    m.source = CraterTimeSource::Requested;
    m.when = "the time asked for";
  } else if (m.energy.reached && !req.at_end) {
    if (Status s = replay.seek_event(m.energy.event); !s) return s.error();
    m.source = CraterTimeSource::EnergyFraction;
    m.when = "the first event after which at most " + f +
             " of the initial kinetic energy remains";
  } else {
    // The end of a log cut short is its last event: seeking by index is exact in every scalar type.
    const Status s = log->complete() ? replay.seek_time(replay.final_time()) : replay.seek_event(log->total_events());
    if (!s) return s.error();
    m.source = CraterTimeSource::LogEnd;
    m.when = req.at_end ? "the log's end, as asked"
                        : "the log's end: the kinetic energy never fell to " + f + " of its initial value (" +
                              brief(m.energy.end_fraction) + " of it is left at the end)";
  }
  m.time = double(replay.time());
  if (m.time < m.before_time)
    return Error{log->path() + ": the crater is measured at t = " + brief(m.time) +
                 ", before the reference state (--before " + brief(m.before_time) + "): measure later"};
  m.events = replay.events_applied();
  m.energy_fraction = m.has_energy ? kinetic_energy(replay.particles()) / m.energy.initial_energy
                                   : std::numeric_limits<double>::quiet_NaN();
  const DiskPositions after = positions(replay.particles(), replay.time());
  auto report = analyze_crater(before, after, m.bed.is_bed, m.box, req.settings);
  if (!report) return Error{log->path() + ": " + report.error().message};
  m.report = std::move(report).value();
  return m;
}

Result<CraterMeasurement> measure_crater(const Log& log, const CraterRequest& request) {
  return with_scalar(log.info().scalar, [&]<class T>() { return measure_crater_in<T>(log, request); });
}

}  // namespace ede
