// ChunkDecoder and apply_event; see chunk_codec.hpp.
#include <cmath>

#include "log/chunk_codec.hpp"

namespace ede {

template <class T>
ChunkDecoder<T>::ChunkDecoder(MessageWords storage, const unsigned char* const* cols,
                              const std::size_t* sizes, std::uint64_t first_event, std::uint32_t count,
                              std::size_t disks, T last_time, std::uint32_t encoding,
                              const EventPhysics<T>& physics)
    : storage_(std::move(storage)),
      times_(cols[kTimes], sizes[kTimes]),
      kinds_(cols[kKinds], sizes[kKinds]),
      disks_(cols[kDisks], sizes[kDisks]),
      partners_(cols[kPartners], sizes[kPartners]),
      residuals_(cols[kResiduals], sizes[kResiduals]),
      spins_(cols[kSpins], sizes[kSpins]),
      raw_shuffled_(cols[kRaw]),
      raw_size_(sizes[kRaw]),
      first_event_(first_event),
      count_(count),
      disks_count_(disks),
      last_time_(last_time),
      encoding_(encoding),
      physics_(physics),
      gravity_(physics.gx != T(0) || physics.gy != T(0)),
      lookahead_(kinds_, disks_, partners_, count, disks, encoding >= 2 ? kTcElasticFlag : 0) {}

template <class T>
Status ChunkDecoder<T>::init() {
  if (!unshuffle_bytes(raw_shuffled_, raw_size_, kScalarWidth<T>, raw_))
    return Error{"chunk at event " + std::to_string(first_event_) +
                 ": the raw velocity column is not a whole number of scalars"};
  return Ok{};
}

template <class T>
bool ChunkDecoder<T>::fail(const std::string& what) {
  if (error_.empty()) error_ = what;
  return false;
}

template <class T>
bool ChunkDecoder<T>::read_disk(ByteReader& r, std::int32_t& out) {
  u128 v;
  if (!r.varint(v, 32)) return fail("a disk id is cut short");
  if (v >= disks_count_) return fail_disk(v);
  out = std::int32_t(v);
  return true;
}

template <class T>
bool ChunkDecoder<T>::fail_disk(u128 v) {
  return fail("disk id " + std::to_string(std::uint64_t(v)) + " out of range (N = " + std::to_string(disks_count_) + ")");
}

template <class T>
bool ChunkDecoder<T>::read_scalar(T& out) {
  if (raw_at_ + kScalarWidth<T> > raw_.size()) return fail("the raw velocity column is cut short");
  out = scalar_from_bytes<T>(raw_.data() + raw_at_);
  raw_at_ += kScalarWidth<T>;
  if (!std::isfinite(double(out))) return fail("a stored velocity is not finite");
  return true;
}

template <class T>
bool ChunkDecoder<T>::read_residual(T predicted, T& out) {
  if (residuals_.zero()) {  // the prediction was exact: apply_residual(0, predicted) is predicted itself
    out = predicted;
    if (!std::isfinite(double(out))) return fail("a decoded velocity is not finite");
    return true;
  }
  u128 r;
  if (!residuals_.varint(r)) return fail("the residual column is cut short");
  out = apply_residual(r, predicted);
  if (!std::isfinite(double(out))) return fail("a decoded velocity is not finite");
  return true;
}

// Rough logs: a spin after a pair or wall event, against the rough rule's prediction.
template <class T>
bool ChunkDecoder<T>::read_spin(T predicted, T& out) {
  u128 r;
  if (!spins_.varint(r)) return fail("the spin column is cut short");
  out = apply_residual(r, predicted);
  if (!std::isfinite(double(out))) return fail("a decoded angular velocity is not finite");
  return true;
}

template <class T>
bool ChunkDecoder<T>::accept_time(u128 key, T& out) {
  previous_key_ = key;
  out = from_ordered_key<T>(key);
  if (!std::isfinite(double(out))) return fail("an event time is not finite");
  if (out < last_time_) return fail("an event time goes back in time");
  last_time_ = out;
  return true;
}

template <class T>
bool ChunkDecoder<T>::read_time(T& out) {
  u128 v;
  if (!times_.varint(v, ScalarBytes<T>::kBits)) return fail("the time column is cut short");
  const u128 key = previous_key_ + v;  // the previous key is 0 before the chunk's first event
  if (key < previous_key_ || (key >> ScalarBytes<T>::kBits) != 0) return fail("an event time overflows");
  return accept_time(key, out);
}

// Encoding 2: an even code is a residual against the prediction, an odd one a delta to the previous time
// (the prediction is computed only for an even code).
template <class T>
template <class Predict>
bool ChunkDecoder<T>::read_time_v2(const Predict& predict, T& out) {
  u128 v;
  if (!times_.varint(v, ScalarBytes<T>::kBits + 2)) return fail("the time column is cut short");
  u128 key;
  if (v & 1) {
    key = previous_key_ + (v >> 1);
    if (key < previous_key_) return fail("an event time overflows");
  } else {
    const T predicted = predict();
    key = ordered_key(predicted) + u128(unzigzag(v >> 1));  // wraps harmlessly on corrupted input
  }
  if ((key >> ScalarBytes<T>::kBits) != 0) return fail("an event time overflows");
  return accept_time(key, out);
}

template <class T>
bool ChunkDecoder<T>::read_kind(DecodedEvent<T>& e) {
  unsigned char kind;
  if (!kinds_.byte(kind)) return fail("the kind column is cut short");
  const unsigned char flag = encoding_ >= 2 ? kTcElasticFlag : 0;
  e.tc_elastic = (kind & flag) != 0;
  const unsigned char k = static_cast<unsigned char>(kind & ~flag);
  e.kind = static_cast<EventKind>(k);
  const bool known = e.kind == EventKind::Pair || e.kind == EventKind::Wall || e.kind == EventKind::Wrap ||
                     e.kind == EventKind::Action || e.kind == EventKind::Segment ||
                     ((e.kind == EventKind::Step || e.kind == EventKind::Thermostat || e.kind == EventKind::Shear) &&
                      encoding_ >= 3);
  if (!known) return fail("unknown event kind " + std::to_string(kind));
  if (e.tc_elastic && e.kind != EventKind::Pair && e.kind != EventKind::Wall && e.kind != EventKind::Segment)
    return fail("a TC flag on an event that is not a collision");
  return true;
}

template <class T>
bool ChunkDecoder<T>::read_ids(DecodedEvent<T>& e) {
  switch (e.kind) {
    case EventKind::Pair:
    case EventKind::Step: {  // encoding 3: a step event names its pair as a collision does
      u128 zj;
      if (!read_disk(disks_, e.i)) return false;
      if (!partners_.varint(zj, 33)) return fail("a pair partner is cut short or out of range");  // zigzag of an int32 difference
      // zj < 2^33 (checked by the read), so 64-bit arithmetic is exact (i128 cost ~25 instructions per event).
      const std::uint64_t z = std::uint64_t(zj);
      const std::int64_t j = std::int64_t(e.i) + (std::int64_t(z >> 1) ^ -std::int64_t(z & 1));
      if (j < 0 || std::uint64_t(j) >= disks_count_ || j == e.i) return fail("a pair partner id is out of range");
      e.j = std::int32_t(j);
      return true;
    }
    case EventKind::Wall: {
      u128 wall;
      if (!read_disk(disks_, e.i)) return false;
      if (!partners_.varint(wall, 8) || wall > 3) return fail("a wall id is missing or out of range");
      e.j = std::int32_t(wall);
      return true;
    }
    case EventKind::Segment: {
      // Version 2 headers list the segments (FORMAT.md); a version 1 log's do not, so only the id's width
      // is checked there (decoding a version 1 segment event needs no geometry).
      u128 seg;
      if (!read_disk(disks_, e.i)) return false;
      const bool listed = encoding_ >= 2;
      if (!partners_.varint(seg, 32) || seg > u128(0x7fffffff) || (listed && seg >= physics_.segments.size()))
        return fail("a segment index is missing or out of range");
      e.j = std::int32_t(seg);
      return true;
    }
    case EventKind::Thermostat: return read_disk(disks_, e.i);
    case EventKind::Shear: {  // encoding 3: a crossing of the top (2) or bottom (3) edge
      u128 dir;
      if (!read_disk(disks_, e.i)) return false;
      if (!partners_.varint(dir, 8) || dir < 2 || dir > 3) return fail("a shear direction is missing or out of range");
      e.j = std::int32_t(dir);
      return true;
    }
    case EventKind::Wrap: {
      u128 dir;
      if (!read_disk(disks_, e.i)) return false;
      if (!partners_.varint(dir, 8) || dir > 3) return fail("a wrap direction is missing or out of range");
      e.j = std::int32_t(dir);
      return true;
    }
    default: return true;
  }
}

// A disk's velocity at time t from replay's record, by the format's state update.
template <class T>
T vx_at(const Particles<T>& p, std::int32_t i, T t) {
  const Disk<T>& d = p.disk[std::size_t(i)];
  return rules::velocity_along(d.vx, p.gx, d.t, t);
}
template <class T>
T vy_at(const Particles<T>& p, std::int32_t i, T t) {
  const Disk<T>& d = p.disk[std::size_t(i)];
  return rules::velocity_along(d.vy, p.gy, d.t, t);
}

// Encoding 1: the time came first; then ids and velocities.
template <class T>
bool ChunkDecoder<T>::read_fields(const Particles<T>& p, DecodedEvent<T>& e) {
  if (!read_kind(e) || !read_ids(e)) return false;
  switch (e.kind) {
    case EventKind::Pair: {
      // Velocities just before the event: the records' own, moved on by gravity if there is any.
      const T aix = vx_at(p, e.i, e.time), aiy = vy_at(p, e.i, e.time);
      const T ajx = vx_at(p, e.j, e.time), ajy = vy_at(p, e.j, e.time);
      const T mi = p.mass(std::size_t(e.i)), mj = p.mass(std::size_t(e.j));
      if (!read_scalar(e.vix) || !read_scalar(e.viy)) return false;
      return read_residual(rules::v1::momentum_prediction(mi, mj, aix, ajx, e.vix), e.vjx) &&
             read_residual(rules::v1::momentum_prediction(mi, mj, aiy, ajy, e.viy), e.vjy);
    }
    case EventKind::Wall: {
      const T ax = vx_at(p, e.i, e.time), ay = vy_at(p, e.i, e.time);
      const bool vertical = e.j == rules::kLeft || e.j == rules::kRight;
      return read_residual(vertical ? -ax : ax, e.vix) && read_residual(vertical ? ay : -ay, e.viy);
    }
    case EventKind::Segment: {
      const T ax = vx_at(p, e.i, e.time), ay = vy_at(p, e.i, e.time);
      return read_residual(ax, e.vix) && read_residual(ay, e.viy);
    }
    default: return true;
  }
}

// What the velocity predictors read of disk i in replay's state.
template <class T>
DiskTraits<T> traits_of(const Particles<T>& p, std::size_t i) {
  DiskTraits<T> c;
  c.mass = p.mass(i);
  c.species = p.species_of(i);
  if (!p.omega.empty()) c.omega = p.omega[i], c.inertia = p.inertia[i];
  return c;
}

// Encoding 2: kind and ids, then the time against its prediction, then the velocities against theirs.
// Pairs (nearly every event) take a path compiled for the header's gravity (kGravity = false: the gravity
// branches of the predictor and of bring_to fold away; the same bits, since with g = 0 they are drift).
template <class T>
template <bool kGravity>
bool ChunkDecoder<T>::read_v2(const Particles<T>& p, DecodedEvent<T>& e) {
  if (!read_kind(e) || !read_ids(e)) return false;
  const bool rough = !p.omega.empty();
  if (e.kind == EventKind::Pair) {
    const Disk<T>& ri = p.disk[std::size_t(e.i)];
    const Disk<T>& rj = p.disk[std::size_t(e.j)];
    if (!read_time_v2([&] { return predict_pair_time<T, kGravity>(physics_, ri, rj); }, e.time)) return false;
    const T gx = kGravity ? physics_.gx : T(0), gy = kGravity ? physics_.gy : T(0);
    RecordBefore<T> a = record_before(ri), b = record_before(rj);
    rules::bring_to(a, e.time, gx, gy);
    rules::bring_to(b, e.time, gx, gy);
    e.advanced = true;
    e.xi = a.x, e.yi = a.y, e.xj = b.x, e.yj = b.y;
    T v[4], w[2] = {};  // w: rough runs only
    predict_pair_velocities(physics_, a, b, traits_of(p, std::size_t(e.i)), traits_of(p, std::size_t(e.j)), rough,
                            e.tc_elastic, v, w);
    return read_residual(v[0], e.vix) && read_residual(v[1], e.viy) && read_residual(v[2], e.vjx) &&
           read_residual(v[3], e.vjy) && (!rough || (read_spin(w[0], e.wi) && read_spin(w[1], e.wj)));
  }
  if (e.kind == EventKind::Step) {  // encoding 3: no predictions yet (FORMAT.md, "Step events")
    if (!read_time_v2([] { return rules::v2::kNever<T>; }, e.time)) return false;
    return read_residual(vx_at(p, e.i, e.time), e.vix) && read_residual(vy_at(p, e.i, e.time), e.viy) &&
           read_residual(vx_at(p, e.j, e.time), e.vjx) && read_residual(vy_at(p, e.j, e.time), e.vjy);
  }
  const Disk<T>* d = e.i >= 0 ? &p.disk[std::size_t(e.i)] : nullptr;
  if (!read_time_v2([&] { return d ? predicted_event_time(physics_, e.kind, *d, *d, e.j) : rules::v2::kNever<T>; },
                    e.time))
    return false;
  if (e.kind == EventKind::Wall) {
    T v[2], w[2] = {};
    predict_wall_velocity(physics_, *d, e.time, e.j, traits_of(p, std::size_t(e.i)), rough, e.tc_elastic, v, w);
    return read_residual(v[0], e.vix) && read_residual(v[1], e.viy) && (!rough || read_spin(w[0], e.wi));
  }
  if (e.kind == EventKind::Segment) {
    T v[2];
    predict_segment_velocity(physics_, *d, e.time, e.j, e.tc_elastic, v);
    return read_residual(v[0], e.vix) && read_residual(v[1], e.viy);
  }
  if (e.kind == EventKind::Thermostat) return read_scalar(e.vix) && read_scalar(e.viy);
  if (e.kind == EventKind::Shear) {  // the new x (in xi) and vx as they are; vy unchanged
    e.viy = vy_at(p, e.i, e.time);
    return read_scalar(e.xi) && read_scalar(e.vix);
  }
  return true;
}

template <class T>
bool ChunkDecoder<T>::decode(const Particles<T>& state, DecodedEvent<T>& e) {
  if (done()) return fail("the chunk has no more events");
  lookahead_.before(decoded_, state);
  e.index = first_event_ + decoded_;
  e.tc_elastic = false;
  e.advanced = false;
  e.i = e.j = -1;
  e.vix = e.viy = e.vjx = e.vjy = T(0);  // a wall, wrap or action event leaves some of them unset
  e.wi = e.wj = T(0);
  const bool ok = encoding_ < 2 ? read_time(e.time) && read_fields(state, e)
                  : gravity_  ? read_v2<true>(state, e)
                              : read_v2<false>(state, e);
  if (!ok) return false;
  ++decoded_;
  return true;
}

template <class T>
std::string ChunkDecoder<T>::error_message() const {
  return "event " + std::to_string(first_event_ + decoded_) + ": " + error_;
}

template <class T>
Status ChunkDecoder<T>::next(const Particles<T>& state, DecodedEvent<T>& e) {
  e = DecodedEvent<T>{};
  if (!decode(state, e)) return Error{error_message()};
  return Ok{};
}

template <class T>
Status ChunkDecoder<T>::check_consumed() const {
  if (!times_.at_end() || !kinds_.at_end() || !disks_.at_end() || !partners_.at_end() || !residuals_.at_end() || !spins_.at_end() ||
      raw_at_ != raw_.size())
    return Error{"chunk at event " + std::to_string(first_event_) + ": its columns hold more data than its " +
                 std::to_string(count_) + " events"};
  return Ok{};
}

template class ChunkDecoder<float>;
template class ChunkDecoder<double>;
template class ChunkDecoder<long double>;

}  // namespace ede
