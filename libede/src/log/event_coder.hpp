// From an event as the engine reports it to what the chunk encoder codes (log/logged_event.hpp): on the event
// loop, where the records the engine hands over with the event are still in cache.
//
// Format version 2: the time's prediction, and the velocities' (and spins') where the engine does not vouch
// for them (EventOutcome::v2_*_exact), by the format's predictors (log/event_predictions.hpp) run on the
// records before the event. An ordinary pair collision is vouched for entirely and costs nothing here.
// `check` (the scene's log.check_exactness; the tests) also runs the predictors where the engine vouched,
// and reports the first event where they disagree: a log written without the check would decode wrongly
// there, so the writer fails the run instead.
// An event without the flag from a run whose header has the TC model (a converted version 1 log) gets it
// when only the elastic rule predicts its velocities exactly; in a run the engine's own flag always does.
// Format version 1: the velocities after and before and the masses its coder reads.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>

#include "core/event.hpp"
#include "core/particles.hpp"
#include "log/event_predictions.hpp"
#include "log/logged_event.hpp"
#include "log/rules/state_update.hpp"

namespace ede {

template <class T>
class EventCoder {
 public:
  // `trust`: the header's physics is the engine's (LogRunInfo::engine_constants), so its vouches hold; else
  // every event is predicted here.
  EventCoder(const EventPhysics<T>& physics, std::uint32_t format_version, bool check, bool trust = true)
      : physics_(physics), format_version_(format_version), check_(check), trust_(trust) {}

  // The first disagreement `check` found (empty: none).
  const std::string& mismatch() const { return mismatch_; }

  // Codes e into `out`: an event the engine vouched for entirely (an ordinary pair collision) without
  // building a CodedEvent.
  void add(const EventOutcome<T>& e, const Particles<T>& p, ChunkEvents<T>& out) {
    if (trust_ && !check_ && format_version_ >= 2 && e.v2_time_exact && e.v2_velocities_exact)
      return out.push_plain({e.time, e.i, e.j, e.kind, e.tc_elastic, false, false});
    out.push_back(code(e, p));
  }

  CodedEvent<T> code(const EventOutcome<T>& e, const Particles<T>& p) {
    const bool time_exact = trust_ && e.v2_time_exact, velocities_exact = trust_ && e.v2_velocities_exact;
    CodedEvent<T> c;
    c.time = e.time, c.kind = e.kind, c.tc_elastic = e.tc_elastic, c.i = e.i, c.j = e.j;
    if (format_version_ < 2) return code_v1(e, p, c);
    c.predicted_time = time_exact ? e.time : predicted_event_time(physics_, e.kind, e.before_i, e.before_j, e.j);
    if (check_ && time_exact) check_time(e);
    if (e.kind == EventKind::Thermostat) {  // version 3: the drawn velocity, stored as it is
      c.v[0] = e.vix, c.v[1] = e.viy;
      c.velocities_predicted = false;
      return c;
    }
    if (e.kind == EventKind::Shear) {  // version 3: the new x (the outcome's vjx) and vx, stored as they are
      c.v[0] = e.vjx, c.v[1] = e.vix;
      c.velocities_predicted = false;
      return c;
    }
    if (e.kind == EventKind::Step) return code_step(e, c);
    if (!collision(e.kind)) return c;
    if (velocities_exact) {
      if (check_) check_velocities(e, p, c);
      return c;
    }
    if (!c.tc_elastic && physics_.tc_model && !rule_exact(e, p, false) && rule_exact(e, p, true)) c.tc_elastic = true;
    predict(e, p, c.tc_elastic, c.pv, c.pw);
    set_after(e, c);
    c.velocities_predicted = false;
    return c;
  }

 private:
  static bool collision(EventKind k) { return k == EventKind::Pair || k == EventKind::Wall || k == EventKind::Segment; }
  static int velocities(EventKind k) { return k == EventKind::Pair ? 4 : 2; }
  static int spins(EventKind k) { return k == EventKind::Pair ? 2 : k == EventKind::Wall ? 1 : 0; }
  static bool same(const T* a, const T* b, int n) {
    for (int k = 0; k < n; ++k)
      if (ordered_bits(a[k]) != ordered_bits(b[k])) return false;
    return true;
  }
  static unsigned __int128 ordered_bits(T v) {
    unsigned __int128 b = 0;
    std::memcpy(&b, &v, sizeof(T) == 16 ? 10 : sizeof(T));
    return b;
  }

  CodedEvent<T> code_v1(const EventOutcome<T>& e, const Particles<T>& p, CodedEvent<T>& c) {
    c.v[0] = e.vix, c.v[1] = e.viy, c.v[2] = e.vjx, c.v[3] = e.vjy;
    c.pv[0] = e.vix0, c.pv[1] = e.viy0, c.pv[2] = e.vjx0, c.pv[3] = e.vjy0;
    if (e.kind == EventKind::Pair) c.mi = p.mass(std::size_t(e.i)), c.mj = p.mass(std::size_t(e.j));
    return c;
  }

  // A step event (format version 3): no predictor yet, its velocities against those before the event.
  static CodedEvent<T> code_step(const EventOutcome<T>& e, CodedEvent<T>& c) {
    c.pv[0] = e.vix0, c.pv[1] = e.viy0, c.pv[2] = e.vjx0, c.pv[3] = e.vjy0;
    set_after(e, c);
    c.velocities_predicted = false;
    return c;
  }

  static void set_after(const EventOutcome<T>& e, CodedEvent<T>& c) {
    c.v[0] = e.vix, c.v[1] = e.viy, c.v[2] = e.vjx, c.v[3] = e.vjy;
    c.w[0] = e.wi, c.w[1] = e.wj;
  }

  DiskTraits<T> traits(const Particles<T>& p, std::int32_t i, T omega_before) const {
    DiskTraits<T> d;
    d.mass = p.mass(std::size_t(i));
    d.species = p.species_of(std::size_t(i));
    if (physics_.rough) d.omega = omega_before, d.inertia = p.inertia[std::size_t(i)];
    return d;
  }

  // The velocities (and spins) format version 2 predicts after a collision, from the event's records.
  void predict(const EventOutcome<T>& e, const Particles<T>& p, bool tc, T v[4], T w[2]) const {
    if (e.kind == EventKind::Pair) {
      RecordBefore<T> a = e.before_i, b = e.before_j;
      rules::bring_to(a, e.time, physics_.gx, physics_.gy);
      rules::bring_to(b, e.time, physics_.gx, physics_.gy);
      predict_pair_velocities(physics_, a, b, traits(p, e.i, e.wi0), traits(p, e.j, e.wj0), physics_.rough, tc, v, w);
    } else if (e.kind == EventKind::Wall) {
      predict_wall_velocity(physics_, e.before_i, e.time, e.j, traits(p, e.i, e.wi0), physics_.rough, tc, v, w);
    } else {
      predict_segment_velocity(physics_, e.before_i, e.time, e.j, tc, v);
    }
  }

  bool rule_exact(const EventOutcome<T>& e, const Particles<T>& p, bool tc) const {
    T v[4] = {}, w[2] = {};
    predict(e, p, tc, v, w);
    const T after[4] = {e.vix, e.viy, e.vjx, e.vjy};
    return same(after, v, velocities(e.kind));
  }

  void check_velocities(const EventOutcome<T>& e, const Particles<T>& p, CodedEvent<T> c) {
    predict(e, p, c.tc_elastic, c.pv, c.pw);
    set_after(e, c);
    if (!same(c.v, c.pv, velocities(e.kind)) || (physics_.rough && !same(c.w, c.pw, spins(e.kind))))
      report(e, "its velocities");
  }

  void check_time(const EventOutcome<T>& e) {
    const T t = predicted_event_time(physics_, e.kind, e.before_i, e.before_j, e.j);
    if (ordered_bits(t) != ordered_bits(e.time)) report(e, "its time");
  }

  void report(const EventOutcome<T>& e, const char* what) {
    if (!mismatch_.empty()) return;
    mismatch_ = "the engine vouched for " + std::string(what) + " at the " + std::string(to_string(e.kind)) +
                " event of disk " + std::to_string(e.i) + " at t = " + std::to_string(double(e.time)) +
                ", but format version 2's predictors compute otherwise: the log would decode wrongly there "
                "(a bug in ede; please report it with the scene)";
  }

  const EventPhysics<T>& physics_;
  std::uint32_t format_version_;
  bool check_, trust_;
  std::string mismatch_;
};

}  // namespace ede
