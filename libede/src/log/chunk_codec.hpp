// Coding a chunk of logged events as columns (schema/FORMAT.md, "Chunk columns"), and decoding it while
// applying it to a replayed state.
//
// Columns, per event in order:
//   times       varint: the first event's ordered key in full, then key deltas (times never decrease)
//   kinds       one byte (EventKind: pair 0, wall 1, wrap 3, action 4)
//   disks       varint i (pair, wall, wrap)
//   partners    varint: pair zigzag(j - i); wall the wall id; wrap the direction
//   raw         pair: v_i' x and y as raw scalars; the column is byte-plane shuffled
//   residuals   varint zigzag(key(v) - key(prediction)): pair v_j' against momentum conservation
//               (m_i v_i + m_j v_j - m_i v_i') / m_j; wall v' against a perfect reflection
// The predictions are plain arithmetic on values the reader already has (the pre-event velocities of its
// replayed state and the masses from the header), evaluated identically on both sides, so decoding is
// exact whatever the prediction's quality: a residual of 0 costs one byte, a bad prediction a few more.
// Rejected: storing all four velocities raw (~8 more bytes per pair event) and predicting v_i' with the
// collision rule itself (replay would then re-run the physics it exists to avoid).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "log/byte_columns.hpp"
#include "core/event.hpp"
#include "core/particles.hpp"
#include "ede/error.hpp"
#include "core/state_update.hpp"
#include "log/scalar_bytes.hpp"

namespace ede {

// The prediction of v_j' from momentum conservation, in one fixed order of operations.
template <class T>
inline T momentum_prediction(T mi, T mj, T vi0, T vj0, T vi1) {
  return ((mi * vi0 + mj * vj0) - mi * vi1) / mj;
}

template <class T>
inline u128 residual(T actual, T predicted) {
  return zigzag(i128(ordered_key(actual)) - i128(ordered_key(predicted)));
}

// Unsigned, wrapping arithmetic: a residual from a corrupted file may be any 128-bit value, and a signed
// overflow would be undefined behaviour; the (garbage) result is then refused as non-finite or checked
// like any other value. Valid data never wraps (keys and residuals fit in 81 bits).
template <class T>
inline T apply_residual(u128 r, T predicted) {
  return from_ordered_key<T>(ordered_key(predicted) + u128(unzigzag(r)));
}

// The raw columns of one chunk, as the encoder fills them and the schema stores them.
struct ChunkColumns {
  std::vector<unsigned char> times, kinds, disks, partners, raw, residuals;  // raw: already shuffled
};

template <class T>
class ChunkEncoder {
 public:
  explicit ChunkEncoder(const std::vector<T>& mass) : mass_(mass) {}

  void reset(std::uint64_t first_event) {
    first_event_ = first_event;
    count_ = 0;
    times_.clear(), kinds_.clear(), disks_.clear(), partners_.clear(), raw_.clear(), residuals_.clear();
  }

  void add(const EventOutcome<T>& e) {
    add_time(e.time);
    kinds_.byte(static_cast<unsigned char>(e.kind));
    switch (e.kind) {
      case EventKind::Pair: add_pair(e); break;
      case EventKind::Wall: add_wall(e); break;
      case EventKind::Wrap:
        disks_.varint(u128(e.i));
        partners_.varint(u128(e.j));
        break;
      default: break;  // Action: the kind and time say it all
    }
    ++count_;
  }

  std::uint32_t count() const { return count_; }
  std::uint64_t first_event() const { return first_event_; }
  T time_first() const { return time_first_; }
  T time_last() const { return time_last_; }

  ChunkColumns columns() const {
    return {times_.bytes(), kinds_.bytes(), disks_.bytes(), partners_.bytes(),
            shuffle_bytes(raw_.bytes(), kScalarWidth<T>), residuals_.bytes()};
  }

 private:
  void add_time(T t) {
    const u128 key = ordered_key(t);
    times_.varint(count_ == 0 ? key : key - previous_key_);
    previous_key_ = key;
    if (count_ == 0) time_first_ = t;
    time_last_ = t;
  }

  void add_scalar(T v) {
    unsigned char b[kScalarWidth<T>];
    scalar_to_bytes(v, b);
    raw_.raw(b, sizeof b);
  }

  void add_pair(const EventOutcome<T>& e) {
    disks_.varint(u128(e.i));
    partners_.varint(zigzag(i128(e.j) - i128(e.i)));
    add_scalar(e.vix);
    add_scalar(e.viy);
    const T mi = mass_[std::size_t(e.i)], mj = mass_[std::size_t(e.j)];
    residuals_.varint(residual(e.vjx, momentum_prediction(mi, mj, e.vix0, e.vjx0, e.vix)));
    residuals_.varint(residual(e.vjy, momentum_prediction(mi, mj, e.viy0, e.vjy0, e.viy)));
  }

  void add_wall(const EventOutcome<T>& e) {
    disks_.varint(u128(e.i));
    partners_.varint(u128(e.j));
    const bool vertical = e.j == kWallLeft || e.j == kWallRight;
    residuals_.varint(residual(e.vix, vertical ? -e.vix0 : e.vix0));
    residuals_.varint(residual(e.viy, vertical ? e.viy0 : -e.viy0));
  }

  const std::vector<T>& mass_;
  std::uint64_t first_event_ = 0;
  std::uint32_t count_ = 0;
  u128 previous_key_ = 0;
  T time_first_{}, time_last_{};
  ByteWriter times_, kinds_, disks_, partners_, raw_, residuals_;
};

// One decoded event, as tools list them.
template <class T>
struct DecodedEvent {
  std::uint64_t index = 0;
  T time{};
  EventKind kind{};
  std::int32_t i = -1, j = -1;
  T vix{}, viy{}, vjx{}, vjy{};
};

// Decodes a chunk one event at a time against a replayed state: the next event's fields need the state
// just before it (the residuals are coded against its velocities), so decoding and applying alternate,
// and the decoder is a cursor that can stop after any event and go on later. It owns the decompressed
// message the columns point into. Every value is checked before it indexes anything: disk ids against N,
// kinds and wall/wrap codes against their lists, times against the previous event.
template <class T>
class ChunkDecoder {
 public:
  enum Column { kTimes = 0, kKinds, kDisks, kPartners, kRaw, kResiduals, kColumnCount };

  ChunkDecoder(std::vector<std::uint64_t> storage, const unsigned char* const* cols, const std::size_t* sizes,
               std::uint64_t first_event, std::uint32_t count, std::size_t disks, T last_time);
  Status init();  // checks the raw column and unshuffles it

  bool done() const { return decoded_ == count_; }
  std::uint64_t next_index() const { return first_event_ + decoded_; }
  // Decodes the next event against `state` (which must hold the state just before it).
  Status next(const Particles<T>& state, DecodedEvent<T>& e);
  // After the last event: every column consumed exactly.
  Status check_consumed() const;

 private:
  bool fail(const std::string& what);
  bool read_disk(ByteReader& r, std::int32_t& out);
  bool read_scalar(T& out);
  bool read_residual(T predicted, T& out);
  bool read_time(T& out);
  bool read_fields(const Particles<T>& state, DecodedEvent<T>& e);

  std::vector<std::uint64_t> storage_;
  ByteReader times_, kinds_, disks_, partners_, residuals_;
  const unsigned char* raw_shuffled_;
  std::size_t raw_size_;
  std::vector<unsigned char> raw_;
  std::size_t raw_at_ = 0;
  std::uint64_t first_event_;
  std::uint32_t count_, decoded_ = 0;
  std::size_t disks_count_;
  T last_time_;
  u128 previous_key_ = 0;
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
bool apply_event(const DecodedEvent<T>& e, Particles<T>& state, T lx, T ly);

}  // namespace ede
