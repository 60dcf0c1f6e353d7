// Coding a chunk of logged events as columns (schema/FORMAT.md, "Chunk columns"), and decoding it while
// applying it to a replayed state. Two column encodings, chosen by the header's columnEncoding:
//
// Encoding 1 (format version 1), per event in order:
//   times       varint: the first event's ordered key in full, then key deltas (times never decrease)
//   kinds       one byte (EventKind: pair 0, wall 1, wrap 3, action 4)
//   disks       varint i (pair, wall, wrap)
//   partners    varint: pair zigzag(j - i); wall the wall id; wrap the direction
//   raw         pair: v_i' x and y as raw scalars; the column is byte-plane shuffled
//   residuals   varint zigzag(key(v) - key(prediction)): pair v_j' against momentum conservation
//               (m_i v_i + m_j v_j - m_i v_i') / m_j; wall v' against a perfect reflection
// Encoding 2 (format version 2): every velocity and time coded against what replay predicts from the state
// just before the event (log/event_predictions.hpp), so an ordinary run's velocities cost ~0 and its times
// a byte or so:
//   kinds       one byte: the kind, plus kTcElasticFlag when the TC model made the collision elastic
//   disks, partners  as in encoding 1
//   times       varint: 2 zigzag(key(t) - key(predicted t)), or 2 (key(t) - key(previous t)) + 1 when that
//               is smaller or nothing is predicted (the previous key is 0 at a chunk's first event)
//   raw         empty
//   residuals   varint zigzag(key(v) - key(prediction)): pair v_i'x, v_i'y, v_j'x, v_j'y against the
//               collision rule; wall v'x, v'y against the wall's rule; segment v'x, v'y against the
//               segment's rule (and in encoding 1 against the velocity before the event)
// Rough runs (the state has omega) add one column, spins: varint zigzag(key(w) - key(prediction)) of
// pair w_i', w_j' and wall w' against the rough rule (FORMAT.md, "Rotation"); other runs have it empty.
// Segment events (kind 6) take the disk in `disks` and the segment's index in `partners`, like a wall.
// Both are lossless whatever the predictions' quality: a residual of 0 costs one byte, a bad prediction a
// few more. Rejected for encoding 2: keeping v_i' raw (60 % of a version 1 log) and the momentum
// prediction of v_j' (it is exact only when the rule's own v_j' happens to round the same way).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "log/byte_columns.hpp"
#include "log/id_lookahead.hpp"
#include "core/event.hpp"
#include "core/particles.hpp"
#include "ede/error.hpp"
#include "core/state_update.hpp"
#include "log/event_predictions.hpp"
#include "log/message_words.hpp"
#include "log/scalar_bytes.hpp"

namespace ede {

// The prediction of v_j' from momentum conservation, in one fixed order of operations.
template <class T>
inline T momentum_prediction(T mi, T mj, T vi0, T vj0, T vi1) {
  return ((mi * vi0 + mj * vj0) - mi * vi1) / mj;
}

// zigzag(key(actual) - key(predicted)). Keys of 64 bits or fewer (float, double) take the difference's
// magnitude in 64-bit arithmetic (it always fits) and zigzag it as 2|d| or 2|d| - 1: the same value as the
// 128-bit formula, a quarter of its instructions (it runs ~4 times per event in the log writer).
template <class T>
[[gnu::always_inline]] inline u128 residual(T actual, T predicted) {
  if constexpr (ScalarBytes<T>::kBits <= 64) {
    const std::uint64_t a = std::uint64_t(ordered_key(actual)), b = std::uint64_t(ordered_key(predicted));
    return a >= b ? u128(a - b) << 1 : (u128(b - a) << 1) - 1;
  } else {
    return zigzag(i128(ordered_key(actual)) - i128(ordered_key(predicted)));
  }
}

// Unsigned, wrapping arithmetic: a residual from a corrupted file may be any 128-bit value, and a signed
// overflow would be undefined behaviour; the (garbage) result is then refused as non-finite or checked
// like any other value. Valid data never wraps (keys and residuals fit in 81 bits).
template <class T>
inline T apply_residual(u128 r, T predicted) {
  return from_ordered_key<T>(ordered_key(predicted) + u128(unzigzag(r)));
}

// Kind byte of encoding 2: this collision was made elastic by the TC model (the rule uses 1 + xi = 2).
constexpr unsigned char kTcElasticFlag = 0x10;
constexpr std::uint32_t kLatestColumnEncoding = 2;
// A resumable keyframe's engineCounts: the event kinds there were before segments (pair .. sample), stale,
// tc_elastic, and then the segment events only in a run with segments (FORMAT.md, "Keyframe").
constexpr int kCountedKindsV2 = 6;

// The time a version 2 log predicts for an event from the state just before it (kNever: no prediction).
template <class T, class S>
inline T predicted_event_time(const EventPhysics<T>& ph, const S& s, EventKind kind, std::int32_t i, std::int32_t j) {
  switch (kind) {
    case EventKind::Pair: return predict_pair_time(ph, s, i, j);
    case EventKind::Wall: return predict_wall_time(ph, record_of(s, std::size_t(i)), j);
    case EventKind::Wrap: return predict_wrap_time(ph, record_of(s, std::size_t(i)), j);
    case EventKind::Segment: return predict_segment_time(ph, record_of(s, std::size_t(i)), j);
    default: return kNever<T>;
  }
}

// The raw columns of one chunk, as the encoder fills them and the schema stores them.
struct ChunkColumns {
  std::vector<unsigned char> times, kinds, disks, partners, raw, residuals;  // raw: already shuffled
  std::vector<unsigned char> spins;  // rough runs only
};

template <class T>
class ChunkEncoder {
 public:
  // Encoding 2 reads the physics (and `state` in add): the caller keeps them alive.
  ChunkEncoder(const std::vector<T>& mass, std::uint32_t encoding, const EventPhysics<T>& physics)
      : mass_(mass), encoding_(encoding), physics_(physics) {}

  void reset(std::uint64_t first_event) {
    first_event_ = first_event;
    count_ = 0;
    previous_key_ = 0;
    times_.clear(), kinds_.clear(), disks_.clear(), partners_.clear(), raw_.clear(), residuals_.clear();
    spins_.clear();
  }

  // `before`: the state just before the event, as replay has it (encoding 2 only): a Particles<T> or the
  // writer's CoderState<T>.
  template <class S>
  void add(const EventOutcome<T>& e, const S& before) {
    if (encoding_ == 1)
      add_v1(e);
    else
      add_v2(e, before);
    if (count_ == 0) time_first_ = e.time;
    time_last_ = e.time;
    ++count_;
  }

  std::uint32_t count() const { return count_; }
  std::uint64_t first_event() const { return first_event_; }
  T time_first() const { return time_first_; }
  T time_last() const { return time_last_; }

  ChunkColumns columns() const {
    return {times_.bytes(), kinds_.bytes(), disks_.bytes(), partners_.bytes(),
            shuffle_bytes(raw_.bytes(), kScalarWidth<T>), residuals_.bytes(), spins_.bytes()};
  }

 private:
  void add_v1(const EventOutcome<T>& e) {
    const u128 key = ordered_key(e.time);
    times_.varint(key - previous_key_);
    previous_key_ = key;
    kinds_.byte(static_cast<unsigned char>(e.kind));
    switch (e.kind) {
      case EventKind::Pair: add_pair_v1(e); break;
      case EventKind::Wall: add_wall_v1(e); break;
      case EventKind::Wrap: add_ids(e); break;
      case EventKind::Segment:
        add_ids(e);
        residuals_.varint(residual(e.vix, e.vix0));
        residuals_.varint(residual(e.viy, e.viy0));
        break;
      default: break;  // Action: the kind and time say it all
    }
  }

  template <class S>
  void add_v2(const EventOutcome<T>& e, const S& s) {
    const bool collision = e.kind == EventKind::Pair || e.kind == EventKind::Wall || e.kind == EventKind::Segment;
    bool tc = collision && e.tc_elastic;
    // An event that does not say (a converted version 1 log) gets the flag when only the elastic rule
    // predicts it exactly; in a run the engine's own flag is always the one that does.
    if (collision && !tc && physics_.tc_model && !rule_exact(e, s, false) && rule_exact(e, s, true)) tc = true;
    kinds_.byte(static_cast<unsigned char>(static_cast<unsigned char>(e.kind) | (tc ? kTcElasticFlag : 0)));
    if (e.kind == EventKind::Pair || e.kind == EventKind::Wall || e.kind == EventKind::Wrap ||
        e.kind == EventKind::Segment)
      add_ids(e);
    add_time_v2(e.time, predicted_event_time(physics_, s, e.kind, e.i, e.j));
    if (e.kind == EventKind::Pair) {
      T v[4], w[2] = {};  // w: rough runs only (GCC cannot see that the omega tests agree)
      predict_pair_velocities(physics_, s, e.i, e.j, e.time, tc, v, w);
      residuals_.varint(residual(e.vix, v[0]));
      residuals_.varint(residual(e.viy, v[1]));
      residuals_.varint(residual(e.vjx, v[2]));
      residuals_.varint(residual(e.vjy, v[3]));
      if (!s.omega.empty()) spins_.varint(residual(e.wi, w[0])), spins_.varint(residual(e.wj, w[1]));
    } else if (e.kind == EventKind::Wall) {
      T v[2], w[1] = {};
      predict_wall_velocity(physics_, s, e.i, e.j, e.time, tc, v, w);
      residuals_.varint(residual(e.vix, v[0]));
      residuals_.varint(residual(e.viy, v[1]));
      if (!s.omega.empty()) spins_.varint(residual(e.wi, w[0]));
    } else if (e.kind == EventKind::Segment) {
      T v[2];
      predict_segment_velocity(physics_, s, e.i, e.j, e.time, tc, v);
      residuals_.varint(residual(e.vix, v[0]));
      residuals_.varint(residual(e.viy, v[1]));
    }
  }

  template <class S>
  bool rule_exact(const EventOutcome<T>& e, const S& s, bool tc) const {
    T v[4];
    if (e.kind == EventKind::Pair) {
      predict_pair_velocities(physics_, s, e.i, e.j, e.time, tc, v);
      return same_bits(v[0], e.vix) && same_bits(v[1], e.viy) && same_bits(v[2], e.vjx) && same_bits(v[3], e.vjy);
    }
    if (e.kind == EventKind::Segment)
      predict_segment_velocity(physics_, s, e.i, e.j, e.time, tc, v);
    else
      predict_wall_velocity(physics_, s, e.i, e.j, e.time, tc, v);
    return same_bits(v[0], e.vix) && same_bits(v[1], e.viy);
  }
  static bool same_bits(T a, T b) { return ordered_key(a) == ordered_key(b); }

  // The smaller of the residual against the prediction (even code) and the delta to the previous event.
  void add_time_v2(T t, T predicted) {
    const u128 key = ordered_key(t);
    const u128 delta = key - previous_key_;
    previous_key_ = key;
    if (predicted != kNever<T> && predicted == predicted) {
      const u128 r = residual(t, predicted);
      if (r < delta) {
        times_.varint(r << 1);
        return;
      }
    }
    times_.varint((delta << 1) | 1);
  }

  void add_ids(const EventOutcome<T>& e) {
    disks_.varint(u128(e.i));
    if (e.kind == EventKind::Pair)
      partners_.varint(zigzag(i128(e.j) - i128(e.i)));
    else
      partners_.varint(u128(e.j));
  }

  void add_scalar(T v) {
    unsigned char b[kScalarWidth<T>];
    scalar_to_bytes(v, b);
    raw_.raw(b, sizeof b);
  }

  void add_pair_v1(const EventOutcome<T>& e) {
    add_ids(e);
    add_scalar(e.vix);
    add_scalar(e.viy);
    const T mi = mass_[std::size_t(e.i)], mj = mass_[std::size_t(e.j)];
    residuals_.varint(residual(e.vjx, momentum_prediction(mi, mj, e.vix0, e.vjx0, e.vix)));
    residuals_.varint(residual(e.vjy, momentum_prediction(mi, mj, e.viy0, e.vjy0, e.viy)));
  }

  void add_wall_v1(const EventOutcome<T>& e) {
    add_ids(e);
    const bool vertical = e.j == kWallLeft || e.j == kWallRight;
    residuals_.varint(residual(e.vix, vertical ? -e.vix0 : e.vix0));
    residuals_.varint(residual(e.viy, vertical ? e.viy0 : -e.viy0));
  }

  const std::vector<T>& mass_;
  std::uint32_t encoding_;
  const EventPhysics<T>& physics_;
  std::uint64_t first_event_ = 0;
  std::uint32_t count_ = 0;
  u128 previous_key_ = 0;
  T time_first_{}, time_last_{};
  ByteWriter times_, kinds_, disks_, partners_, raw_, residuals_, spins_;
};

// One decoded event, as tools list them.
template <class T>
struct DecodedEvent {
  std::uint64_t index = 0;
  T time{};
  EventKind kind{};
  std::int32_t i = -1, j = -1;
  T vix{}, viy{}, vjx{}, vjy{};
  bool tc_elastic = false;  // encoding 2: the kind byte's TC flag
  // Encoding 2 pairs: the positions of i and j at `time` (advance_disk), computed for the prediction and
  // reused by apply_event instead of advancing the records a second time (same function, same bits).
  bool advanced = false;
  T xi{}, yi{}, xj{}, yj{};
  T wi{}, wj{};  // rough logs, pair and wall: the spins after the event
};

// Decodes a chunk one event at a time against a replayed state: the next event's fields need the state
// just before it (the residuals are coded against its velocities), so decoding and applying alternate,
// and the decoder is a cursor that can stop after any event and go on later. It owns the decompressed
// message the columns point into. Every value is checked before it indexes anything: disk ids against N,
// kinds and wall/wrap codes against their lists, times against the previous event.
template <class T>
class ChunkDecoder {
 public:
  // kSpins: rough logs only (else empty); appended so the other columns keep their places.
  enum Column { kTimes = 0, kKinds, kDisks, kPartners, kRaw, kResiduals, kSpins, kColumnCount };

  // `physics`: encoding 2's predictions (copied: small).
  ChunkDecoder(MessageWords storage, const unsigned char* const* cols, const std::size_t* sizes,
               std::uint64_t first_event, std::uint32_t count, std::size_t disks, T last_time,
               std::uint32_t encoding, const EventPhysics<T>& physics);
  Status init();  // checks the raw column and unshuffles it

  bool done() const { return decoded_ == count_; }
  std::uint64_t next_index() const { return first_event_ + decoded_; }
  // Decodes the next event against `state` (which must hold the state just before it).
  Status next(const Particles<T>& state, DecodedEvent<T>& e);
  // The same without building a Status (replay's loop): false on an error, then error_message() says it.
  bool decode(const Particles<T>& state, DecodedEvent<T>& e);
  std::string error_message() const;
  // After the last event: every column consumed exactly.
  Status check_consumed() const;

 private:
  // The per-event readers are forced inline into decode (replay spends most of its time here; as calls
  // they cost ~15 % of it); the failure paths, which build messages, are kept out of line.
  [[gnu::cold, gnu::noinline]] bool fail(const std::string& what);
  [[gnu::cold, gnu::noinline]] bool fail_disk(u128 v);
  [[gnu::always_inline]] inline bool read_disk(ByteReader& r, std::int32_t& out);
  bool read_scalar(T& out);
  [[gnu::always_inline]] inline bool read_residual(T predicted, T& out);
  bool read_spin(T predicted, T& out);
  bool read_time(T& out);
  template <class Predict>
  [[gnu::always_inline]] inline bool read_time_v2(const Predict& predict, T& out);
  [[gnu::always_inline]] inline bool accept_time(u128 key, T& out);
  [[gnu::always_inline]] inline bool read_kind(DecodedEvent<T>& e);
  [[gnu::always_inline]] inline bool read_ids(DecodedEvent<T>& e);
  bool read_fields(const Particles<T>& state, DecodedEvent<T>& e);
  template <bool kGravity>
  [[gnu::always_inline]] inline bool read_v2(const Particles<T>& state, DecodedEvent<T>& e);

  MessageWords storage_;
  ByteReader times_, kinds_, disks_, partners_, residuals_, spins_;
  const unsigned char* raw_shuffled_;
  std::size_t raw_size_;
  std::vector<unsigned char> raw_;
  std::size_t raw_at_ = 0;
  std::uint64_t first_event_;
  std::uint32_t count_, decoded_ = 0;
  std::size_t disks_count_;
  T last_time_;
  u128 previous_key_ = 0;
  std::uint32_t encoding_;
  EventPhysics<T> physics_;
  bool gravity_;  // the header's gravity is not zero: decode takes the general pair path
  IdLookahead lookahead_;  // prefetches the records of the events ahead (large N only)
  std::string error_;
};

// The time of the last event of a chunk from its times column alone (times need no replayed state).
template <class T>
Result<T> last_time_of_column(const unsigned char* data, std::size_t size, std::uint32_t count) {
  ByteReader r(data, size);
  u128 key = 0;
  for (std::uint32_t k = 0; k < count; ++k) {
    u128 v;
    if (!r.varint(v, ScalarBytes<T>::kBits)) return Error{"the time column is cut short"};
    const u128 next = k == 0 ? v : key + v;
    if (next < key || (next >> ScalarBytes<T>::kBits) != 0) return Error{"an event time overflows"};
    key = next;
  }
  return from_ordered_key<T>(key);
}

// Applies a decoded event to a state with the shared state-update functions. Returns false if a record
// it touched is no longer finite: a log can only say so if it is corrupted (e.g. a huge but finite time).
template <class T>
inline bool finite_record(const Disk<T>& d) {
  return std::isfinite(double(d.x)) && std::isfinite(double(d.y)) && std::isfinite(double(d.t));
}

// The record of disk i to change: a reference into replay's Particles<T>; the writer's CoderState<T> has
// its own overload (log/coder_state.hpp), a copy written back when it goes out of scope.
template <class T>
[[gnu::always_inline]] inline Disk<T>& writable_record(Particles<T>& p, std::size_t i) {
  return p.disk[i];
}

template <class T, class S>
[[gnu::always_inline]] inline bool apply_event(const DecodedEvent<T>& e, S& p, T lx, T ly) {
  switch (e.kind) {
    case EventKind::Pair: {
      auto&& ra = writable_record(p, std::size_t(e.i));
      auto&& rb = writable_record(p, std::size_t(e.j));
      Disk<T>& a = ra;
      Disk<T>& b = rb;
      if (e.advanced) {
        a.x = e.xi, a.y = e.yi, a.t = e.time;
        b.x = e.xj, b.y = e.yj, b.t = e.time;
      } else {
        advance_disk(a, e.time, p.gx, p.gy);
        advance_disk(b, e.time, p.gx, p.gy);
      }
      a.vx = e.vix, a.vy = e.viy, b.vx = e.vjx, b.vy = e.vjy;
      if (!p.omega.empty()) p.omega[std::size_t(e.i)] = e.wi, p.omega[std::size_t(e.j)] = e.wj;
      return finite_record(a) && finite_record(b);
    }
    case EventKind::Wall:
    case EventKind::Segment: {
      auto&& ra = writable_record(p, std::size_t(e.i));
      Disk<T>& a = ra;
      advance_disk(a, e.time, p.gx, p.gy);
      a.vx = e.vix, a.vy = e.viy;
      if (!p.omega.empty() && e.kind == EventKind::Wall) p.omega[std::size_t(e.i)] = e.wi;
      return finite_record(a);
    }
    case EventKind::Wrap: {
      auto&& ra = writable_record(p, std::size_t(e.i));
      Disk<T>& a = ra;
      wrap_disk(a, e.time, e.j, lx, ly);
      return finite_record(a);
    }
    case EventKind::Action: {
      bool ok = true;
      for (std::size_t i = 0; i < p.size(); ++i) {
        auto&& r = writable_record(p, i);
        Disk<T>& d = r;
        reverse_disk(d, e.time, p.gx, p.gy);
        ok = ok && finite_record(d);
      }
      for (T& w : p.omega) w = -w;  // rough logs: Engine::reverse_velocities
      return ok;
    }
    default: return true;
  }
}


}  // namespace ede
