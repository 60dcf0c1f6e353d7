// Engine<T, Boundary, Dissipation, Field, Contact, Walls, Spin, Potential, Heat>: the event-driven hard-disk
// engine, one instantiation per set of effects (eight axes, effects.hpp; the instantiations that exist:
// engine_factory.hpp).
//
// The loop: take the earliest of (next disk event, next sample, next action, next thermostat redraw, next
// realignment of a Lees-Edwards box's sliding rows, stop time); for a disk event,
// discard it if its partner changed since it was predicted (collision counters), else hand it to the room of
// its kind, which brings the disks involved to the event time (lazy state: nobody else moves), resolves it,
// tells the sinks and re-predicts those disks only. Each disk holds one prediction (its earliest collision,
// wall hit, or cell crossing), so the queue has N keys and a prediction looks at the 3 x 3 cells around the
// disk: the cost per event does not depend on N. Disks at rest predict nothing and cost nothing until
// something approaches them. The few disks much larger than the rest stay out of the cell lists
// (big_disks.hpp), so they do not set the cell size for everyone.
// This class is the loop and the set-up; the rest lives in rooms over its state (engine_state.hpp): one per
// event kind (room_pair, room_wall, room_segment, room_crossing, room_wrap, room_action, room_step,
// room_thermostat, room_shear), the predictions
// (predict_disk), the stops (stops), the invariants (invariants) and the prefetch (prefetch). Adding an
// event kind is its value in EDE_EVENT_KINDS (ede/events.hpp), its room, and its line in resolve() below.
// Rejected: storing every predicted pair event (the queue grows with density and fills with stale events)
// and updating every disk to the current time at each event (O(N) per event).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "core/energy.hpp"
#include "core/initial_state.hpp"
#include "engine/engine.hpp"
#include "engine/engine_state.hpp"
#include "engine/invariants.hpp"
#include "engine/neighbours.hpp"
#include "engine/predict_disk.hpp"
#include "engine/prefetch.hpp"
#include "engine/room_action.hpp"
#include "engine/room_crossing.hpp"
#include "engine/room_pair.hpp"
#include "engine/room_segment.hpp"
#include "engine/room_shear.hpp"
#include "engine/room_thermostat.hpp"
#include "engine/room_step.hpp"
#include "engine/room_wall.hpp"
#include "engine/room_wrap.hpp"
#include "engine/stops.hpp"

namespace ede {

template <class T, class Boundary, class Dissipation, class Field = NoField, class Contact = StableContact,
          class Walls = NoSegments, class Spin = Smooth, class Potential = HardCore, class Heat = NoThermostat>
class Engine final : public EngineApi<T> {
  using Fx = EffectSet<Boundary, Dissipation, Field, Contact, Walls, Spin, Potential, Heat>;
  using State = EngineState<T, Fx>;

 public:
  Engine(const InitialState& init, const EngineOptions& options, GridShape shape, const ResumePoint<T>* resume) {
    State& s = s_;
    s.opt = options;
    load(init);
    s.lx = T(init.lx);
    s.ly = T(init.ly);
    s.half_lx = s.lx / 2;
    s.half_ly = s.ly / 2;
    if constexpr (Fx::kDissipative)
      s.dissipation.setup(init.species_names, options.physics, uses_tc_model(options.physics));
    if constexpr (Fx::kRough) s.spin.setup(init.species_names, options.physics);
    if constexpr (Fx::kSteps) s.steps.setup(init.species_names, options.physics, init.size());
    if constexpr (Fx::kThermostat)
      s.thermostat.setup(init.species_names, init.species, options.physics, options.species_thermostats, options.seed);
    if constexpr (Fx::kSheared) s.shear.setup(options.shear_rate.value_or(0), s.lx, s.ly, shape.nx);
    if constexpr (Fx::kGravity) {
      s.field.gx = s.p.gx = T(options.physics.gravity[0]);
      s.field.gy = s.p.gy = T(options.physics.gravity[1]);
    }
    s.b_noise2 = b_noise2_for(std::max(s.lx, s.ly));
    // The all-pairs baseline tests every disk, most of them far and receding: the branching test, which
    // skips their roots, keeps it the honest baseline it was (the selects made it 1.5x slower).
    s.select_pairs = init.size() <= options.branch_free_scan_up_to && options.algorithm != Algorithm::AllPairs;
    s.prefetch_ahead = init.size() >= options.prefetch_upcoming_from;
    s.grid.reset(shape.nx, shape.ny, s.lx, s.ly, s.p.disk);
    find_big_disks(s, init, shape.split);
    s.pair_times_vouchable = std::is_same_v<Contact, StableContact> && s.big.empty() && !Fx::kSteps && !Fx::kSheared &&
                             (!Fx::kPeriodic || (s.grid.nx() >= 5 && s.grid.ny() >= 5));
    if constexpr (Fx::kSegments) setup_segments(s, options.physics, init, shape);
    s.queue.reset(static_cast<std::uint32_t>(s.p.size()));
    s.pred.assign(s.p.size(), Prediction<T>::none());
    s.stall.limit = options.stall_limit ? options.stall_limit
                                        : std::max<std::uint64_t>(1000000, 100 * std::uint64_t(s.p.size()));
    if (options.stop.collisions_per_particle) s.schedule.pairs_to_stop = pairs_for(s, *options.stop.collisions_per_particle);
    if (resume) restore(*resume);
    s.schedule.next_pair_target = pair_target(s);
  }

  void add_sink(Sink<T>* sink) override { s_.sinks.push_back(sink); }
  T time() const override { return s_.now; }
  const Particles<T>& particles() const override { return s_.p; }
  const EventCounts& counts() const override { return s_.counts; }
  double initial_kinetic_energy() const override { return s_.ke0; }
  double potential_energy() const override {
    if constexpr (Fx::kSteps) return s_.steps.potential;
    return 0;
  }
  std::string stall_message() const override { return s_.stall.message; }
  double largest_overlap() const override { return ede::largest_overlap(s_); }
  std::string check_invariants(double tolerance) const override { return ede::check_invariants(s_, tolerance); }

  std::string effects() const override {
    const PhysicsSpec& ph = s_.opt.physics;
    std::ostringstream o;
    o << Boundary::kName << ", ";
    if constexpr (Fx::kSheared) o << "shear rate " << s_.opt.shear_rate.value_or(0) << ", ";
    if (Fx::kDissipative && !ph.elastic()) {
      o << "inelastic (xi=" << ph.restitution;
      if (!ph.pairs.empty()) o << ", " << ph.pairs.size() << " species pairs apart";
      o << ", xi_w=" << ph.wall_restitution;
      static constexpr const char* kWallName[4] = {"left", "right", "bottom", "top"};
      for (int w = 0; w < 4; ++w)
        if (ph.walls[std::size_t(w)]) o << ", " << kWallName[w] << " " << *ph.walls[std::size_t(w)];
      o << ")";
      if (s_.tc_model()) o << ", TC (tc=" << ph.tc << ")";
    } else {
      o << "elastic";
    }
    if constexpr (Fx::kGravity) o << ", gravity (" << ph.gravity[0] << ", " << ph.gravity[1] << ")";
    if constexpr (Fx::kSegments) o << ", " << s_.walls.seg.size() << (s_.walls.seg.size() == 1 ? " segment" : " segments");
    if constexpr (Fx::kSteps) {
      std::size_t n = 0;
      for (const PairSteps& st : ph.steps) n += st.radius.size();
      o << ", stepped potential (" << n << (n == 1 ? " step" : " steps") << ")";
    }
    if constexpr (Fx::kRough) {
      o << ", rough (beta=" << ph.roughness << ", beta_w=" << ph.wall_roughness;
      if (!ph.pairs.empty()) o << ", per species pair";
      o << ")";
    }
    // (The sheared engine carries the clock for every scene: only a thermostat that redraws is named.)
    if constexpr (Fx::kThermostat) if (!s_.thermostat.groups.empty()) {
      std::size_t disks = 0;
      for (const auto& g : s_.thermostat.groups) disks += g.disks.size();
      o << ", Andersen thermostat (" << disks << " disks, " << s_.thermostat.total_rate << " redraws per unit time)";
    }
    o << Contact::kLabel << ", grid " << s_.grid.nx() << "x" << s_.grid.ny();
    if (!s_.big.empty()) o << " + " << s_.big.size() << (s_.big.size() == 1 ? " big disk" : " big disks");
    return o.str();
  }

  std::size_t memory_bytes() const override {
    const Particles<T>& p = s_.p;
    std::size_t bytes = p.disk.capacity() * sizeof(Disk<T>) + p.masses.capacity() * sizeof(T) +
                        p.species_ids.capacity() * sizeof(std::int32_t) + p.last_collision.capacity() * sizeof(T) +
                        (p.omega.capacity() + p.inertia.capacity()) * sizeof(T) +
                        s_.pred.capacity() * sizeof(Prediction<T>) + s_.grid.memory_bytes() + s_.queue.memory_bytes() +
                        s_.big.capacity() * sizeof(BigDisk);
    if constexpr (Fx::kDissipative) bytes += s_.dissipation.memory_bytes();
    if constexpr (Fx::kSegments) bytes += s_.walls.memory_bytes();
    if constexpr (Fx::kRough) bytes += s_.spin.memory_bytes();
    if constexpr (Fx::kSteps) bytes += s_.steps.memory_bytes();
    if constexpr (Fx::kThermostat) bytes += s_.thermostat.memory_bytes();
    return bytes;
  }

  RunStatus run(std::uint64_t max_events) override { return run_until(kNever<T>, max_events); }

  // The loop. Everything at or before `until` happens; a stop time before it ends the run as usual.
  RunStatus run_until(T until, std::uint64_t max_events) override {
    State& s = s_;
    if (status_ != RunStatus::Running) return status_;
    if (!started_) start();
    const T t_limit = std::min(s.stop_time, until);
    for (std::uint64_t done = 0; done < max_events;) {
      const QueueKey<T> next = s.queue.top();
      if (s.prefetch_ahead) prefetch_.run(s);
      const T t_sample = next_sample_time(s);
      const T t_action = next_action_time(s);
      const T t_stop = s.stop_time;
      const T t_heat = thermostat_time(s);  // a constant never without the thermostat: its tests fold away
      const T t_align = realign_time(s);     // likewise without the sliding edges of a Lees-Edwards box
      if (next.time <= t_sample && next.time <= t_action && next.time <= t_limit && next.time != kNever<T> &&
          (!Fx::kThermostat || next.time <= t_heat) && (!Fx::kSheared || next.time <= t_align)) {
        if (!process_disk_event(next)) continue;  // stale prediction: not an event
        ++done;
        if (s.counts.of(EventKind::Pair) >= s.schedule.next_pair_target) done += on_pair_target(s);
        if (const RunStatus st = check_stops(s); st != RunStatus::Running) return finish(st);
        if (s.opt.rebuild_interval && s.events_done() % s.opt.rebuild_interval == 0) rebuild_predictions(s);
      } else if (t_action != kNever<T> && t_action <= t_sample && t_action <= t_limit &&
                 (!Fx::kThermostat || t_action <= t_heat) && (!Fx::kSheared || t_action <= t_align)) {
        // Everything that happens at time <= t, actions included, happens before an observer looks at t.
        reverse_velocities(s, t_action);
        ++done;
        if (const RunStatus st = check_stops(s); st != RunStatus::Running) return finish(st);
      } else if (Fx::kThermostat && t_heat != kNever<T> && t_heat <= t_sample && t_heat <= t_limit &&
                 (!Fx::kSheared || t_heat <= t_align)) {
        // At equal times disk events and actions go first, as the order of the kinds says; a realignment
        // due before the redraw goes first (it would otherwise be taken later, at a time in the past).
        redraw_velocity(s, t_heat);
        ++done;
        if (const RunStatus st = check_stops(s); st != RunStatus::Running) return finish(st);
        if (s.opt.rebuild_interval && s.events_done() % s.opt.rebuild_interval == 0) rebuild_predictions(s);
      } else if (Fx::kSheared && t_align != kNever<T> && t_align <= t_sample && t_align <= t_limit) {
        realign_sliding_rows(s, t_align);  // bookkeeping, not an event: not counted
      } else if (t_sample != kNever<T> && t_sample <= t_limit &&
                 !frozen_after(s, t_sample, std::min(next.time, t_heat), t_action, t_stop)) {
        take_sample(s, t_sample);
        ++done;  // samples count towards max_events, so a caller's run(n) always returns
      } else if (t_stop != kNever<T> && t_stop <= until) {
        s.now = t_stop;
        return finish(RunStatus::ReachedTime);
      } else if (until != kNever<T>) {
        s.now = std::max(s.now, until);  // paused: nothing happens before `until`
        return RunStatus::Running;
      } else {
        return finish(RunStatus::NoMoreEvents);
      }
    }
    return RunStatus::Running;
  }

 private:
  // The disk event a queue key names; false for a stale prediction (discarded, the disk re-predicted).
  bool process_disk_event(const QueueKey<T>& key) {
    State& s = s_;
    const std::int32_t i = std::int32_t(tag_disk(key.tag));
    const EventKind kind = tag_kind(key.tag);
    const Prediction<T>& pr = s.pred[i];
    const bool with_disk = kind == EventKind::Pair || (Fx::kSteps && kind == EventKind::Step);
    if (with_disk && pr.partner_moved(s.p.disk[pr.partner_id()].counter)) {
      ++s.counts.stale;
      s.now = key.time;
      predict_disk(s, i);
      return false;
    }
    note_time(s, key.time);
    s.now = key.time;
    switch (kind) {  // made from the list of event kinds: each kind to its room (resolve below)
#define EDE_EVENT_KIND_ROOM(name, value, text) \
  case EventKind::name: resolve<EventKind::name>(i, pr); break;
      EDE_EVENT_KINDS(EDE_EVENT_KIND_ROOM)
#undef EDE_EVENT_KIND_ROOM
    }
    return true;
  }

  // Each queued kind's room. Actions and samples are never queued (the loop takes them by time).
  template <EventKind K>
  void resolve(std::int32_t i, const Prediction<T>& pr) {
    State& s = s_;
    if constexpr (K == EventKind::Pair)
      resolve_pair(s, i, pr.partner_id(), pair_time_exact_v2(s, i, pr));
    else if constexpr (K == EventKind::Wall)
      resolve_wall(s, i, pr.partner_id());
    else if constexpr (K == EventKind::Segment && Fx::kSegments)
      resolve_segment(s, i, pr.partner_id());
    else if constexpr (K == EventKind::Step && Fx::kSteps)
      resolve_step(s, i, pr.partner_id());
    else if constexpr (K == EventKind::Cell)
      cross_cell(s, i, pr.cross_dir(), EventKind::Cell);
    else if constexpr (K == EventKind::Wrap && Fx::kSheared)  // through the top or bottom: the sliding edge
      pr.cross_dir() == kCrossUp || pr.cross_dir() == kCrossDown ? resolve_shear(s, i, pr.cross_dir())
                                                                 : resolve_wrap(s, i, pr.cross_dir());
    else if constexpr (K == EventKind::Wrap && Fx::kPeriodic)
      resolve_wrap(s, i, pr.cross_dir());
  }

  void load(const InitialState& init) {
    State& s = s_;
    const std::size_t n = init.size();
    s.p.disk.resize(n);
    std::vector<T> masses(n);
    if (uses_tc_model(s.opt.physics) && Fx::kDissipative) s.p.last_collision.assign(n, -scalar_limits<T>::infinity());
    for (std::size_t i = 0; i < n; ++i) {
      s.p.disk[i] = Disk<T>{T(init.x[i]), T(init.y[i]), T(init.vx[i]), T(init.vy[i]), T(0), T(init.radius[i]),
                            -1, 0, -1, -1};
      masses[i] = T(init.mass[i]);
    }
    s.p.set_masses(std::move(masses));
    s.p.set_species(init.species);
    if constexpr (Fx::kRough) Roughness<T>::load_spins(init, s.p);
    s.ke0 = kinetic_energy(s.p);
    if constexpr (Fx::kDissipative) s.dissipation.ke = s.ke0;
    if (s.opt.stop.time) s.stop_time = T(*s.opt.stop.time);
  }

  // A resumed engine takes the state of a rebuild point; start() then rebuilds exactly as the original
  // run did there, without telling the sinks again (they saw that point in the original run).
  void restore(const ResumePoint<T>& r) {
    State& s = s_;
    for (std::size_t i = 0; i < s.p.size(); ++i) {
      Disk<T>& d = s.p.disk[i];
      const Disk<T>& from = r.disks[i];
      d.x = from.x, d.y = from.y, d.vx = from.vx, d.vy = from.vy, d.t = from.t;
      d.last_partner = from.last_partner;
    }
    if (s.tc_model()) s.p.last_collision = r.last_collision;
    if constexpr (Fx::kRough)
      if (!r.omega.empty()) s.p.omega = r.omega;
    s.now = r.time;
    s.counts = r.counts;
    s.schedule.next_sample_index = r.next_sample_index;
    s.schedule.next_action_index = std::size_t(r.next_action_index);
    s.stall.same_time_events = r.same_time_events;
    s.ke0 = r.initial_energy;
    resumed_ = true;
  }

  void start() {
    started_ = true;
    if (resumed_) return rebuild_predictions(s_, false);
    for (Sink<T>* k : s_.sinks) k->on_start(s_.now, s_.p);
    rebuild_predictions(s_);
  }

  RunStatus finish(RunStatus st) {
    status_ = st;
    for (Sink<T>* k : s_.sinks) k->on_finish(s_.now, s_.p, st);
    return st;
  }

  State s_;
  UpcomingPrefetch prefetch_;
  bool started_ = false;
  bool resumed_ = false;
  RunStatus status_ = RunStatus::Running;
};

}  // namespace ede
