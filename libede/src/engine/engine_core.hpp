// Engine<T, Boundary, Dissipation, Field, Contact>: the event-driven hard-disk engine, one instantiation per
// effect set (effects.hpp; the instantiations that exist: engine_factory.hpp).
//
// The loop: take the earliest of (next disk event, next sample, next action, stop time); for a disk event,
// discard it if its partner changed since it was predicted (collision counters), else bring the disks
// involved to the event time (lazy state: nobody else moves), resolve, tell the sinks, re-predict those
// disks only. Each disk holds one prediction (its earliest collision, wall hit, or cell crossing), so the
// queue has N keys and a prediction looks at the 3 x 3 cells around the disk: the cost per event does not
// depend on N. Disks at rest predict nothing and cost nothing until something approaches them. The few
// disks much larger than the rest stay out of the cell lists (big_disks.hpp), so they do not set the
// cell size for everyone.
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

#include "engine/big_disks.hpp"
#include "engine/candidate.hpp"
#include "engine/cell_grid.hpp"
#include "engine/collide.hpp"
#include "engine/engine.hpp"
#include "core/initial_state.hpp"
#include "core/state_update.hpp"
#include "engine/effects.hpp"
#include "engine/event_queue.hpp"
#include "engine/predict_crossing.hpp"
#include "engine/predict_pair.hpp"
#include "engine/predict_wall.hpp"
#include "engine/segment_cells.hpp"
#include "core/scalar_math.hpp"
#include "core/segment.hpp"

namespace ede {

// Grid dimensions for a box and largest radius: cells at least one largest diameter wide (with a margin
// far above round-off), at most ~4 cells per disk (dilute scenes need no finer grid), at least 3 per side
// in a periodic box (so the 3 x 3 neighbourhood holds distinct cells and each has one image).
struct GridShape {
  std::int32_t nx = 1, ny = 1;
  DiskSizeSplit split;  // big disks (big_disks.hpp): the grid is sized by split.small_max_radius
};
GridShape grid_shape_for(double lx, double ly, double max_radius, std::size_t disks, bool periodic,
                         Algorithm algorithm);
// The grid for an initial state: big disks kept out of the cell lists when some stand out and the box
// allows it (periodic: n >= 2 reach + 3 on each side), else every disk in the grid.
GridShape engine_grid_for(const InitialState& init, bool periodic, Algorithm algorithm);

template <class T, class Boundary, class Dissipation, class Field = NoField, class Contact = StableContact,
          class Walls = NoSegments, class Spin = Smooth>
class Engine final : public EngineApi<T> {
  static constexpr bool kSegments = Walls::kSegments;
  static constexpr bool kRough = Spin::kRough;
  static_assert(!kRough || (Dissipation::kDissipative && !Field::kGravity && !kSegments),
                "rough disks run in a dissipative engine without gravity or segments");
  static_assert(!kSegments || (!Boundary::kPeriodic && !Field::kGravity), "segments need walls and no gravity");
  static constexpr bool kPeriodic = Boundary::kPeriodic;
  static constexpr bool kDissipative = Dissipation::kDissipative;
  static constexpr bool kGravity = Field::kGravity;

  // One disk's current prediction: its earliest collision (pair, wall or segment) and its cell crossing's
  // direction, kept apart so a crossing can update the collision part with the new neighbours only. The
  // crossing's time is not kept: it only chooses the queue key, right when it is computed (the key holds
  // whichever time won). 16 bytes in double (32 before issue 15's memory round: docs/performance.md):
  // `who` = partner (29 bits: disk id, WallId or segment number; all ones for none) | kind code << 29 |
  // fresh << 31; `check` = the partner's counter when predicted (its low 30 bits) << 2 | crossing direction.
  // A pair prediction is stale when the partner's counter moved since: 30 bits wrap only after 2^30
  // collisions of the partner while this prediction stands, as 32 bits did after 2^32 (never, in any run so
  // far). `fresh`: the collision was predicted at the time of this disk's own record, which has not changed
  // since (a wrap clears it): what lets the engine vouch for a pair's time to the log (pair_time_exact_v2).
  // Rejected: separate fields (24 B with the padding).
  struct Prediction {
    static constexpr std::uint32_t kPartnerBits = kTagDiskBits, kPartnerMask = (1u << kPartnerBits) - 1;
    static constexpr std::uint32_t kCounterMask = (1u << 30) - 1;
    static constexpr std::uint32_t kFreshBit = 1u << 31;
    T t_coll;
    std::uint32_t who;
    std::uint32_t check;

    std::int32_t partner() const {
      const std::uint32_t p = who & kPartnerMask;
      return p == kPartnerMask ? -1 : std::int32_t(p);
    }
    EventKind coll_kind() const {
      static constexpr EventKind kOf[] = {EventKind::Pair, EventKind::Wall, EventKind::Segment, EventKind::Pair};
      return kOf[(who >> kPartnerBits) & 3u];
    }
    // The partner of a pending (finite) event: never none.
    std::int32_t partner_id() const { return std::int32_t(who & kPartnerMask); }
    CrossDir cross_dir() const { return CrossDir(check & 3u); }
    bool partner_moved(std::uint32_t counter_now) const { return ((counter_now ^ (check >> 2)) & kCounterMask) != 0; }
    bool fresh() const { return (who & kFreshBit) != 0; }
    void clear_fresh() { who &= ~kFreshBit; }
    // The whole prediction at once (predict()); set_coll and set_cross update one part (cross_cell()).
    void set(const Candidate<T>& c, std::uint32_t counter, CrossDir dir, bool is_fresh) {
      t_coll = c.time;
      who = code_of(c) | (is_fresh ? kFreshBit : 0u);
      check = (counter & kCounterMask) << 2 | std::uint32_t(dir);
    }
    void set_coll(const Candidate<T>& c, std::uint32_t counter, bool is_fresh) {
      t_coll = c.time;
      who = code_of(c) | (is_fresh ? kFreshBit : 0u);
      check = (counter & kCounterMask) << 2 | (check & 3u);
    }
    // Partner -1 (none) becomes all ones in 29 bits by the mask; the kind code is 0 Pair, 1 Wall, 2 Segment.
    static std::uint32_t code_of(const Candidate<T>& c) {
      const std::uint32_t code = c.kind == EventKind::Segment ? 2u : std::uint32_t(c.kind);
      return (std::uint32_t(c.partner) & kPartnerMask) | code << kPartnerBits;
    }
    void set_cross(CrossDir dir) { check = (check & ~3u) | std::uint32_t(dir); }
  };

 public:
  Engine(const InitialState& init, const EngineOptions& options, GridShape shape, const ResumePoint<T>* resume)
      : opt_(options), tc_model_(kDissipative && uses_tc_model(options.physics)) {
    load(init);
    lx_ = T(init.lx);
    ly_ = T(init.ly);
    half_lx_ = lx_ / 2;
    half_ly_ = ly_ / 2;
    tc_ = T(options.physics.tc);
    if constexpr (kDissipative) setup_restitution(init.species_names, options.physics);
    if constexpr (kRough) setup_roughness(init.species_names, options.physics);
    if constexpr (kGravity) {
      gx_ = p_.gx = T(options.physics.gravity[0]);
      gy_ = p_.gy = T(options.physics.gravity[1]);
    }
    b_noise2_ = b_noise2_for(std::max(lx_, ly_));
    // The all-pairs baseline tests every disk, most of them far and receding: the branching test, which
    // skips their roots, keeps it the honest baseline it was (the selects made it 1.5x slower).
    select_pairs_ = init.size() <= options.branch_free_scan_up_to && options.algorithm != Algorithm::AllPairs;
    prefetch_ahead_ = init.size() >= options.prefetch_upcoming_from;
    grid_.reset(shape.nx, shape.ny, lx_, ly_, p_.disk);
    find_big_disks(init, shape.split);
    pair_times_vouchable_ = std::is_same_v<Contact, StableContact> && big_.empty() &&
                            (!kPeriodic || (grid_.nx() >= 5 && grid_.ny() >= 5));
    if constexpr (kSegments) setup_segments(options.physics, init, shape);
    queue_.reset(static_cast<std::uint32_t>(p_.size()));
    pred_.assign(p_.size(), Prediction{kNever<T>, Prediction::kPartnerMask, 0});
    stall_limit_ = options.stall_limit ? options.stall_limit
                                       : std::max<std::uint64_t>(1000000, 100 * std::uint64_t(p_.size()));
    if (options.stop.collisions_per_particle)
      pairs_to_stop_ = static_cast<std::uint64_t>(std::ceil(*options.stop.collisions_per_particle * double(p_.size()) / 2));
    if (resume) restore(*resume);
    next_pair_target_ = pair_target();
  }

  void add_sink(Sink<T>* sink) override { sinks_.push_back(sink); }
  T time() const override { return now_; }
  const Particles<T>& particles() const override { return p_; }
  const EventCounts& counts() const override { return counts_; }
  double initial_kinetic_energy() const override { return ke0_; }
  std::string stall_message() const override { return stall_message_; }

  std::string effects() const override {
    std::ostringstream s;
    s << Boundary::kName << ", ";
    if (kDissipative && !opt_.physics.elastic()) {
      s << "inelastic (xi=" << opt_.physics.restitution;
      if (!opt_.physics.pairs.empty()) s << ", " << opt_.physics.pairs.size() << " species pairs apart";
      s << ", xi_w=" << opt_.physics.wall_restitution;
      for (int w = 0; w < 4; ++w)
        if (opt_.physics.walls[std::size_t(w)]) s << ", " << kWallName[w] << " " << *opt_.physics.walls[std::size_t(w)];
      s << ")";
      if (tc_model()) s << ", TC (tc=" << opt_.physics.tc << ")";
    } else {
      s << "elastic";
    }
    if constexpr (kGravity) s << ", gravity (" << opt_.physics.gravity[0] << ", " << opt_.physics.gravity[1] << ")";
    if constexpr (kSegments) s << ", " << seg_.size() << (seg_.size() == 1 ? " segment" : " segments");
    if constexpr (kRough) {
      s << ", rough (beta=" << opt_.physics.roughness << ", beta_w=" << opt_.physics.wall_roughness;
      if (!opt_.physics.pairs.empty()) s << ", per species pair";
      s << ")";
    }
    s << Contact::kLabel;
    s << ", grid " << grid_.nx() << "x" << grid_.ny();
    if (!big_.empty()) s << " + " << big_.size() << (big_.size() == 1 ? " big disk" : " big disks");
    return s.str();
  }

  std::size_t memory_bytes() const override {
    return p_.disk.capacity() * sizeof(Disk<T>) + p_.masses.capacity() * sizeof(T) +
           p_.species_ids.capacity() * sizeof(std::int32_t) + p_.last_collision.capacity() * sizeof(T) +
           pred_.capacity() * sizeof(Prediction) + grid_.memory_bytes() + queue_.memory_bytes() +
           big_.capacity() * sizeof(BigDisk) + seg_.capacity() * sizeof(Segment<T>) + seg_cells_.memory_bytes() +
           (p_.omega.capacity() + p_.inertia.capacity() + beta_table_.capacity()) * sizeof(T);
  }

  RunStatus run(std::uint64_t max_events) override { return run_until(kNever<T>, max_events); }

  RunStatus run_until(T until, std::uint64_t max_events) override {
    if (status_ != RunStatus::Running) return status_;
    if (!started_) start();
    // Everything at or before `until` happens; a stop time before it ends the run as usual.
    const T t_limit = std::min(stop_time_, until);
    for (std::uint64_t done = 0; done < max_events;) {
      const QueueKey<T> next = queue_.top();
      if (prefetch_ahead_) prefetch_upcoming();
      const T t_sample = next_sample_time();
      const T t_action = next_action_time();
      const T t_stop = stop_time_;
      if (next.time <= t_sample && next.time <= t_action && next.time <= t_limit && next.time != kNever<T>) {
        if (!process_disk_event(next)) continue;  // stale prediction: not an event
        ++done;
        if (counts_.of(EventKind::Pair) >= next_pair_target_) done += on_pair_target();
        if (const RunStatus s = check_stops(); s != RunStatus::Running) return finish(s);
        if (opt_.rebuild_interval && counts_.events() % opt_.rebuild_interval == 0) rebuild();
      } else if (t_action != kNever<T> && t_action <= t_sample && t_action <= t_limit) {
        // Everything that happens at time <= t, actions included, happens before an observer looks at t.
        reverse_velocities(t_action);
        ++done;
        if (const RunStatus s = check_stops(); s != RunStatus::Running) return finish(s);
      } else if (t_sample != kNever<T> && t_sample <= t_limit && !frozen_after(t_sample, next.time, t_action, t_stop)) {
        sample(t_sample);
        ++done;  // samples count towards max_events, so a caller's run(n) always returns
      } else if (t_stop != kNever<T> && t_stop <= until) {
        now_ = t_stop;
        return finish(RunStatus::ReachedTime);
      } else if (until != kNever<T>) {
        now_ = std::max(now_, until);  // paused: nothing happens before `until`
        return RunStatus::Running;
      } else {
        return finish(RunStatus::NoMoreEvents);
      }
    }
    return RunStatus::Running;
  }

  // The disks of the next few events (the queue's next buckets), fetched into the cache in three stages
  // while the events before them run, each stage using what the one before brought in:
  //   1. their records and predictions;
  //   2. one event later, their partners' records and the cell heads of the 3 x 3 cells around them;
  //   3. one event after that, the first disk's record in each of those cells (the neighbour scan's
  //      loads; a cell's second disk is one more link away and not fetched).
  // Only the cache changes: the events are the same with or without (tests/engine/test_engine_run.cpp).
  // Cells on a periodic grid's edge are not wrapped here: those neighbours are just not fetched.
  void prefetch_upcoming() {
    for (std::uint32_t k = 0; k < heads_ready_.count; ++k)
      for_each_cell_row_around(heads_ready_.disk[k], [&](std::int32_t row) {
        for (std::int32_t c = row; c < row + 3; ++c)
          if (const std::int32_t h = grid_.head(c); h >= 0) __builtin_prefetch(&p_.disk[std::size_t(h)]);
      });
    heads_ready_.count = 0;
    for (std::uint32_t k = 0; k < records_ready_.count; ++k) {
      const std::int32_t d = records_ready_.disk[k];
      const Prediction& pr = pred_[std::size_t(d)];
      const std::int32_t partner = pr.partner();  // -1 for none (a disk at rest predicts nothing)
      if (partner >= 0 && pr.coll_kind() == EventKind::Pair) __builtin_prefetch(&p_.disk[std::size_t(partner)]);
      for_each_cell_row_around(d, [&](std::int32_t row) {
        __builtin_prefetch(grid_.head_data() + row);
        __builtin_prefetch(grid_.head_data() + row + 2);
      });
      heads_ready_.add(d);
    }
    records_ready_.count = 0;
    queue_.visit_ahead(kPrefetchBuckets, [&](std::int32_t d) {
      __builtin_prefetch(&p_.disk[std::size_t(d)]);
      __builtin_prefetch(&pred_[std::size_t(d)]);
      records_ready_.add(d);
    });
  }

  // f(first cell) for the rows below, at and above disk d's cell that lie wholly inside the grid's array.
  template <class F>
  void for_each_cell_row_around(std::int32_t d, F&& f) const {
    const std::int32_t cell = p_.disk[std::size_t(d)].cell, nx = grid_.nx(), cells = nx * grid_.ny();
    if (cell < 0) return;
    for (const std::int32_t row : {cell - nx - 1, cell - 1, cell + nx - 1})
      if (row >= 0 && row + 2 < cells) f(row);
  }

  // Three buckets (about three events) ahead: 2, 3, 5 and 8 measured alike at 10^6 disks.
  static constexpr std::uint32_t kPrefetchBuckets = 3;
  struct UpcomingDisks {  // the disks one prefetch stage has handled, for the next stage
    static constexpr std::uint32_t kMax = 16;
    std::int32_t disk[kMax] = {};
    std::uint32_t count = 0;
    void add(std::int32_t d) {
      if (count < kMax) disk[count++] = d;
    }
  };
  UpcomingDisks records_ready_, heads_ready_;

  // Nothing left to happen and no stop time: samples after now would observe the same state for ever
  // (disks at rest with only an event-count stop, say), so the run ends with NoMoreEvents instead of
  // sampling on. A sample at now itself (the time of the last action) is still taken.
  bool frozen_after(T t_sample, T t_event, T t_action, T t_stop) const {
    return t_sample > now_ && t_event == kNever<T> && t_action == kNever<T> && t_stop == kNever<T>;
  }

  double largest_overlap() const override {
    double worst = 0;
    for_each_near_pair([&](std::int32_t, std::int32_t, double distance, double contact) {
      worst = std::max(worst, (contact - distance) / contact);
    });
    return worst;
  }

  // Debug and test aid: every pair of disks overlapping by more than `tolerance` (relative to the contact
  // distance) at the current time, and predictions in the past. Empty when all is well. O(N) with the grid.
  std::string check_invariants(double tolerance) const override {
    std::ostringstream problems;
    for (std::size_t i = 0; i < p_.size(); ++i)
      if (queue_.key_of(std::uint32_t(i)).time < now_) problems << "disk " << i << " has an event in the past; ";
    for_each_near_pair([&](std::int32_t i, std::int32_t k, double distance, double contact) {
      if (distance < contact * (1 - tolerance))
        problems << "disks " << i << " and " << k << " overlap by " << (contact - distance) / contact
                 << " of their contact distance; ";
    });
    if constexpr (kSegments)
      for (std::size_t i = 0; i < p_.size(); ++i)
        for (std::size_t s = 0; s < seg_.size(); ++s) {
          const Position2<T> pi = pos_at(p_.disk[i]);
          const double distance = double(segment_distance(seg_[s], pi.x, pi.y)), r = double(p_.disk[i].r);
          if (distance < r * (1 - tolerance))
            problems << "disk " << i << " overlaps segment " << s << " by " << (r - distance) / r << " of its radius; ";
        }
    return problems.str();
  }

  // Calls f(i, k, distance, contact distance) at now_ for every pair of disks close enough to touch
  // (through any periodic image), each pair at least once: neighbouring cells, and big disks' reach.
  template <class F>
  void for_each_near_pair(F&& f) const {
    const auto visit = [&](std::int32_t i, std::int32_t k, T sx, T sy) {
      const Position2<T> pi = pos_at(p_.disk[i]), pk = pos_at(p_.disk[k]);
      const double dx = double((pk.x + sx) - pi.x), dy = double((pk.y + sy) - pi.y);
      f(i, k, std::sqrt(dx * dx + dy * dy), double(p_.disk[i].r + p_.disk[k].r));
    };
    for (std::size_t i = 0; i < p_.size(); ++i) {
      if (is_big(p_.disk[i])) continue;
      for_each_neighbour(std::int32_t(i), grid_.cell_of(std::int32_t(i)), [&](std::int32_t k, T sx, T sy) {
        if (std::size_t(k) > i) visit(std::int32_t(i), k, sx, sy);
      });
    }
    for (const BigDisk& b : big_) {
      for_each_in_reach(b, [&](std::int32_t k, T sx, T sy) { visit(b.id, k, sx, sy); });
      for (const BigDisk& other : big_) {
        if (other.id <= b.id) continue;
        const int images = kPeriodic ? 1 : 0;
        for (int ky = -images; ky <= images; ++ky)
          for (int kx = -images; kx <= images; ++kx) visit(b.id, other.id, T(kx) * lx_, T(ky) * ly_);
      }
    }
  }

 private:
  // --- state set-up -------------------------------------------------------------------------------
  void load(const InitialState& init) {
    const std::size_t n = init.size();
    p_.disk.resize(n);
    std::vector<T> masses(n);
    if (tc_model()) p_.last_collision.assign(n, -scalar_limits<T>::infinity());
    for (std::size_t i = 0; i < n; ++i) {
      p_.disk[i] = Disk<T>{T(init.x[i]), T(init.y[i]), T(init.vx[i]), T(init.vy[i]), T(0), T(init.radius[i]),
                           -1, 0, -1, -1};
      masses[i] = T(init.mass[i]);
    }
    p_.set_masses(std::move(masses));
    p_.set_species(init.species);
    if constexpr (kRough) load_spins(init);
    ke0_ = kinetic_energy(p_);
    ke_ = ke0_;
    if (opt_.stop.time) stop_time_ = T(*opt_.stop.time);
  }

  // A resumed engine takes the state of a rebuild point; start() then rebuilds exactly as the original
  // run did there, without telling the sinks again (they saw that point in the original run).
  void restore(const ResumePoint<T>& r) {
    for (std::size_t i = 0; i < p_.size(); ++i) {
      Disk<T>& d = p_.disk[i];
      const Disk<T>& from = r.disks[i];
      d.x = from.x, d.y = from.y, d.vx = from.vx, d.vy = from.vy, d.t = from.t;
      d.last_partner = from.last_partner;
    }
    if (tc_model()) p_.last_collision = r.last_collision;
    if constexpr (kRough)
      if (!r.omega.empty()) p_.omega = r.omega;
    now_ = r.time;
    counts_ = r.counts;
    next_sample_index_ = r.next_sample_index;
    next_action_index_ = std::size_t(r.next_action_index);
    same_time_events_ = r.same_time_events;
    ke0_ = r.initial_energy;
    resumed_ = true;
  }

  void start() {
    started_ = true;
    if (resumed_) return rebuild(false);
    for (Sink<T>* s : sinks_) s->on_start(now_, p_);
    rebuild();
  }

  // Rebuilds cells and every prediction from the state alone (positions at now_, last partners): the same
  // state always gives the same queue, which is what makes a resumed run identical to an uninterrupted one.
  void rebuild(bool notify = true) {
    grid_.reset(grid_.nx(), grid_.ny(), lx_, ly_, p_.disk);
    for (std::size_t i = 0; i < p_.size(); ++i) {
      const Position2<T> pos = pos_at(p_.disk[i]);
      const std::int32_t cell = grid_.cell_containing(pos.x, pos.y);
      if (is_big(p_.disk[i]))
        grid_.set_home(std::int32_t(i), cell);
      else
        grid_.insert(std::int32_t(i), cell);
    }
    for (std::size_t i = 0; i < p_.size(); ++i) predict(std::int32_t(i));
    if constexpr (kDissipative) ke_ = kinetic_energy(p_);
    if (!notify) return;
    const RebuildPoint<T> point{now_, p_, counts_, next_sample_index_, next_action_index_, same_time_events_, ke0_};
    for (Sink<T>* s : sinks_) s->on_rebuild(point);
  }

  // --- prediction ---------------------------------------------------------------------------------
  // Calls f(k, shift_x, shift_y) for every disk k != i in the 3 x 3 cells around `cell`.
  template <class F>
  void for_each_neighbour(std::int32_t i, std::int32_t cell, F&& f) const {
    const std::int32_t cx = grid_.cell_x(cell), cy = grid_.cell_y(cell);
    for (std::int32_t dy = -1; dy <= 1; ++dy)
      for (std::int32_t dx = -1; dx <= 1; ++dx) visit_cell(i, cx + dx, cy + dy, f);
  }

  // Calls f for every disk k != i in cell (cx, cy), wrapped in a periodic box (else skipped if outside).
  template <class F>
  void visit_cell(std::int32_t i, std::int32_t cx, std::int32_t cy, F&& f) const {
    T sx = 0, sy = 0;
    if (!wrap_index(cx, grid_.nx(), lx_, sx) || !wrap_index(cy, grid_.ny(), ly_, sy)) return;
    for (std::int32_t k = grid_.head(grid_.cell_at(cx, cy)); k != CellGrid<T>::kNone; k = grid_.next(k))
      if (k != i) f(k, sx, sy);
  }

  static bool wrap_index(std::int32_t& c, std::int32_t n, T length, T& shift) {
    if (c >= 0 && c < n) return true;
    if constexpr (!kPeriodic) {
      return false;
    } else {
      shift = c < 0 ? -length : length;
      c = c < 0 ? c + n : c - n;
      return true;
    }
  }

  // A pair that has just collided (each is the other's last partner, no velocity change since) cannot
  // meet again through the image they collided in: straight lines cross a circle once on the way in.
  // Skipping it keeps round-off from turning their separation into a spurious second collision at once
  // (for xi = 0 the post-collision approach speed is zero up to round-off in the velocities, which can
  // exceed the position floor of pair_contact_time when both disks move fast).
  // In a walled box that is the whole story. In a periodic box the pair can meet again through another
  // image after a long flight, and the image they collided in is not recorded: it is the one in which they
  // still touch (to kJustCollidedRange), since two images of one disk can never both touch (L >= 3 cells).
  // A pair far apart in the collision image is receding there (b > 0), so nothing needs skipping. And a
  // pair that touches while approaching faster than round-off (b clearly negative) arrived through another
  // image: it is never skipped, so no window is left in which a real collision could be missed.
  bool just_collided(std::int32_t i, std::int32_t k, T dx, T dy) const {
    if (p_.disk[i].last_partner != k || p_.disk[k].last_partner != i) return false;
    if constexpr (kPeriodic) {
      const Disk<T>&di = p_.disk[i], &dk = p_.disk[k];
      const T s = di.r + dk.r;
      if (dx * dx + dy * dy > s * s * (T(1) + T(1e-6))) return false;
      const Position2<T> vi = vel_at(di), vk = vel_at(dk);
      const T b = dx * (vk.x - vi.x) + dy * (vk.y - vi.y);
      const T speeds = ede::abs(vi.x) + ede::abs(vi.y) + ede::abs(vk.x) + ede::abs(vk.y);
      return b >= -T(64) * scalar_limits<T>::epsilon() * s * speeds;
    }
    return true;
  }

  // Position and velocity of a disk at now_: straight lines, or parabolas under gravity.
  Position2<T> pos_at(const Disk<T>& d) const {
    if constexpr (kGravity)
      return {position_along(d.x, d.vx, gx_, d.t, now_), position_along(d.y, d.vy, gy_, d.t, now_)};
    else
      return position_at(d, now_);
  }
  Position2<T> vel_at(const Disk<T>& d) const {
    if constexpr (kGravity)
      return {velocity_along(d.vx, gx_, d.t, now_), velocity_along(d.vy, gy_, d.t, now_)};
    else
      return {d.vx, d.vy};
  }

  // Time at which disks i (at pi with velocity vi, now) and k (image shifted by sx, sy) touch. Under gravity
  // their relative motion is still a straight line, from their velocities at now.
  T pair_time(const Disk<T>& di, Position2<T> pi, Position2<T> vi, const Disk<T>& dk, T sx, T sy) const {
    if constexpr (kGravity) {
      const Position2<T> pk = pos_at(dk), vk = vel_at(dk);
      return now_ + Contact::time((pk.x + sx) - pi.x, (pk.y + sy) - pi.y, vk.x - vi.x, vk.y - vi.y, di.r + dk.r,
                                  b_noise2_);
    } else {
      (void)vi;
      return predict_pair<Contact>(di, pi, dk, sx, sy, now_, b_noise2_);
    }
  }

  // Straight-line contacts with the library's root can be tested without branches (consider_pair), up to
  // EngineOptions::branch_free_scan_up_to disks.
  static constexpr bool kSelectPairs = !kGravity && std::is_same_v<Contact, StableContact>;

  // Disk i (at pi with velocity vi, now) against disk k's image shifted by (sx, sy): keeps the earlier.
  [[gnu::always_inline]] void consider_pair(std::int32_t i, Position2<T> pi, Position2<T> vi, std::int32_t k, T sx,
                                           T sy, Candidate<T>& best) const {
    const Disk<T>& di = p_.disk[i];
    const Disk<T>& dk = p_.disk[k];
    if (k == di.last_partner) {
      const Position2<T> pk = pos_at(dk);
      if (just_collided(i, k, (pk.x + sx) - pi.x, (pk.y + sy) - pi.y)) return;
    }
    if (kSelectPairs && select_pairs_) {
      // Without branches on the data (pair_contact_time_select): Candidate::before spelled out as selects
      // for a pair candidate {t, Pair, k}, so the winner is the same as the branching version's. (Letting
      // disk i itself through, masked here, instead of scan_3x3's test was 7 % slower at 10^4 disks.)
      const T t = predict_pair<StableContactSelect>(di, pi, dk, sx, sy, now_, b_noise2_);
      const bool tie_won = (best.kind != EventKind::Pair) | (k < best.partner);
      const bool better = (t < best.time) | ((t == best.time) & tie_won);
      best.time = select_value(better, t, best.time);
      best.partner = better ? k : best.partner;
      best.kind = better ? EventKind::Pair : best.kind;
    } else {
      const T t = pair_time(di, pi, vi, dk, sx, sy);
      if (t > best.time) return;
      const Candidate<T> c{t, EventKind::Pair, k};
      if (c.before(best)) best = c;
    }
  }

  // Best pair candidate of disk i against the disks of cell (cx, cy).
  void scan_cell(std::int32_t i, Position2<T> pi, Position2<T> vi, std::int32_t cx, std::int32_t cy,
                 Candidate<T>& best) const {
    visit_cell(i, cx, cy, [&](std::int32_t k, T sx, T sy) { consider_pair(i, pi, vi, k, sx, sy, best); });
  }

  // The 3 x 3 cells around (cx, cy), in scan_cell's order (rows from below, columns from the left), with
  // the three columns' and rows' wrapping worked out once instead of once per cell: what predict() does
  // for every small disk, ~40 % of the run. (The order does not change the result: Candidate's order is
  // total; it is kept anyway.)
  void scan_3x3(std::int32_t i, Position2<T> pi, Position2<T> vi, std::int32_t cx, std::int32_t cy,
                Candidate<T>& best) const {
    std::int32_t col[3], row[3];
    T sx[3], sy[3];
    int ncol = 0, nrow = 0;
    for (std::int32_t d = -1; d <= 1; ++d) {
      std::int32_t c = cx + d;
      T s = 0;
      if (wrap_index(c, grid_.nx(), lx_, s)) col[ncol] = c, sx[ncol++] = s;
      c = cy + d;
      s = 0;
      if (wrap_index(c, grid_.ny(), ly_, s)) row[nrow] = c, sy[nrow++] = s;
    }
    for (int r = 0; r < nrow; ++r)
      for (int c = 0; c < ncol; ++c)
        for (std::int32_t k = grid_.head(grid_.cell_at(col[c], row[r])); k != CellGrid<T>::kNone; k = grid_.next(k))
          if (k != i) consider_pair(i, pi, vi, k, sx[c], sy[r], best);
  }

  // --- big disks (big_disks.hpp) -----------------------------------------------------------------
  struct BigDisk {
    std::int32_t id, reach_x, reach_y;  // the block of cells it scans: (2 reach + 1) on each side
  };

  void find_big_disks(const InitialState& init, const DiskSizeSplit& split) {
    big_radius_ = T(split.big_radius);
    const double wx = double(lx_) / grid_.nx(), wy = double(ly_) / grid_.ny();
    for (std::size_t i = 0; i < init.size(); ++i)
      if (init.radius[i] > split.big_radius)
        big_.push_back({std::int32_t(i), big_disk_reach(init.radius[i], split.small_max_radius, wx),
                        big_disk_reach(init.radius[i], split.small_max_radius, wy)});
  }

  bool is_big(const Disk<T>& d) const { return d.r > big_radius_; }

  const BigDisk& big_entry(std::int32_t i) const {
    return *std::find_if(big_.begin(), big_.end(), [&](const BigDisk& b) { return b.id == i; });
  }

  // Disk i against every big disk (but itself). A small disk takes the nearest image, the only one it can
  // reach before it next crosses a cell (n >= 2 reach + 3); two big disks try the 3 x 3 images.
  void scan_big(std::int32_t i, Position2<T> pi, Position2<T> vi, bool i_big, Candidate<T>& best) const {
    for (const BigDisk& b : big_) {
      if (b.id == i) continue;
      if constexpr (kPeriodic) {
        if (i_big) {
          for (int ky = -1; ky <= 1; ++ky)
            for (int kx = -1; kx <= 1; ++kx) consider_pair(i, pi, vi, b.id, T(kx) * lx_, T(ky) * ly_, best);
          continue;
        }
        const Position2<T> pb = pos_at(p_.disk[b.id]);
        const T dx = pb.x - pi.x, dy = pb.y - pi.y;
        const T sx = dx > half_lx_ ? -lx_ : dx < -half_lx_ ? lx_ : T(0);
        const T sy = dy > half_ly_ ? -ly_ : dy < -half_ly_ ? ly_ : T(0);
        consider_pair(i, pi, vi, b.id, sx, sy, best);
      } else {
        (void)i_big;
        consider_pair(i, pi, vi, b.id, T(0), T(0), best);
      }
    }
  }

  // Calls f(k, shift_x, shift_y) for every small disk within a big disk's reach.
  template <class F>
  void for_each_in_reach(const BigDisk& b, F&& f) const {
    const std::int32_t cell = grid_.cell_of(b.id);
    const std::int32_t cx = grid_.cell_x(cell), cy = grid_.cell_y(cell);
    for (std::int32_t dy = -b.reach_y; dy <= b.reach_y; ++dy)
      for (std::int32_t dx = -b.reach_x; dx <= b.reach_x; ++dx) visit_cell(b.id, cx + dx, cy + dy, f);
  }

  // --- wall segments (WithSegments only) --------------------------------------------------------------
  // Segments with their cell lists: a cell lists those within the largest small radius of it (with a
  // margin for a centre a hair past its cell's side); a big disk, whose reach is wider, tries them all.
  void setup_segments(const PhysicsSpec& ph, const InitialState& init, const GridShape& shape) {
    std::vector<std::array<double, 4>> ends;
    for (const SegmentSpec& s : ph.segments) {
      seg_.push_back(make_segment(T(s.from[0]), T(s.from[1]), T(s.to[0]), T(s.to[1]), T(s.restitution)));
      ends.push_back({s.from[0], s.from[1], s.to[0], s.to[1]});
    }
    double largest = 0;  // the largest radius in the cell lists (every disk when none is big)
    for (const double r : init.radius)
      if (r <= shape.split.big_radius) largest = std::max(largest, r);
    const double reach = largest * (1 + 1e-6) + 1e-9 * std::max(double(lx_), double(ly_));
    seg_cells_.build(ends, grid_.nx(), grid_.ny(), double(lx_), double(ly_), reach);
  }

  // Disk d's earliest segment hit, from its record (the time does not depend on now: replay predicts it
  // from the same record), against the segments of `cell` (every segment for a big disk).
  void scan_segments(const Disk<T>& d, std::int32_t cell, bool big, Candidate<T>& best) const {
    const auto consider = [&](std::int32_t s) {
      const T dt = segment_contact_time(seg_[std::size_t(s)], d.x, d.y, d.vx, d.vy, d.r, b_noise2_);
      if (dt == kNever<T>) return;
      T t = d.t + dt;
      if (t < now_) t = now_;
      const Candidate<T> c{t, EventKind::Segment, s};
      if (c.before(best)) best = c;
    };
    if (big) {
      for (std::size_t s = 0; s < seg_.size(); ++s) consider(std::int32_t(s));
      return;
    }
    for (const std::int32_t* s = seg_cells_.begin(cell); s != seg_cells_.end(cell); ++s) consider(*s);
  }

  // Full prediction for disk i at now_: walls, pairs in the 3 x 3 cells, cell crossing.
  void predict(std::int32_t i) {
    const Disk<T>& d = p_.disk[i];
    Candidate<T> best;
    if constexpr (kGravity)
      best = predict_wall_accelerated(d, lx_, ly_, gx_, gy_, now_);
    else if constexpr (!kPeriodic)
      best = predict_wall(d, lx_, ly_, now_);
    const Position2<T> pi = pos_at(d), vi = vel_at(d);
    const std::int32_t cell = grid_.cell_of(i);
    const std::int32_t cx = grid_.cell_x(cell), cy = grid_.cell_y(cell);
    std::int32_t reach_x = 1, reach_y = 1;
    const bool big = !big_.empty() && is_big(d);
    if constexpr (kSegments) scan_segments(d, cell, big, best);
    if (big) {
      const BigDisk& b = big_entry(i);
      reach_x = b.reach_x, reach_y = b.reach_y;
    }
    if (!big) {
      scan_3x3(i, pi, vi, cx, cy, best);
    } else {
      for (std::int32_t dy = -reach_y; dy <= reach_y; ++dy)
        for (std::int32_t dx = -reach_x; dx <= reach_x; ++dx) scan_cell(i, pi, vi, cx + dx, cy + dy, best);
    }
    if (!big_.empty()) scan_big(i, pi, vi, big, best);
    Prediction& pr = pred_[i];
    const Crossing<T> cross = crossing(d, cell);
    pr.set(best, counter_of(best), cross.dir, now_ == d.t);
    push(i, cross.time, best.kind);
  }

  Crossing<T> crossing(const Disk<T>& d, std::int32_t cell) const {
    if constexpr (kGravity)
      return predict_crossing_accelerated(d, grid_, cell, gx_, gy_, now_);
    else
      return predict_crossing(d, grid_, cell, kPeriodic, now_);
  }

  std::uint32_t counter_of(const Candidate<T>& c) const {
    return c.kind == EventKind::Pair && c.partner >= 0 ? p_.disk[c.partner].counter : 0;
  }

  // The disk's queue key: its collision (of kind coll_kind) or its crossing, whichever comes first.
  void push(std::int32_t i, T t_cross, EventKind coll_kind) {
    const Prediction& pr = pred_[i];
    if (pr.t_coll <= t_cross)
      queue_.set(std::uint32_t(i), pr.t_coll, coll_kind);
    else
      queue_.set(std::uint32_t(i), t_cross, is_wrap(i, pr.cross_dir()) ? EventKind::Wrap : EventKind::Cell);
  }

  bool is_wrap(std::int32_t i, CrossDir dir) const {
    if constexpr (!kPeriodic) {
      return false;
    } else {
      const std::int32_t cell = grid_.cell_of(i);
      switch (dir) {
        case kCrossRight: return grid_.cell_x(cell) == grid_.nx() - 1;
        case kCrossLeft: return grid_.cell_x(cell) == 0;
        case kCrossUp: return grid_.cell_y(cell) == grid_.ny() - 1;
        case kCrossDown: return grid_.cell_y(cell) == 0;
      }
      return false;
    }
  }

  // --- what the engine vouches for to the log ----------------------------------------------------
  // The log (format version 2) codes each event against its own predictors (log/event_predictions.hpp, over
  // log/rules/). Where the engine knows it computed exactly what they would, it says so with the event
  // (EventOutcome::v2_*_exact) and the writer codes a residual of 0 without computing anything; elsewhere
  // the writer runs the predictor on the records the event carries. A wrong vouch would make a log decode
  // wrongly, so each one rests on a test: tests/log/test_format_rules.cpp (the engine's functions give the
  // format's bits) and tests/log/test_log_exactness.cpp (every example scene written with the writer
  // recomputing what was vouched for, log.check_exactness).
  // The collision rules (engine/collide.hpp) are format version 2's: every velocity and spin residual is 0.
  // An engine whose rule changes sets this false (and its logs grow) until a format version follows it.
  static constexpr bool kRulesAreFormatV2 = true;

  // A pair's time as format version 2 predicts it from the two records just before the event is exactly the
  // time this engine predicted when: the owner's prediction was made at the time of its own record, which is
  // unchanged since (fresh); the partner's record is strictly older (so the format predicts from the owner's
  // side, at the same now; an equal time would let the format take the other side); the partner's image is
  // the one the format picks (no big disks, whose images are chosen apart; in a periodic box at least five
  // cells a side, so a neighbour's image is within a tenth of the box of the nearest one); and the root is
  // the format's (StableContact; the select scan gives its bits).
  bool pair_time_exact_v2(std::int32_t owner, const Prediction& pr) const {
    if (!pair_times_vouchable_ || !pr.fresh()) return false;
    return p_.disk[pr.partner_id()].t < p_.disk[owner].t;
  }

  // --- events -------------------------------------------------------------------------------------
  // Returns false for a stale prediction (discarded, the disk re-predicted).
  bool process_disk_event(const QueueKey<T>& key) {
    const std::int32_t i = std::int32_t(tag_disk(key.tag));
    const EventKind kind = tag_kind(key.tag);
    const Prediction& pr = pred_[i];
    if (kind == EventKind::Pair && pr.partner_moved(p_.disk[pr.partner_id()].counter)) {
      ++counts_.stale;
      now_ = key.time;
      predict(i);
      return false;
    }
    note_time(key.time);
    now_ = key.time;
    switch (kind) {
      case EventKind::Pair: resolve_pair(i, pr.partner_id(), pair_time_exact_v2(i, pr)); break;
      case EventKind::Wall: resolve_wall(i, pr.partner_id()); break;
      case EventKind::Segment:
        if constexpr (kSegments) resolve_segment(i, pr.partner_id());
        break;
      default: cross_cell(i, pr.cross_dir(), kind); break;
    }
    return true;
  }

  void advance(std::int32_t i) {
    if constexpr (kGravity)
      advance_disk(p_.disk[i], now_, gx_, gy_);
    else
      advance_disk(p_.disk[i], now_);
  }

  // The TC model is on for a dissipative scene with tc > 0 (uses_tc_model): a compile-time false in the
  // Elastic engine, a value in the Dissipative one. Within t_c of either disk's previous collision it makes
  // a collision elastic.
  bool tc_model() const { return kDissipative && tc_model_; }
  bool tc_elastic(std::int32_t i, std::int32_t j) const {
    if (!tc_model()) return false;
    if (now_ - p_.last_collision[i] < tc_) return true;
    return j >= 0 && now_ - p_.last_collision[j] < tc_;
  }

  // The pair is resolved in the order (lower id, higher id) whichever disk owned the prediction, so the
  // rounding of the result does not depend on who predicted it (cells and all-pairs engines agree).
  void resolve_pair(std::int32_t i, std::int32_t j, bool time_exact_v2) {
    if (j < i) std::swap(i, j);
    const RecordBefore<T> before_i = record_before(p_.disk[i]), before_j = record_before(p_.disk[j]);
    T wi0 = 0, wj0 = 0;
    if constexpr (kRough) wi0 = p_.omega[i], wj0 = p_.omega[j];
    advance(i);
    advance(j);
    Disk<T>& a = p_.disk[i];
    Disk<T>& b = p_.disk[j];
    const T vix0 = a.vx, viy0 = a.vy, vjx0 = b.vx, vjy0 = b.vy;
    T dx = b.x - a.x, dy = b.y - a.y;
    if constexpr (kPeriodic) {
      if (dx > half_lx_) dx -= lx_; else if (dx < -half_lx_) dx += lx_;
      if (dy > half_ly_) dy -= ly_; else if (dy < -half_ly_) dy += ly_;
    }
    const bool by_tc = tc_elastic(i, j);
    if constexpr (kDissipative) {
      const double ke_before = pair_energy(i, j);
      collide_pair(dx, dy, p_.mass(i), p_.mass(j), by_tc ? T(2) : pair_one_plus_xi(i, j), a.vx, a.vy, b.vx, b.vy);
      if constexpr (kRough)
        collide_pair_tangential(dx, dy, vjx0 - vix0, vjy0 - viy0, p_.mass(i), p_.mass(j), a.r, b.r, p_.inertia[i],
                                p_.inertia[j], by_tc ? T(0) : pair_one_plus_beta(i, j), a.vx, a.vy, b.vx, b.vy,
                                p_.omega[i], p_.omega[j]);
      ke_ += pair_energy(i, j) - ke_before;
      note_if_too_slow(i);
      note_if_too_slow(j);
      if (tc_model()) p_.last_collision[i] = p_.last_collision[j] = now_;
    } else {
      collide_pair(dx, dy, p_.mass(i), p_.mass(j), T(2), a.vx, a.vy, b.vx, b.vy);
    }
    ++a.counter;
    ++b.counter;
    a.last_partner = j;
    b.last_partner = i;
    ++counts_.by_kind[int(EventKind::Pair)];
    if (by_tc) ++counts_.tc_elastic;
    if (!sinks_.empty()) {
      EventOutcome<T> o{now_, EventKind::Pair, by_tc, i, j, a.vx, a.vy, b.vx, b.vy, vix0, viy0, vjx0, vjy0};
      if constexpr (kRough) o.wi = p_.omega[i], o.wj = p_.omega[j], o.wi0 = wi0, o.wj0 = wj0;
      o.before_i = before_i, o.before_j = before_j;
      o.v2_time_exact = time_exact_v2;
      o.v2_velocities_exact = kRulesAreFormatV2;
      emit(o);
    }
    predict(i);
    predict(j);
  }

  void resolve_wall(std::int32_t i, std::int32_t wall) {
    const RecordBefore<T> before = record_before(p_.disk[i]);
    T wi0 = 0;
    if constexpr (kRough) wi0 = p_.omega[i];
    advance(i);
    Disk<T>& d = p_.disk[i];
    const T vx0 = d.vx, vy0 = d.vy;
    const bool vertical = wall == kWallLeft || wall == kWallRight;
    const bool by_tc = tc_elastic(i, -1);
    if constexpr (kDissipative) {
      const double ke_before = disk_energy(i);
      if (by_tc)
        collide_wall_elastic(vertical, d.vx, d.vy);
      else
        collide_wall(vertical, xi_wall_[wall], d.vx, d.vy);
      if constexpr (kRough)
        if (!by_tc)
          collide_wall_tangential(kWallNormal[wall][0], kWallNormal[wall][1], vx0, vy0, p_.mass(i), d.r,
                                  p_.inertia[i], wall_one_plus_beta_, d.vx, d.vy, p_.omega[i]);
      ke_ += disk_energy(i) - ke_before;
      note_if_too_slow(i);
      if (tc_model()) p_.last_collision[i] = now_;
    } else {
      collide_wall_elastic(vertical, d.vx, d.vy);
    }
    ++d.counter;
    d.last_partner = -1;
    ++counts_.by_kind[int(EventKind::Wall)];
    if (by_tc) ++counts_.tc_elastic;
    if (!sinks_.empty()) {
      EventOutcome<T> o{now_, EventKind::Wall, by_tc, i, wall, d.vx, d.vy, T(0), T(0), vx0, vy0, T(0), T(0)};
      if constexpr (kRough) o.wi = p_.omega[i], o.wi0 = wi0;
      o.before_i = before;
      o.v2_velocities_exact = kRulesAreFormatV2;
      emit(o);
    }
    predict(i);
  }

  // A disk hits wall segment s (core/segment.hpp): the segment's rule (collide_segment) at the disk's
  // position now, which tells body from end point; like a wall, it leaves no partner to skip.
  void resolve_segment(std::int32_t i, std::int32_t s) {
    const RecordBefore<T> before = record_before(p_.disk[i]);
    advance(i);
    Disk<T>& d = p_.disk[i];
    const T vx0 = d.vx, vy0 = d.vy;
    const bool by_tc = tc_elastic(i, -1);
    const double ke_before = disk_energy(i);
    collide_segment(seg_[std::size_t(s)], d.x, d.y, by_tc ? T(2) : seg_[std::size_t(s)].one_plus_xi, d.vx, d.vy);
    ke_ += disk_energy(i) - ke_before;
    note_if_too_slow(i);
    if (tc_model()) p_.last_collision[i] = now_;
    ++d.counter;
    d.last_partner = -1;
    ++counts_.by_kind[int(EventKind::Segment)];
    if (by_tc) ++counts_.tc_elastic;
    if (!sinks_.empty()) {
      EventOutcome<T> o{now_, EventKind::Segment, by_tc, i, s, d.vx, d.vy, T(0), T(0), vx0, vy0, T(0), T(0)};
      o.before_i = before;
      o.v2_velocities_exact = kRulesAreFormatV2;
      emit(o);
    }
    predict(i);
  }

  // Moves disk i into the neighbouring cell; at a periodic edge its stored position wraps by one box
  // length (a state change, so it is an event sinks see). Then only the three cells that became
  // neighbours (for a big disk, the strip of its reach block) and the big disks are searched:
  // predictions against the others are still valid.
  void cross_cell(std::int32_t i, CrossDir dir, EventKind kind) {
    const std::int32_t cell = grid_.cell_of(i);
    std::int32_t cx = grid_.cell_x(cell), cy = grid_.cell_y(cell);
    const std::int32_t step_x = dir == kCrossRight ? 1 : dir == kCrossLeft ? -1 : 0;
    const std::int32_t step_y = dir == kCrossUp ? 1 : dir == kCrossDown ? -1 : 0;
    cx += step_x;
    cy += step_y;
    if constexpr (kPeriodic) {
      if (kind == EventKind::Wrap) wrap(i, dir), pred_[i].clear_fresh();  // its record moved: see Prediction
      cx = (cx + grid_.nx()) % grid_.nx();
      cy = (cy + grid_.ny()) % grid_.ny();
    }
    const bool big = !big_.empty() && is_big(p_.disk[i]);
    std::int32_t reach_x = 1, reach_y = 1;
    if (big) {
      const BigDisk& b = big_entry(i);
      reach_x = b.reach_x, reach_y = b.reach_y;
      grid_.set_home(i, grid_.cell_at(cx, cy));
    } else {
      grid_.move(i, grid_.cell_at(cx, cy));
    }
    ++counts_.by_kind[int(kind)];

    Prediction& pr = pred_[i];
    Candidate<T> best{pr.t_coll, pr.coll_kind(), pr.partner()};
    const Position2<T> pi = pos_at(p_.disk[i]), vi = vel_at(p_.disk[i]);
    if (step_x != 0)
      for (std::int32_t k = -reach_y; k <= reach_y; ++k) scan_cell(i, pi, vi, cx + step_x * reach_x, cy + k, best);
    else
      for (std::int32_t k = -reach_x; k <= reach_x; ++k) scan_cell(i, pi, vi, cx + k, cy + step_y * reach_y, best);
    if (!big_.empty()) scan_big(i, pi, vi, big, best);
    if constexpr (kSegments) scan_segments(p_.disk[i], grid_.cell_of(i), big, best);
    if (best.time != pr.t_coll || best.kind != pr.coll_kind() || best.partner != pr.partner())
      pr.set_coll(best, counter_of(best), now_ == p_.disk[i].t);
    const Crossing<T> cross = crossing(p_.disk[i], grid_.cell_of(i));
    pr.set_cross(cross.dir);
    push(i, cross.time, best.kind);
  }

  void wrap(std::int32_t i, CrossDir dir) {
    static constexpr std::int32_t kWrapOf[] = {kWrapRight, kWrapLeft, kWrapTop, kWrapBottom};
    Disk<T>& d = p_.disk[i];
    const RecordBefore<T> before = record_before(d);
    wrap_disk(d, now_, kWrapOf[dir], lx_, ly_);
    if (!sinks_.empty()) {
      EventOutcome<T> o{now_, EventKind::Wrap, false, i, kWrapOf[dir], d.vx, d.vy, T(0), T(0), d.vx, d.vy, T(0), T(0)};
      o.before_i = before;
      emit(o);
    }
  }

  void sample(T t) {
    now_ = t;
    ++next_sample_index_;
    ++counts_.by_kind[int(EventKind::Sample)];
    for (Sink<T>* s : sinks_) s->on_sample(t, p_);
  }

  // The time-reversal action: every disk is brought to now and its velocity negated (exact in floating
  // point), then every prediction is rebuilt.
  void reverse_velocities(T t) {
    now_ = t;
    ++next_action_index_;
    for (std::size_t i = 0; i < p_.size(); ++i) {
      if constexpr (kGravity)
        reverse_disk(p_.disk[i], now_, gx_, gy_);
      else
        reverse_disk(p_.disk[i], now_);
      ++p_.disk[i].counter;
      p_.disk[i].last_partner = -1;
    }
    if constexpr (kRough)
      for (T& w : p_.omega) w = -w;  // the reversed motion spins the other way
    ++counts_.by_kind[int(EventKind::Action)];
    if (!sinks_.empty()) emit({now_, EventKind::Action, false, -1, -1, T(0), T(0), T(0), T(0), T(0), T(0), T(0), T(0)});
    rebuild();
  }

  void emit(const EventOutcome<T>& outcome) {
    for (Sink<T>* s : sinks_) s->on_event(outcome, p_);
  }

  // --- bookkeeping --------------------------------------------------------------------------------
  T next_sample_time() const {
    if (!opt_.sample_interval) return kNever<T>;
    return T(double(next_sample_index_ + 1) * *opt_.sample_interval);
  }
  T next_action_time() const {
    if (next_action_index_ >= opt_.actions.size() || opt_.actions[next_action_index_].collisions_per_disk) return kNever<T>;
    return T(opt_.actions[next_action_index_].time);
  }

  // Actions and samples by collisions per disk (Scene::actions, Scene::sample_collisions): one happens
  // right after the pair collision that brings the pair count P to ceil(c N / 2) (c: its collisions per
  // disk; the k-th sample's c is k times the interval), at that collision's time, before the next event.
  // The loop compares P with next_pair_target_, the nearest such count (never: the largest integer), so a
  // scene without them pays one comparison per event.
  std::uint64_t pairs_for(double collisions_per_disk) const {
    return static_cast<std::uint64_t>(std::ceil(collisions_per_disk * double(p_.size()) / 2));
  }
  std::uint64_t pair_target() const {
    std::uint64_t target = std::numeric_limits<std::uint64_t>::max();
    if (next_action_index_ < opt_.actions.size())
      if (const auto& c = opt_.actions[next_action_index_].collisions_per_disk) target = pairs_for(*c);
    if (opt_.sample_collisions)
      target = std::min(target, pairs_for(double(next_sample_index_ + 1) * *opt_.sample_collisions));
    return target;
  }
  // Every action, then every sample, whose target the pair count has reached; the events it processed.
  std::uint64_t on_pair_target() {
    const std::uint64_t pairs = counts_.of(EventKind::Pair);
    std::uint64_t done = 0;
    while (next_action_index_ < opt_.actions.size() && opt_.actions[next_action_index_].collisions_per_disk &&
           pairs >= pairs_for(*opt_.actions[next_action_index_].collisions_per_disk))
      reverse_velocities(now_), ++done;
    while (opt_.sample_collisions && pairs >= pairs_for(double(next_sample_index_ + 1) * *opt_.sample_collisions))
      sample(now_), ++done;
    next_pair_target_ = pair_target();
    return done;
  }

  // An inelastic run that cools for ever (a wall restitution of 0.1 divides a speed by 10 per bounce)
  // reaches speeds whose squares leave T's normal range: below sqrt(min / epsilon) (~1e-146 in double,
  // ~3e-16 in float) the products of the contact-time formula lose digits or underflow to zero, pairs
  // approaching each other are no longer seen, and disks overlap (found by fuzz_engine: three disks
  // after 3000 events at speeds ~1e-192). The first disk to leave a collision that slow ends the run,
  // before anything goes wrong. Exact zero (a disk stopped dead by xi = 0) is fine: it is at rest.
  // Not under gravity: g renews the speeds and bounds the times between events, and a disk bouncing to
  // rest on the floor (speeds falling for ever in a finite time) is the stall detector's case, with its
  // message about resting contact and the TC model.
  void note_if_too_slow(std::int32_t i) {
    if constexpr (kGravity) return;
    const Disk<T>& d = p_.disk[i];
    const T speed = std::max(ede::abs(d.vx), ede::abs(d.vy));
    if (speed != T(0) && speed < kSlowestSpeed && too_slow_ < 0) too_slow_ = i;
  }
  // Above this share of the initial energy, a disk too slow to resolve means collapse, not rest (a gas
  // cooled to such speeds keeps ~1e-30 of its energy in float, ~1e-290 in double).
  static constexpr double kCollapseEnergyFraction = 1e-6;
  static inline const T kSlowestSpeed = ede::sqrt(scalar_limits<T>::min() / scalar_limits<T>::epsilon());

  // Inelastic collapse shows as ever more events at one and the same time; past the limit we stop.
  void note_time(T t) {
    if (t == now_) {
      if (++same_time_events_ > stall_limit_) stalled_ = true;
    } else {
      same_time_events_ = 0;
    }
  }

  RunStatus check_stops() {
    if (stalled_) {
      std::ostringstream m;
      m << "the simulation stalled at t = " << double(now_) << ": " << same_time_events_
        << " consecutive events without time advancing (inelastic collapse). ";
      if constexpr (kGravity)
        m << "Under gravity, disks settling on the floor or on each other bounce ever lower and ever faster: "
             "resting contact is not a state an event-driven run can reach. ";
      if (tc_model())
        m << "Increase physics.tc (now " << opt_.physics.tc << ")"
          << (kGravity ? " so that settled disks keep hopping elastically at a height of about g tc^2 / 8, and keep "
                         "wall_restitution above 0."
                       : ".");
      else
        m << "Enable the TC model (physics.tc > 0, e.g. 1e-3 of the mean free time) or raise the restitution.";
      stall_message_ = m.str();
      return RunStatus::Stalled;
    }
    if constexpr (kDissipative)
      if (too_slow_ >= 0) {
        const Disk<T>& slow = p_.disk[too_slow_];  // its velocity is the one it left the collision with
        const double left = kinetic_energy(p_) / ke0_;
        std::ostringstream m;
        m << "disk " << too_slow_ << " left a collision at t = " << double(now_) << " with speed "
          << double(std::max(ede::abs(slow.vx), ede::abs(slow.vy))) << ", below " << double(kSlowestSpeed)
          << ", the slowest speed whose square the scalar type holds to full precision";
        // A gas cooled to rest has (almost) no energy left; a disk this slow beside a sizeable energy is
        // one caught in a cluster colliding ever more often: inelastic collapse, not rest.
        if (left > kCollapseEnergyFraction) {
          m << ", while " << 100 * left
            << "% of the initial kinetic energy remains: inelastic collapse (disks in a cluster colliding ever "
               "faster and ever slower at one place). ";
          if (tc_model())
            m << "Increase physics.tc (now " << opt_.physics.tc << ").";
          else
            m << "Enable the TC model: physics.tc > 0, e.g. 1e-6, two orders of magnitude below the typical time "
                 "between a disk's collisions (docs/crater.md), or raise the restitution.";
          stall_message_ = m.str();
          return RunStatus::Collapsed;
        }
        m << ": the run has cooled to rest as far as it can tell (kinetic energy " << left
          << " of the initial), and contact times would no longer be exact. Stop earlier with "
             "stop.energy_fraction or stop.time.";
        stall_message_ = m.str();
        return RunStatus::CameToRest;
      }
    if (opt_.stop.events && counts_.events() >= *opt_.stop.events) return RunStatus::ReachedEvents;
    if (opt_.stop.collisions_per_particle && counts_.of(EventKind::Pair) >= pairs_to_stop_)
      return RunStatus::ReachedCollisions;
    if constexpr (kDissipative)
      if (opt_.stop.energy_fraction && ke_ <= *opt_.stop.energy_fraction * ke0_) return RunStatus::ReachedEnergy;
    return RunStatus::Running;
  }

  RunStatus finish(RunStatus s) {
    status_ = s;
    for (Sink<T>* sink : sinks_) sink->on_finish(now_, p_, s);
    return s;
  }

  // Restitution per pair of species (a table, with a fast path when every pair has the same) and per wall.
  void setup_restitution(const std::vector<std::string>& names, const PhysicsSpec& ph) {
    const std::size_t n = std::max<std::size_t>(names.size(), 1);
    species_count_ = n;
    pair_table_.assign(n * n, T(1) + T(ph.restitution));
    const auto index_of = [&](const std::string& name) {
      return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
    };
    for (const PairRestitution& pr : ph.pairs) {
      const std::size_t a = index_of(pr.a), b = index_of(pr.b);  // checked by check_engine_input
      pair_table_[a * n + b] = pair_table_[b * n + a] = T(1) + T(pr.value);
    }
    uniform_pairs_ = std::all_of(pair_table_.begin(), pair_table_.end(), [&](T v) { return v == pair_table_[0]; });
    one_plus_xi_ = pair_table_[0];
    for (int w = 0; w < 4; ++w) xi_wall_[w] = T(ph.wall(w));
  }

  T pair_one_plus_xi(std::int32_t i, std::int32_t j) const {
    if (uniform_pairs_) return one_plus_xi_;
    return pair_table_[std::size_t(p_.species_of(i)) * species_count_ + std::size_t(p_.species_of(j))];
  }

  double disk_energy(std::int32_t i) const {
    const double vx = double(p_.disk[i].vx), vy = double(p_.disk[i].vy);
    if constexpr (kRough) {
      const double w = double(p_.omega[i]);
      return 0.5 * double(p_.mass(i)) * (vx * vx + vy * vy) + 0.5 * double(p_.inertia[i]) * (w * w);
    }
    return 0.5 * double(p_.mass(i)) * (vx * vx + vy * vy);
  }

  // Rough disks: omega and I from the initial state, or omega = 0 and I = m r^2 / 2 (a uniform disk) where
  // it has none (a state built in code, or a start from a smooth run's log).
  void load_spins(const InitialState& init) {
    const std::size_t n = init.size();
    p_.omega.assign(n, T(0));
    p_.inertia.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      p_.inertia[i] = T(0.5) * p_.mass(i) * p_.disk[i].r * p_.disk[i].r;
      if (init.omega.size() == n) p_.omega[i] = T(init.omega[i]);
      if (init.inertia.size() == n) p_.inertia[i] = T(init.inertia[i]);
    }
  }

  // 1 + beta per pair of species (physics.roughness, physics.pairs[].roughness) and for the box walls.
  void setup_roughness(const std::vector<std::string>& names, const PhysicsSpec& ph) {
    const std::size_t n = std::max<std::size_t>(names.size(), 1);
    beta_table_.assign(n * n, T(1) + T(ph.roughness));
    const auto index_of = [&](const std::string& name) {
      return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
    };
    for (const PairRestitution& pr : ph.pairs) {
      const std::size_t a = index_of(pr.a), b = index_of(pr.b);
      beta_table_[a * n + b] = beta_table_[b * n + a] = T(1) + T(ph.pair_roughness(pr));
    }
    wall_one_plus_beta_ = T(1) + T(ph.wall_roughness);
  }

  T pair_one_plus_beta(std::int32_t i, std::int32_t j) const {
    if (beta_table_.size() == 1) return beta_table_[0];
    return beta_table_[std::size_t(p_.species_of(i)) * species_count_ + std::size_t(p_.species_of(j))];
  }
  double pair_energy(std::int32_t i, std::int32_t j) const { return disk_energy(i) + disk_energy(j); }

  EngineOptions opt_;
  Particles<T> p_;
  std::vector<Prediction> pred_;
  CellGrid<T> grid_;
  EventQueue<T> queue_;
  std::vector<Sink<T>*> sinks_;
  EventCounts counts_;

  T lx_ = 1, ly_ = 1, half_lx_ = 0.5, half_ly_ = 0.5;
  T one_plus_xi_ = 2, tc_ = 0;
  bool tc_model_ = false;  // Dissipative only: read through tc_model()
  T xi_wall_[4] = {1, 1, 1, 1};
  std::vector<T> pair_table_;  // 1 + xi for species (a, b) at a * species_count_ + b
  std::size_t species_count_ = 1;
  bool uniform_pairs_ = true;
  std::vector<T> beta_table_;       // rough only: 1 + beta for species (a, b) at a * species_count_ + b
  T wall_one_plus_beta_ = 0;        // rough only: 1 + beta_w of the box walls
  // The outward normal of each box wall (from a disk to the wall), by WallId.
  static constexpr T kWallNormal[4][2] = {{T(-1), T(0)}, {T(1), T(0)}, {T(0), T(-1)}, {T(0), T(1)}};
  T gx_ = 0, gy_ = 0;          // gravity (UniformGravity only)
  std::vector<BigDisk> big_;   // disks outside the cell lists (big_disks.hpp), by id
  std::vector<Segment<T>> seg_;  // wall segments (WithSegments only), in the scene's order
  SegmentCells seg_cells_;       // the segments each cell looks at
  T big_radius_ = kNever<T>;
  static constexpr const char* kWallName[4] = {"left", "right", "bottom", "top"};
  T b_noise2_ = 0;  // round-off floor of b, geometry.hpp
  bool prefetch_ahead_ = false;  // prefetch_upcoming() (EngineOptions::prefetch_upcoming_from)
  bool select_pairs_ = false;  // consider_pair without branches (kSelectPairs, EngineOptions)
  bool pair_times_vouchable_ = false;  // pair_time_exact_v2's conditions that hold for the whole run
  T now_ = 0;
  T stop_time_ = kNever<T>;
  double ke0_ = 0, ke_ = 0;
  std::uint64_t pairs_to_stop_ = 0;
  std::uint64_t next_pair_target_ = std::numeric_limits<std::uint64_t>::max();  // pair_target()
  std::uint64_t next_sample_index_ = 0;
  std::size_t next_action_index_ = 0;
  std::uint64_t same_time_events_ = 0, stall_limit_ = 0;
  bool stalled_ = false;
  std::int32_t too_slow_ = -1;  // the first disk to leave a collision too slow (note_if_too_slow), or -1
  bool started_ = false;
  bool resumed_ = false;
  RunStatus status_ = RunStatus::Running;
  std::string stall_message_;
};

}  // namespace ede
