// Replay<T>; see replay.hpp. The state moves forward only by applying logged events with the shared
// state-update functions; moving backward reloads a keyframe. A chunk is decoded through a cursor that
// can stop after any event (decoding needs the state just before each event), and the next event, once
// decoded, waits in `pending_` until a later seek applies it.
#include "replay/replay.hpp"

#include <capnp/serialize.h>
#include <kj/exception.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "ede/number_text.hpp"
#include "log/run_id.hpp"
#include "log/chunk_codec.hpp"
#include "ede_log.capnp.h"
#include "log/log_messages.hpp"
#include "log/scalar_bytes.hpp"

namespace ede {

namespace {

template <class T>
constexpr ScalarKind scalar_kind() {
  if constexpr (std::is_same_v<T, float>) return ScalarKind::Float;
  if constexpr (std::is_same_v<T, double>) return ScalarKind::Double;
  return ScalarKind::LongDouble;
}

// A shuffled per-disk scalar column into a vector of T; false if its size is wrong or a value not finite.
template <class T>
bool read_column(const unsigned char* data, std::size_t size, std::size_t n, std::vector<T>& out) {
  std::vector<unsigned char> raw;
  if (size != n * kScalarWidth<T> || !unshuffle_bytes(data, size, kScalarWidth<T>, raw)) return false;
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = scalar_from_bytes<T>(raw.data() + i * kScalarWidth<T>);
    if (!std::isfinite(double(out[i]))) return false;
  }
  return true;
}

// n plain (unshuffled) scalars, each finite.
template <class T>
bool read_raw_scalars(const std::vector<unsigned char>& bytes, std::size_t n, std::vector<T>& out) {
  if (bytes.size() != n * kScalarWidth<T>) return false;
  out.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    out[k] = scalar_from_bytes<T>(bytes.data() + k * kScalarWidth<T>);
    if (!std::isfinite(double(out[k]))) return false;
  }
  return true;
}

template <class T>
bool read_column(capnp::Data::Reader d, std::size_t n, std::vector<T>& out) {
  return read_column(d.begin(), d.size(), n, out);
}

// The decoded content of a keyframe record.
template <class T>
struct KeyframeData {
  std::uint64_t events_before = 0;
  T time{};
  bool resumable = false;
  std::vector<T> x, y, vx, vy, t, last_collision;
  std::vector<T> omega;  // rough logs
  std::vector<std::int32_t> last_partner;
  std::vector<std::uint64_t> counts;
  std::uint64_t next_sample = 0, next_action = 0, same_time_events = 0;
};

template <class T>
Result<KeyframeData<T>> read_keyframe(const LogReader& log, const LogRecordRef& ref) {
  auto words = log.load_message(ref.offset, ref.payload_size);
  if (!words) return words.error();
  const std::size_t n = log.header().disks;
  const std::string where = log.path() + " (keyframe at byte " + std::to_string(ref.offset) + ")";
  KeyframeData<T> k;
  try {
    capnp::FlatArrayMessageReader message(as_words(words.value()), reader_options(words.value()));
    const auto kf = message.getRoot<logschema::Keyframe>();
    if (Status s = check_run_id(log, kf.getRunId(), ref.offset, "keyframe"); !s) return s.error();
    k.events_before = kf.getEventsBefore();
    const auto time = kf.getTime();
    if (time.size() != kScalarWidth<T>) return Error{where + ": malformed time"};
    k.time = scalar_from_bytes<T>(time.begin());
    k.resumable = kf.getResumable();
    if (!read_column(kf.getX(), n, k.x) || !read_column(kf.getY(), n, k.y) || !read_column(kf.getVx(), n, k.vx) ||
        !read_column(kf.getVy(), n, k.vy) || !read_column(kf.getT(), n, k.t) || !std::isfinite(double(k.time)))
      return Error{where + ": a state column is malformed or holds a non-finite number"};
    if (log.header().rotation() && !read_column(kf.getOmega(), n, k.omega))
      return Error{where + ": the angular velocity column is malformed or holds a non-finite number"};
    if (k.resumable) {
      for (const std::int32_t p : kf.getLastPartner()) {
        if (p < -1 || p >= std::int32_t(n)) return Error{where + ": a last-partner id is out of range"};
        k.last_partner.push_back(p);
      }
      if (k.last_partner.size() != n) return Error{where + ": the last-partner list has the wrong length"};
      if (kf.hasLastCollision() && !read_column(kf.getLastCollision(), n, k.last_collision)) {
        // -inf ("never collided") is legitimate here: read it without the finiteness check.
        const auto d = kf.getLastCollision();
        std::vector<unsigned char> raw;
        if (d.size() != n * kScalarWidth<T> || !unshuffle_bytes(d.begin(), d.size(), kScalarWidth<T>, raw))
          return Error{where + ": the TC times are malformed"};
        k.last_collision.resize(n);
        for (std::size_t i = 0; i < n; ++i) k.last_collision[i] = scalar_from_bytes<T>(raw.data() + i * kScalarWidth<T>);
      }
      for (const std::uint64_t c : kf.getEngineCounts()) k.counts.push_back(c);
      // Version 3: 10, 11 with the thermostat, 12 in a Lees-Edwards box (FORMAT.md).
      const std::size_t counted = k.counts.size();
      if (counted < std::size_t(kCountedKindsV2 + 2) || counted > std::size_t(kCountedKindsV2 + 6))
        return Error{where + ": the engine counters are malformed"};
      k.next_sample = kf.getNextSample();
      k.next_action = kf.getNextAction();
      k.same_time_events = kf.getSameTimeEvents();
    }
  } catch (const kj::Exception& e) {
    return Error{where + ": malformed (" + e.getDescription().cStr() + ")"};
  }
  if (k.events_before != ref.first_event) return Error{where + ": its event count disagrees with its record header"};
  return k;
}

}  // namespace

template <class T>
Replay<T>::Replay(std::shared_ptr<const LogReader> log) : log_(std::move(log)) {}

template <class T>
Result<std::unique_ptr<Replay<T>>> Replay<T>::create(std::shared_ptr<const LogReader> log) {
  const LogHeaderInfo& h = log->header();
  if (h.scalar != scalar_kind<T>())
    return Error{log->path() + ": the log was written in " + std::string(to_string(h.scalar)) +
                 " precision, not " + to_string(scalar_kind<T>())};
  std::unique_ptr<Replay<T>> r(new Replay<T>(log));
  const std::size_t n = h.disks;
  std::vector<T> radius, mass;
  if (!read_column(h.radius.data(), h.radius.size(), n, radius) || !read_column(h.mass.data(), h.mass.size(), n, mass))
    return Error{log->path() + ": the header's radii or masses are malformed"};
  r->state_.disk.assign(n, Disk<T>{});
  std::vector<std::int32_t> species(n);
  for (std::size_t i = 0; i < n; ++i) {
    r->state_.disk[i].r = radius[i];
    species[i] = std::int32_t(h.species[i]);
    if (!(radius[i] > 0) || !(mass[i] > 0)) return Error{log->path() + ": a radius or mass in the header is not positive"};
  }
  r->state_.set_masses(std::move(mass));
  r->state_.set_species(std::move(species));
  r->lx_ = T(h.lx);
  r->ly_ = T(h.ly);
  r->state_.gx = T(h.gx);
  r->state_.gy = T(h.gy);
  r->physics_ = EventPhysics<T>::box(h.lx, h.ly, h.boundary == BoundaryKind::Periodic, r->state_.gx, r->state_.gy);
  if (h.column_encoding >= 2) {
    const std::size_t s = std::max<std::size_t>(1, h.species_names.size());
    std::vector<T> table, walls;
    const std::size_t wall_values = h.wall_restitution.size() / kScalarWidth<T>;  // 4 + 5 per segment (checked)
    if (!read_raw_scalars(h.pair_one_plus_xi, s * s, table) || !read_raw_scalars(h.wall_restitution, wall_values, walls) ||
        wall_values < 4 || (wall_values - 4) % 5 != 0)
      return Error{log->path() + ": the header's restitution tables are malformed"};
    r->physics_.species = s;
    r->physics_.one_plus_xi = table;
    for (int w = 0; w < 4; ++w) r->physics_.xi_wall[w] = walls[std::size_t(w)];
    for (std::size_t k = 4; k + 5 <= walls.size(); k += 5) {
      const T* g = &walls[k];
      if (g[0] == g[2] && g[1] == g[3]) return Error{log->path() + ": the header lists a wall segment of zero length"};
      r->physics_.segments.push_back(rules::v2::make_segment(g[0], g[1], g[2], g[3], g[4]));
    }
  }
  if (h.rotation()) {
    const std::size_t s = std::max<std::size_t>(1, h.species_names.size());
    std::vector<T> beta;
    if (!read_column(h.inertia.data(), h.inertia.size(), n, r->state_.inertia) ||
        !read_raw_scalars(h.one_plus_beta, s * s + 4, beta))
      return Error{log->path() + ": the header's rotation data (inertia, 1 + beta) is malformed"};
    r->state_.omega.assign(n, T(0));
    r->physics_.rough = true;
    r->physics_.one_plus_beta.assign(beta.begin(), beta.begin() + std::ptrdiff_t(s * s));
    r->physics_.wall_one_plus_beta = beta[s * s];
  }
  if (Status s = r->load_keyframe(0); !s) return s.error();
  r->last_event_time_initial_ = r->time_;
  return r;
}

// The cursor over the chunk being decoded, and the next event once decoded (not yet applied).
template <class T>
struct Replay<T>::Cursor {
  std::unique_ptr<ChunkDecoder<T>> decoder;
  DecodedEvent<T> next;  // decoded in place (no copy per event); valid while `pending`
  bool pending = false;
};

template <class T>
Status Replay<T>::load_keyframe(std::size_t k) {
  auto data = read_keyframe<T>(*log_, log_->keyframes()[k]);
  if (!data) return data.error();
  const KeyframeData<T>& kf = data.value();
  for (std::size_t i = 0; i < state_.size(); ++i) {
    Disk<T>& d = state_.disk[i];
    d.x = kf.x[i], d.y = kf.y[i], d.vx = kf.vx[i], d.vy = kf.vy[i], d.t = kf.t[i];
  }
  if (!kf.omega.empty()) state_.omega = kf.omega;
  applied_ = kf.events_before;
  time_ = last_event_time_ = kf.time;
  cursor_ = std::make_shared<Cursor>();
  loaded_ = true;
  return Ok{};
}

template <class T>
std::size_t Replay<T>::keyframe_for_event(std::uint64_t n) const {
  const auto& kfs = log_->keyframes();
  std::size_t best = 0;
  for (std::size_t k = 0; k < kfs.size() && kfs[k].first_event <= n; ++k) best = k;
  return best;
}

template <class T>
std::size_t Replay<T>::chunk_containing(std::uint64_t event) const {
  const auto& chunks = log_->chunks();
  const auto it = std::upper_bound(chunks.begin(), chunks.end(), event,
                                   [](std::uint64_t e, const LogRecordRef& c) { return e < c.first_event; });
  return it == chunks.begin() ? chunks.size() : std::size_t(it - chunks.begin() - 1);
}

// Opens the chunk that starts at applied_ (keyframes sit at chunk boundaries and chunks are read whole,
// so the next event always starts one).
template <class T>
Status Replay<T>::open_chunk() {
  const std::size_t c = chunk_containing(applied_);
  const auto& chunks = log_->chunks();
  if (c >= chunks.size() || chunks[c].first_event != applied_)
    return Error{log_->path() + ": no chunk starts at event " + std::to_string(applied_)};
  const LogRecordRef& ref = chunks[c];
  auto words = log_->load_message(ref.offset, ref.payload_size);
  if (!words) return words.error();
  const std::string where = log_->path() + " (chunk at byte " + std::to_string(ref.offset) + ")";
  try {
    MessageWords storage = std::move(words).value();
    capnp::FlatArrayMessageReader message(as_words(storage), reader_options(storage));
    const auto chunk = message.getRoot<logschema::Chunk>();
    if (chunk.getFirstEvent() != ref.first_event || chunk.getCount() != ref.count)
      return Error{where + ": its event range disagrees with its record header"};
    if (Status s = check_run_id(*log_, chunk.getRunId(), ref.offset, "chunk"); !s) return s;
    const capnp::Data::Reader cols[] = {chunk.getTimes(),    chunk.getKinds(),         chunk.getDisks(),
                                        chunk.getPartners(), chunk.getVelocitiesRaw(), chunk.getVelocityResiduals(),
                                        chunk.getSpinResiduals()};
    constexpr int kCols = ChunkDecoder<T>::kColumnCount;
    static_assert(std::size(cols) == kCols);
    const unsigned char* ptrs[kCols];
    std::size_t sizes[kCols];
    for (int k = 0; k < kCols; ++k) ptrs[k] = cols[k].begin(), sizes[k] = cols[k].size();
    // The column pointers point into `storage`, which the decoder takes over (moving a vector keeps its buffer).
    cursor_->decoder = std::make_unique<ChunkDecoder<T>>(std::move(storage), ptrs, sizes, ref.first_event,
                                                         std::uint32_t(ref.count), state_.size(), last_event_time_,
                                                         log_->header().column_encoding, physics_);
  } catch (const kj::Exception& e) {
    return Error{where + ": malformed (" + e.getDescription().cStr() + ")"};
  }
  if (Status s = cursor_->decoder->init(); !s) return Error{where + ": " + s.error().message};
  return Ok{};
}

// Applies events until `target_event` events are applied, or the next event is later than *until_time,
// or f returns false.
template <class T>
Status Replay<T>::advance(std::uint64_t target_event, const T* until_time,
                          const std::function<bool(const ReplayedEvent<T>&)>& f, EventExtras extras) {
  Cursor& c = *cursor_;
  ReplayedEvent<T> out;
  while (applied_ < target_event) {
    if (!c.pending) {
      if (!c.decoder || c.decoder->done()) {
        if (c.decoder)
          if (Status s = c.decoder->check_consumed(); !s) return Error{log_->path() + ": " + s.error().message};
        if (interrupted_ && *interrupted_ && (*interrupted_)())
          return Error{log_->path() + ": interrupted at event " + std::to_string(applied_) +
                       " (the log is unchanged; read it again to go on)"};
        if (Status s = open_chunk(); !s) return s;
      }
      if (!c.decoder->decode(state_, c.next)) return Error{log_->path() + ": " + c.decoder->error_message()};
      c.pending = true;
    }
    const DecodedEvent<T>& e = c.next;
    if (until_time && e.time > *until_time) break;
    if (!f) {  // a seek: apply only
      if (!apply_event(e, state_, lx_, ly_)) return non_finite_error(e.index);
      ++applied_;
      last_event_time_ = e.time;
      c.pending = false;
      continue;
    }
    // Without extras the fields beyond these stay zero from `out`'s construction, so it is reused (a fresh
    // record per event was ~40 instructions, 5 % of a walk writing narrow rows).
    if (extras.before || extras.positions) out = ReplayedEvent<T>{};
    out.index = e.index, out.time = e.time, out.kind = e.kind, out.i = e.i, out.j = e.j;
    out.vix = e.vix, out.viy = e.viy, out.vjx = e.vjx, out.vjy = e.vjy, out.wi = e.wi, out.wj = e.wj;
    if (extras.before) before_event(e, out);
    if (e.kind != EventKind::Pair) unchanged_after(e, out);
    if (!apply_event(e, state_, lx_, ly_)) return non_finite_error(e.index);
    ++applied_;
    last_event_time_ = e.time;
    if (extras.positions) after_event(e, out);
    c.pending = false;
    if (!f(out)) break;
  }
  return Ok{};
}

template <class T>
Error Replay<T>::non_finite_error(std::uint64_t event) const {
  return Error{log_->path() + ": event " + std::to_string(event) +
               " leaves a disk at a non-finite position or time: the log is corrupted"};
}

// The velocities just before an event, and the positions at it (after applying), for callers that look
// at each event: a seek passes no callback and skips this.
template <class T>
void Replay<T>::before_event(const DecodedEvent<T>& e, ReplayedEvent<T>& out) const {
  if (e.i < 0) return;
  out.vix0 = state_.vx_at(std::size_t(e.i), e.time), out.viy0 = state_.vy_at(std::size_t(e.i), e.time);
  if (e.kind == EventKind::Pair || e.kind == EventKind::Step)
    out.vjx0 = state_.vx_at(std::size_t(e.j), e.time), out.vjy0 = state_.vy_at(std::size_t(e.j), e.time);
  if (!state_.omega.empty()) {
    out.wi0 = state_.omega[std::size_t(e.i)];
    if (e.kind == EventKind::Pair) out.wj0 = state_.omega[std::size_t(e.j)];
  }
}

// What an event leaves unchanged is filled in after it, with or without the velocities before (a wrap's
// velocities; the spin of a disk in a wrap, segment or action event of a rough log).
template <class T>
void Replay<T>::unchanged_after(const DecodedEvent<T>& e, ReplayedEvent<T>& out) const {
  if (e.i < 0) return;
  if (e.kind == EventKind::Wrap)
    out.vix = state_.vx_at(std::size_t(e.i), e.time), out.viy = state_.vy_at(std::size_t(e.i), e.time);
  if (!state_.omega.empty() && e.kind != EventKind::Wall) out.wi = state_.omega[std::size_t(e.i)];
}

template <class T>
void Replay<T>::after_event(const DecodedEvent<T>& e, ReplayedEvent<T>& out) const {
  if (e.i < 0) return;
  if (e.advanced) {  // a version 2 pair: apply_event stored exactly these positions (drift over 0 adds 0)
    out.xi = e.xi, out.yi = e.yi, out.xj = e.xj, out.yj = e.yj;
    return;
  }
  out.xi = state_.x_at(std::size_t(e.i), e.time), out.yi = state_.y_at(std::size_t(e.i), e.time);
  if (e.kind == EventKind::Pair || e.kind == EventKind::Step)
    out.xj = state_.x_at(std::size_t(e.j), e.time), out.yj = state_.y_at(std::size_t(e.j), e.time);
}

// Complete logs record the final time; for an incomplete one it is the last event's time, read exactly
// from the last chunk's times column (the record headers hold it only as a double).
template <class T>
T log_final_time(const LogReader& log, T time_without_chunks) {
  if (log.complete()) return scalar_from_bytes<T>(log.final_time_bytes().data());
  if (log.chunks().empty()) return time_without_chunks;
  const LogRecordRef& ref = log.chunks().back();
  if (log.header().column_encoding >= 2) return T(ref.time_last);  // exact for float and double (Replay::final_time)
  auto words = log.load_message(ref.offset, ref.payload_size);
  if (words) {
    try {
      capnp::FlatArrayMessageReader message(as_words(words.value()), reader_options(words.value()));
      const auto times = message.getRoot<logschema::Chunk>().getTimes();
      if (auto t = last_time_of_column<T>(times.begin(), times.size(), std::uint32_t(ref.count))) return t.value();
    } catch (const kj::Exception&) {
    }
  }
  return T(ref.time_last);  // damaged: the approximation; seeking will report the damage
}
template float log_final_time<float>(const LogReader&, float);
template double log_final_time<double>(const LogReader&, double);
template long double log_final_time<long double>(const LogReader&, long double);

// A version 2 log's times need the replayed state, so an incomplete one's last event time is the record
// header's (a double: exact for float and double runs), or, for long double, replayed.
template <class T>
T Replay<T>::final_time() const {
  if (log_->complete() || log_->chunks().empty() || log_->header().column_encoding < 2)
    return log_final_time<T>(*log_, last_event_time_initial_);
  const LogRecordRef& last = log_->chunks().back();
  if constexpr (ScalarBytes<T>::kBits <= 64) {
    return T(last.time_last);
  } else {
    auto r = Replay<T>::create(log_);
    if (r && r.value()->seek_event(last.first_event + last.count)) return r.value()->last_event_time_;
    return T(last.time_last);
  }
}

template <class T>
Status Replay<T>::seek_time(T t) {
  if (!std::isfinite(double(t)) || t < T(0)) return Error{"the time must be finite and >= 0"};
  const T end = final_time();
  if (t > end)
    return Error{log_->path() + ": t = " + exact_number(t) + " is after the end of the log (t = " + exact_number(end) +
                 (log_->complete() ? ")" : ", the last event of an incomplete log)")};
  // The last keyframe at or before t (the index's times are doubles: check the exact time after loading).
  const auto& kfs = log_->keyframes();
  std::size_t k = 0;
  for (std::size_t m = 0; m < kfs.size() && kfs[m].time_first <= double(t); ++m) k = m;
  const bool can_continue = loaded_ && applied_ >= kfs[k].first_event && last_event_time_ <= t;
  if (!can_continue) {
    for (;; --k) {
      if (Status s = load_keyframe(k); !s) return s;
      if (time_ <= t || k == 0) break;
    }
  }
  if (Status s = advance(log_->total_events(), &t, nullptr); !s) return s;
  time_ = t;
  return Ok{};
}

template <class T>
Status Replay<T>::seek_event(std::uint64_t n) {
  if (n > log_->total_events())
    return Error{log_->path() + ": event " + std::to_string(n) + " is beyond the log's " +
                 std::to_string(log_->total_events()) + " events"};
  const std::size_t k = keyframe_for_event(n);
  const bool can_continue = loaded_ && applied_ >= log_->keyframes()[k].first_event && applied_ <= n;
  if (!can_continue)
    if (Status s = load_keyframe(k); !s) return s;
  if (Status s = advance(n, nullptr, nullptr); !s) return s;
  time_ = last_event_time_;
  return Ok{};
}

template <class T>
Status Replay<T>::for_each_event(std::uint64_t from, std::uint64_t to,
                                 const std::function<bool(const ReplayedEvent<T>&)>& f, EventExtras extras) {
  if (Status s = seek_event(from); !s) return s;
  if (Status s = advance(std::min(to, log_->total_events()), nullptr, f, extras); !s) return s;
  time_ = last_event_time_;
  return Ok{};
}

template <class T>
Result<ReplayedEvent<T>> Replay<T>::next_event() {
  if (applied_ >= log_->total_events()) return Error{log_->path() + ": no more events in the log"};
  ReplayedEvent<T> out;
  const std::uint64_t target = applied_ + 1;
  if (Status s = advance(target, nullptr, [&](const ReplayedEvent<T>& e) { return out = e, true; }); !s) return s.error();
  time_ = last_event_time_;
  return out;
}

template <class T>
Result<StoredRebuildPoint<T>> Replay<T>::rebuild_point(std::size_t keyframe) const {
  auto data = read_keyframe<T>(*log_, log_->keyframes()[keyframe]);
  if (!data) return data.error();
  const KeyframeData<T>& kf = data.value();
  if (!kf.resumable) return Error{log_->path() + ": keyframe " + std::to_string(keyframe) + " is not resumable"};
  StoredRebuildPoint<T> r;
  r.time = kf.time;
  r.disks.resize(state_.size());
  for (std::size_t i = 0; i < state_.size(); ++i) {
    Disk<T>& d = r.disks[i];
    d.x = kf.x[i], d.y = kf.y[i], d.vx = kf.vx[i], d.vy = kf.vy[i], d.t = kf.t[i];
    d.r = state_.disk[i].r;
    d.last_partner = kf.last_partner[i];
  }
  r.last_collision = kf.last_collision;
  r.omega = kf.omega;
  for (int c = 0; c < kCountedKindsV2; ++c) r.counts.by_kind[c] = kf.counts[std::size_t(c)];
  r.counts.stale = kf.counts[kCountedKindsV2];
  r.counts.tc_elastic = kf.counts[kCountedKindsV2 + 1];
  if (kf.counts.size() > std::size_t(kCountedKindsV2 + 2))
    r.counts.by_kind[int(EventKind::Segment)] = kf.counts[kCountedKindsV2 + 2];
  if (kf.counts.size() > std::size_t(kCountedKindsV2 + 3))  // format version 3
    r.counts.by_kind[int(EventKind::Step)] = kf.counts[kCountedKindsV2 + 3];
  if (kf.counts.size() > std::size_t(kCountedKindsV2 + 4))  // format version 3, a run with the thermostat
    r.counts.by_kind[int(EventKind::Thermostat)] = kf.counts[kCountedKindsV2 + 4];
  if (kf.counts.size() > std::size_t(kCountedKindsV2 + 5))  // format version 3, a Lees-Edwards box
    r.counts.by_kind[int(EventKind::Shear)] = kf.counts[kCountedKindsV2 + 5];
  r.next_sample_index = kf.next_sample;
  r.next_action_index = kf.next_action;
  r.same_time_events = kf.same_time_events;
  r.initial_energy = log_->header().initial_energy;
  return r;
}

template class Replay<float>;
template class Replay<double>;
template class Replay<long double>;

}  // namespace ede
