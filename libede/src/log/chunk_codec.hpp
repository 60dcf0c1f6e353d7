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
// just before the event (log/event_predictions.hpp, over the format's own arithmetic in log/rules/), so an
// ordinary run's velocities cost ~0 and its times a byte or so; the encoder reads that state from the
// records each event carries (log/logged_event.hpp), the decoder from the state it replays:
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
// Encoding 3 (format version 3) is encoding 2 plus step events (kind 7: a pair at a step of a stepped
// potential): ids as a pair's, the time coded as an unpredicted one (odd code), residuals of v_i'x, v_i'y,
// v_j'x, v_j'y against the velocities before the event (EventCoder sets them as the predictions).
// Both are lossless whatever the predictions' quality: a residual of 0 costs one byte, a bad prediction a
// few more. Rejected for encoding 2: keeping v_i' raw (60 % of a version 1 log) and the momentum
// prediction of v_j' (it is exact only when the rule's own v_j' happens to round the same way).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/event.hpp"
#include "core/particles.hpp"
#include "ede/error.hpp"
#include "log/byte_columns.hpp"
#include "log/event_predictions.hpp"
#include "log/id_lookahead.hpp"
#include "log/logged_event.hpp"
#include "log/message_words.hpp"
#include "log/rules/predictions_v1.hpp"
#include "log/rules/state_update.hpp"
#include "log/scalar_bytes.hpp"

namespace ede {

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
constexpr std::uint32_t kLatestColumnEncoding = 3;
// Events whose ids are a pair (i, then zigzag(j - i)) and which carry both disks' velocities.
[[gnu::always_inline]] inline bool pair_like(EventKind k) { return k == EventKind::Pair || k == EventKind::Step; }
// A resumable keyframe's engineCounts: the event kinds there were before segments (pair .. sample), stale,
// tc_elastic, and then the segment events only in a run with segments (FORMAT.md, "Keyframe"); in version 3
// always the segment and step events (kinds 6, 7), then the thermostat's (kind 8) in a run with it.
constexpr int kCountedKindsV2 = 6;

// Bytes of one column, where the encoder keeps them (valid until its next reset or add).
struct ColumnView {
  const unsigned char* data = nullptr;
  std::size_t size = 0;
};

// The raw columns of one chunk, as the encoder filled them and the schema stores them: views into the
// encoder's buffers, copied once, into the record's message (a copy into vectors first was ~4 % of the
// worker's instructions).
struct ChunkColumns {
  ColumnView times, kinds, disks, partners, raw, residuals;  // raw: already shuffled
  ColumnView spins;  // rough runs only
};

// Codes events into columns. The predictions are made before (log/event_coder.hpp): the encoder only turns
// each value and its prediction into a residual, a varint in its column.
template <class T>
class ChunkEncoder {
 public:
  // `rough`: a rough run's version 2 chunks carry the spin column.
  ChunkEncoder(std::uint32_t encoding, bool rough) : encoding_(encoding), rough_(rough) {}

  void reset(std::uint64_t first_event) {
    first_event_ = first_event;
    count_ = 0;
    previous_key_ = 0;
    times_.clear(), kinds_.clear(), disks_.clear(), partners_.clear(), raw_.clear(), residuals_.clear();
    spins_.clear();
  }

  // Every event of a chunk, in order: version 2 through a loop that keeps each column's write position in a
  // local (add_all_v2), the same bytes as add() event by event.
  void add_all(const ChunkEvents<T>& events) {
    if (events.empty()) return;
    if (encoding_ == 1) return events.for_each([&](const CodedEvent<T>& e) { add(e); });
    add_all_v2(events);
    if (count_ == 0) time_first_ = events.time_first();
    time_last_ = events.time_last();
    count_ += std::uint32_t(events.size());
  }

  void add(const CodedEvent<T>& e) {
    if (encoding_ == 1)
      add_v1(e);
    else
      add_v2(e);
    if (count_ == 0) time_first_ = e.time;
    time_last_ = e.time;
    ++count_;
  }

  std::uint32_t count() const { return count_; }
  std::uint64_t first_event() const { return first_event_; }
  T time_first() const { return time_first_; }
  T time_last() const { return time_last_; }

  // The columns as views into this encoder (the raw column shuffled into a buffer of its own: version 1).
  ChunkColumns columns() {
    raw_shuffled_ = shuffle_bytes(raw_.bytes(), kScalarWidth<T>);
    const auto view = [](const ByteWriter& w) { return ColumnView{w.data(), w.size()}; };
    return {view(times_), view(kinds_), view(disks_), view(partners_), {raw_shuffled_.data(), raw_shuffled_.size()},
            view(residuals_), view(spins_)};
  }

 private:
  // Version 1: v = the velocities after the event, pv = before it.
  void add_v1(const CodedEvent<T>& e) {
    const u128 key = ordered_key(e.time);
    times_.varint(key - previous_key_);
    previous_key_ = key;
    kinds_.byte(static_cast<unsigned char>(e.kind));
    switch (e.kind) {
      case EventKind::Pair:
        add_ids(e);
        add_scalar(e.v[0]);
        add_scalar(e.v[1]);
        residuals_.varint(residual(e.v[2], rules::v1::momentum_prediction(e.mi, e.mj, e.pv[0], e.pv[2], e.v[0])));
        residuals_.varint(residual(e.v[3], rules::v1::momentum_prediction(e.mi, e.mj, e.pv[1], e.pv[3], e.v[1])));
        break;
      case EventKind::Wall: {
        add_ids(e);
        const bool vertical = e.j == rules::kLeft || e.j == rules::kRight;
        residuals_.varint(residual(e.v[0], vertical ? -e.pv[0] : e.pv[0]));
        residuals_.varint(residual(e.v[1], vertical ? e.pv[1] : -e.pv[1]));
        break;
      }
      case EventKind::Wrap: add_ids(e); break;
      case EventKind::Segment:
        add_ids(e);
        residuals_.varint(residual(e.v[0], e.pv[0]));
        residuals_.varint(residual(e.v[1], e.pv[1]));
        break;
      default: break;  // Action: the kind and time say it all
    }
  }

  void add_v2(const CodedEvent<T>& e) {
    kinds_.byte(static_cast<unsigned char>(static_cast<unsigned char>(e.kind) | (e.tc_elastic ? kTcElasticFlag : 0)));
    if (pair_like(e.kind) || e.kind == EventKind::Wall || e.kind == EventKind::Wrap ||
        e.kind == EventKind::Segment || e.kind == EventKind::Shear)
      add_ids(e);
    if (e.kind == EventKind::Thermostat) add_redrawn(e);
    if (e.kind == EventKind::Shear) add_scalar(e.v[0]), add_scalar(e.v[1]);  // x', vx' (FORMAT.md)
    add_time_v2(e.time, e.predicted_time);
    const int velocities = pair_like(e.kind) ? 4 : e.kind == EventKind::Wall || e.kind == EventKind::Segment ? 2 : 0;
    const int spins = !rough_ ? 0 : e.kind == EventKind::Pair ? 2 : e.kind == EventKind::Wall ? 1 : 0;
    if (e.velocities_predicted) {  // every residual 0: one byte each
      residuals_.zeros(std::size_t(velocities));
      if (spins) spins_.zeros(std::size_t(spins));
      return;
    }
    for (int k = 0; k < velocities; ++k) residuals_.varint(residual(e.v[k], e.pv[k]));
    for (int k = 0; k < spins; ++k) spins_.varint(residual(e.w[k], e.pw[k]));
  }

  // add_v2 for a whole chunk. Per event at most: a kind byte, 5 bytes of disk id, 5 of partner, a 19-byte
  // time code, 4 residuals and 2 spins of 19 bytes each; room for that is made once, before the loop.
  void add_all_v2(const ChunkEvents<T>& events) {
    const std::size_t n = events.size();
    unsigned char* kinds = kinds_.begin_write(n);
    unsigned char* disks = disks_.begin_write(5 * n);
    unsigned char* partners = partners_.begin_write(5 * n);
    unsigned char* times = times_.begin_write(19 * n);
    unsigned char* residuals = residuals_.begin_write(4 * 19 * n);
    unsigned char* spins = spins_.begin_write(rough_ ? 2 * 19 * n : 0);
    u128 previous = previous_key_;
    events.for_each([&](const CodedEvent<T>& e) __attribute__((always_inline)) {
      *kinds++ = static_cast<unsigned char>(static_cast<unsigned char>(e.kind) | (e.tc_elastic ? kTcElasticFlag : 0));
      // A pair first and with one comparison, as before steps existed: steps (encoding 3) come last.
      if (e.kind == EventKind::Pair) {
        disks = put_varint(disks, std::uint64_t(std::uint32_t(e.i)));
        const std::int64_t d = std::int64_t(e.j) - std::int64_t(e.i);
        partners = put_varint(partners, (std::uint64_t(d) << 1) ^ std::uint64_t(d >> 63));
      } else if (e.kind == EventKind::Wall || e.kind == EventKind::Wrap || e.kind == EventKind::Segment) {
        disks = put_varint(disks, std::uint64_t(std::uint32_t(e.i)));
        partners = put_varint(partners, std::uint64_t(std::uint32_t(e.j)));
      } else if (e.kind == EventKind::Thermostat) {
        disks = put_varint(disks, std::uint64_t(std::uint32_t(e.i)));
        add_scalar(e.v[0]);
        add_scalar(e.v[1]);
      } else if (e.kind == EventKind::Step) {
        disks = put_varint(disks, std::uint64_t(std::uint32_t(e.i)));
        const std::int64_t d = std::int64_t(e.j) - std::int64_t(e.i);
        partners = put_varint(partners, (std::uint64_t(d) << 1) ^ std::uint64_t(d >> 63));
      } else if (e.kind == EventKind::Shear) {  // as a wrap, then x' and vx' as they are
        disks = put_varint(disks, std::uint64_t(std::uint32_t(e.i)));
        partners = put_varint(partners, std::uint64_t(std::uint32_t(e.j)));
        add_scalar(e.v[0]);
        add_scalar(e.v[1]);
      }
      times = put_varint(times, time_code(e.time, e.predicted_time, previous));
      const int velocities = e.kind == EventKind::Pair                                   ? 4
                             : e.kind == EventKind::Wall || e.kind == EventKind::Segment ? 2
                             : e.kind == EventKind::Step                                 ? 4
                                                                                         : 0;
      const int spun = !rough_ ? 0 : e.kind == EventKind::Pair ? 2 : e.kind == EventKind::Wall ? 1 : 0;
      if (e.velocities_predicted) {  // every residual 0: one byte each
        for (int k = 0; k < velocities; ++k) *residuals++ = 0;
        for (int k = 0; k < spun; ++k) *spins++ = 0;
        return;
      }
      for (int k = 0; k < velocities; ++k) residuals = put_varint(residuals, residual(e.v[k], e.pv[k]));
      for (int k = 0; k < spun; ++k) spins = put_varint(spins, residual(e.w[k], e.pw[k]));
    });
    previous_key_ = previous;
    kinds_.end_write(kinds), disks_.end_write(disks), partners_.end_write(partners);
    times_.end_write(times), residuals_.end_write(residuals);
    if (rough_) spins_.end_write(spins);
  }

  // The time's code: 2 zigzag(key(t) - key(predicted)) when a prediction exists and that is smaller than the
  // delta to the previous event's key, else 2 delta + 1; `previous` becomes t's key.
  [[gnu::always_inline]] static u128 time_code(T t, T predicted, u128& previous) {
    const u128 key = ordered_key(t);
    const u128 delta = key - previous;
    previous = key;
    if (ordered_key(predicted) == key) return delta != 0 ? 0 : 1;  // the common case: an exact prediction
    if (predicted != rules::v2::kNever<T> && predicted == predicted) {
      const u128 r = residual(t, predicted);
      if (r < delta) return r << 1;
    }
    return (delta << 1) | 1;
  }

  // The smaller of the residual against the prediction (even code) and the delta to the previous event.
  void add_time_v2(T t, T predicted) {
    const u128 key = ordered_key(t);
    const u128 delta = key - previous_key_;
    previous_key_ = key;
    if (predicted != rules::v2::kNever<T> && predicted == predicted) {
      const u128 r = residual(t, predicted);
      if (r < delta) {
        times_.varint(r << 1);
        return;
      }
    }
    times_.varint((delta << 1) | 1);
  }

  void add_ids(const CodedEvent<T>& e) {
    disks_.varint(u128(e.i));
    if (pair_like(e.kind))
      partners_.varint(zigzag(i128(e.j) - i128(e.i)));
    else
      partners_.varint(u128(e.j));
  }

  // Version 3, a thermostat event: the disk, and its new velocity as raw scalars (random: nothing predicts it).
  void add_redrawn(const CodedEvent<T>& e) {
    disks_.varint(u128(e.i));
    add_scalar(e.v[0]);
    add_scalar(e.v[1]);
  }

  void add_scalar(T v) {
    unsigned char b[kScalarWidth<T>];
    scalar_to_bytes(v, b);
    raw_.raw(b, sizeof b);
  }

  std::uint32_t encoding_;
  bool rough_;
  std::uint64_t first_event_ = 0;
  std::uint32_t count_ = 0;
  u128 previous_key_ = 0;
  T time_first_{}, time_last_{};
  ByteWriter times_, kinds_, disks_, partners_, raw_, residuals_, spins_;
  std::vector<unsigned char> raw_shuffled_;
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
  // Encoding 2 pairs: the positions of i and j at `time` (rules::bring_to), computed for the prediction and
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

// Applies a decoded event to replay's state with the format's state update (log/rules/state_update.hpp).
template <class T>
[[gnu::always_inline]] inline bool apply_event(const DecodedEvent<T>& e, Particles<T>& p, T lx, T ly) {
  switch (e.kind) {
    case EventKind::Pair:
    case EventKind::Step: {
      Disk<T>& a = p.disk[std::size_t(e.i)];
      Disk<T>& b = p.disk[std::size_t(e.j)];
      if (e.advanced) {
        a.x = e.xi, a.y = e.yi, a.t = e.time;
        b.x = e.xj, b.y = e.yj, b.t = e.time;
      } else {
        rules::bring_to(a, e.time, p.gx, p.gy);
        rules::bring_to(b, e.time, p.gx, p.gy);
      }
      a.vx = e.vix, a.vy = e.viy, b.vx = e.vjx, b.vy = e.vjy;
      if (!p.omega.empty()) p.omega[std::size_t(e.i)] = e.wi, p.omega[std::size_t(e.j)] = e.wj;
      return finite_record(a) && finite_record(b);
    }
    case EventKind::Wall:
    case EventKind::Segment:
    case EventKind::Thermostat: {
      Disk<T>& a = p.disk[std::size_t(e.i)];
      rules::bring_to(a, e.time, p.gx, p.gy);
      a.vx = e.vix, a.vy = e.viy;
      if (!p.omega.empty() && e.kind == EventKind::Wall) p.omega[std::size_t(e.i)] = e.wi;
      return finite_record(a);
    }
    case EventKind::Wrap: {
      Disk<T>& a = p.disk[std::size_t(e.i)];
      rules::wrap(a, e.time, e.j, lx, ly);
      return finite_record(a);
    }
    case EventKind::Shear: {  // a wrap through the top or bottom, then the stored x and vx (FORMAT.md)
      Disk<T>& a = p.disk[std::size_t(e.i)];
      rules::wrap(a, e.time, e.j, lx, ly);
      a.x = e.xi, a.vx = e.vix;
      return finite_record(a) && std::isfinite(double(a.vx));
    }
    case EventKind::Action: {
      bool ok = true;
      for (Disk<T>& d : p.disk) {
        rules::reverse(d, e.time, p.gx, p.gy);
        ok = ok && finite_record(d);
      }
      for (T& w : p.omega) w = -w;  // rough logs: Engine::reverse_velocities
      return ok;
    }
    default: return true;
  }
}

}  // namespace ede
