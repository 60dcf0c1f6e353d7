// Log (ede/log.hpp): opening, info, states, events and digests over LogReader and Replay<T>.
//
// Every entry point dispatches once on the log's scalar type and then works in T; states leave as columns
// in T (state_of), events as Event with every value widened exactly to Time.
#include "ede/log.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <thread>

#include "core/scalar_dispatch.hpp"
#include "core/state_of.hpp"
#include "log/log_stats.hpp"
#include "replay/log_convert.hpp"
#include "replay/log_digest.hpp"
#include "replay/log_impl.hpp"

namespace ede {

namespace {

LogInfo info_of(const LogReader& r) {
  const LogHeaderInfo& h = r.header();
  LogInfo i;
  i.path = r.path();
  i.format_version = h.format_version;
  i.engine_version = h.engine_version, i.compiler = h.compiler, i.compile_flags = h.compile_flags;
  i.scalar = h.scalar;
  i.seed = h.seed;
  i.scene_name = h.scene_name, i.scene_text = h.scene_text;
  i.disks = h.disks;
  i.species_names = h.species_names;
  i.species_counts.assign(h.species_names.size(), 0);
  for (const std::uint32_t s : h.species) ++i.species_counts[s];  // the reader checked every index
  i.lx = h.lx, i.ly = h.ly, i.boundary = h.boundary;
  i.tc_model = h.tc_model, i.gx = h.gx, i.gy = h.gy;
  i.initial_energy = h.initial_energy;
  i.chunk_events = h.chunk_events, i.keyframe_interval = h.keyframe_interval, i.rebuild_interval = h.rebuild_interval;
  i.events = r.total_events();
  i.chunks = r.chunks().size(), i.keyframes = r.keyframes().size();
  for (const LogRecordRef& k : r.keyframes()) i.resumable_keyframes += k.resumable ? 1 : 0;
  i.file_size = r.file_size();
  i.start_time = r.keyframes().front().time_first;
  i.end_time = with_scalar(h.scalar, [&]<class T>() { return Time(log_final_time<T>(r, T(i.start_time))); });
  if (!r.chunks().empty())
    i.first_event_time = r.chunks().front().time_first, i.last_event_time = r.chunks().back().time_last;
  i.complete = r.complete(), i.damaged = r.damaged();
  i.incomplete_reason = r.incomplete_reason(), i.final_status = r.final_status();
  return i;
}

template <class T>
Event event_of(const ReplayedEvent<T>& e) {
  Event out;
  out.index = e.index, out.time = e.time, out.kind = e.kind, out.i = e.i, out.j = e.j;
  out.xi = e.xi, out.yi = e.yi, out.xj = e.xj, out.yj = e.yj;
  out.vix_before = e.vix0, out.viy_before = e.viy0, out.vjx_before = e.vjx0, out.vjy_before = e.vjy0;
  out.vix = e.vix, out.viy = e.viy, out.vjx = e.vjx, out.vjy = e.vjy;
  out.omega_i_before = e.wi0, out.omega_j_before = e.wj0, out.omega_i = e.wi, out.omega_j = e.wj;
  return out;
}

// Seeks to the first event with time >= t0 (every earlier event applied) and returns its index.
template <class T>
Result<std::uint64_t> seek_before(Replay<T>& replay, T t0) {
  Status s =
      t0 > T(0) ? replay.seek_time(std::nextafter(t0, -std::numeric_limits<T>::infinity())) : replay.seek_event(0);
  if (!s) return s.error();
  return replay.events_applied();
}

}  // namespace

Log::Log(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}

Result<Log> Log::open(const std::string& path, const LogLimits& limits) {
  auto reader = LogReader::open(path, ReadLimits{limits.max_disks, limits.max_record_bytes});
  if (!reader) return reader.error();
  auto impl = std::make_shared<Impl>();
  impl->reader = std::move(reader).value();
  impl->info = info_of(*impl->reader);
  return Log(std::move(impl));
}

const LogInfo& Log::info() const { return impl_->info; }

Result<Scene> Log::scene() const { return parse_scene_text(impl_->info.scene_text, impl_->info.scene_name); }

Result<State> Log::state_at(Time t) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Result<State> {
    auto replay = impl_->replay_in<T>();
    if (!replay) return replay.error();
    Replay<T>& r = *replay.value();
    if (Status s = r.seek_time(T(t)); !s) return s.error();
    const LogInfo& i = impl_->info;
    return state_of(r.particles(), r.time(), r.events_applied(), i.lx, i.ly, i.boundary, i.species_names);
  });
}

Result<State> Log::state_at_event(std::uint64_t n) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Result<State> {
    auto replay = impl_->replay_in<T>();
    if (!replay) return replay.error();
    Replay<T>& r = *replay.value();
    if (Status s = r.seek_event(n); !s) return s.error();
    const LogInfo& i = impl_->info;
    return state_of(r.particles(), r.time(), r.events_applied(), i.lx, i.ly, i.boundary, i.species_names);
  });
}

Result<State> Log::state_at_end() const {
  // The end of a log cut short is its last event: seeking to it by index is exact in every scalar type.
  if (!impl_->info.complete) return state_at_event(impl_->info.events);
  return state_at(impl_->info.end_time);
}

namespace {

// Where a range of events starts and ends, as event indices: [first, end), and the time bound t1 (every
// event after it is left out). A from_time seeks the cached replay `r`, which then stands at `first`.
template <class T>
struct EventSpan {
  std::uint64_t first = 0, end = 0;
  T t1 = std::numeric_limits<T>::infinity();
};

template <class T>
Result<EventSpan<T>> span_of(const Log::Impl& impl, Replay<T>& r, const EventRange& range) {
  const std::uint64_t total = impl.info.events;
  EventSpan<T> span;
  span.first = range.from_event.value_or(0);
  span.end = std::min(total, range.to_event.value_or(total));
  if (span.first > total)
    return Error{impl.info.path + ": event " + std::to_string(span.first) + " is beyond the log's " +
                 std::to_string(total) + " events"};
  if (range.to_time) span.t1 = T(*range.to_time);
  if (range.from_time) {
    const T t0 = T(*range.from_time);
    if (t0 > r.final_time()) span.first = span.end;
    else {
      auto at = seek_before(r, t0);
      if (!at) return at.error();
      span.first = std::max(span.first, at.value());
    }
  }
  // No chunk that starts after t1 holds an event of the range (times never decrease).
  for (const LogRecordRef& c : impl.reader->chunks())
    if (c.time_first > double(span.t1) && c.first_event < span.end) {
      span.end = std::max(span.first, c.first_event);
      break;
    }
  return span;
}

// The events of `range` in order, as the log's own ReplayedEvent<T>: the one walk behind for_each_event and
// event_columns.
template <class T>
Status walk_events(const Log::Impl& impl, const EventRange& range,
                   const std::function<bool(const ReplayedEvent<T>&)>& f) {
  auto replay = impl.replay_in<T>();
  if (!replay) return replay.error();
  Replay<T>& r = *replay.value();
  auto span = span_of(impl, r, range);
  if (!span) return span.error();
  const EventSpan<T> sp = span.value();
  if (sp.first >= sp.end) return Ok{};
  return r.for_each_event(sp.first, sp.end, [&](const ReplayedEvent<T>& e) { return e.time <= sp.t1 && f(e); });
}

// The columns of an event_columns walk, sized for the whole span up front so that each piece writes its
// own slice (no appending, no copying pieces together) and the result is moved out as it is.
template <class T>
struct ColumnsOf {
  std::vector<std::uint64_t> index;
  std::vector<std::uint8_t> kind;
  std::vector<std::int32_t> i, j;
  std::vector<T> time, after[4], at[4], pre[4];
  bool positions = false, before = false;

  template <class F>
  void each(F f) {
    f(index), f(kind), f(i), f(j), f(time);
    for (int k = 0; k < 4; ++k) {
      f(after[k]);
      if (positions) f(at[k]);
      if (before) f(pre[k]);
    }
  }
  void resize(std::size_t n) {
    each([n](auto& v) { v.resize(n); });
  }
  void put(std::size_t r, const ReplayedEvent<T>& e) {
    index[r] = e.index, kind[r] = static_cast<std::uint8_t>(e.kind), i[r] = e.i, j[r] = e.j, time[r] = e.time;
    after[0][r] = e.vix, after[1][r] = e.viy, after[2][r] = e.vjx, after[3][r] = e.vjy;
    if (positions) at[0][r] = e.xi, at[1][r] = e.yi, at[2][r] = e.xj, at[3][r] = e.yj;
    if (before) pre[0][r] = e.vix0, pre[1][r] = e.viy0, pre[2][r] = e.vjx0, pre[3][r] = e.vjy0;
  }
};

// [first, end) cut at keyframes into at most `pieces` runs of about equal length: each piece after the
// first starts exactly at a keyframe, so its replay starts there with nothing to skip.
std::vector<std::uint64_t> piece_bounds(const LogReader& reader, std::uint64_t first, std::uint64_t end,
                                        unsigned pieces) {
  std::vector<std::uint64_t> bounds{first};
  const std::uint64_t target = (end - first) / std::max(pieces, 1u);
  for (const LogRecordRef& k : reader.keyframes()) {
    if (bounds.size() >= pieces) break;
    if (k.first_event > first && k.first_event < end && k.first_event - bounds.back() >= target / 2 &&
        k.first_event - first >= target * bounds.size() - target / 2)
      bounds.push_back(k.first_event);
  }
  bounds.push_back(end);
  return bounds;
}

}  // namespace

Status Log::for_each_event(const EventRange& range, const std::function<bool(const Event&)>& f) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Status {
    return walk_events<T>(*impl_, range, [&](const ReplayedEvent<T>& e) { return f(event_of(e)); });
  });
}

Result<EventColumns> Log::event_columns(const EventRange& range, bool positions, bool before,
                                        unsigned threads) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Result<EventColumns> {
    auto replay = impl_->replay_in<T>();
    if (!replay) return replay.error();
    auto span = span_of(*impl_, *replay.value(), range);
    if (!span) return span.error();
    const EventSpan<T> sp = span.value();
    ColumnsOf<T> c;
    c.positions = positions, c.before = before;
    if (sp.first < sp.end) {
      if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
      const std::vector<std::uint64_t> bounds = piece_bounds(*impl_->reader, sp.first, sp.end, threads);
      const std::size_t n = bounds.size() - 1;
      c.resize(sp.end - sp.first);
      std::vector<std::uint64_t> written(n, 0);
      std::vector<Status> status(n, Ok{});
      // Piece 0 continues the cached replay (a from_time seek left it at `first`); the others replay from
      // their own keyframe on a fresh Replay over the same reader (LogReader is read-only after open).
      const auto run_piece = [&](std::size_t k) {
        Replay<T>* r = replay.value();
        std::unique_ptr<Replay<T>> own;
        if (k > 0) {
          auto made = Replay<T>::create(impl_->reader);
          if (!made) return void(status[k] = made.error());
          own = std::move(made).value();
          r = own.get();
        }
        const std::size_t offset = bounds[k] - sp.first;
        status[k] = r->for_each_event(bounds[k], bounds[k + 1], [&](const ReplayedEvent<T>& e) {
          if (!(e.time <= sp.t1)) return false;
          c.put(offset + written[k]++, e);
          return true;
        });
      };
      std::vector<std::thread> workers;
      for (std::size_t k = 1; k < n; ++k) workers.emplace_back(run_piece, k);
      run_piece(0);
      for (std::thread& w : workers) w.join();
      // The events kept are a prefix: a piece cut short by t1 is followed by pieces that stopped at their
      // first event (times never decrease).
      std::uint64_t kept = 0;
      for (std::size_t k = 0; k < n; ++k) {
        if (!status[k]) return status[k].error();
        kept += written[k];
        if (written[k] < bounds[k + 1] - bounds[k]) break;
      }
      c.resize(kept);
    }
    EventColumns out;
    out.index = std::move(c.index), out.kind = std::move(c.kind), out.i = std::move(c.i), out.j = std::move(c.j);
    out.time = Column(std::move(c.time));
    out.vix = Column(std::move(c.after[0])), out.viy = Column(std::move(c.after[1]));
    out.vjx = Column(std::move(c.after[2])), out.vjy = Column(std::move(c.after[3]));
    if (positions) {
      out.xi = Column(std::move(c.at[0])), out.yi = Column(std::move(c.at[1]));
      out.xj = Column(std::move(c.at[2])), out.yj = Column(std::move(c.at[3]));
    }
    if (before) {
      out.vix_before = Column(std::move(c.pre[0])), out.viy_before = Column(std::move(c.pre[1]));
      out.vjx_before = Column(std::move(c.pre[2])), out.vjy_before = Column(std::move(c.pre[3]));
    }
    return out;
  });
}

Result<std::vector<Event>> Log::events(const EventRange& range) const {
  std::vector<Event> out;
  Status s = for_each_event(range, [&](const Event& e) { return out.push_back(e), true; });
  if (!s) return s.error();
  return out;
}

Result<EventCounts> Log::count_events() const {
  auto counts = count_logged_kinds(*impl_->reader);
  if (!counts) return counts.error();
  EventCounts c;
  for (int k = 0; k < kEventKindCount; ++k) c.by_kind[k] = counts.value().by_kind[k];
  return c;
}

Result<std::string> Log::content_digest() const { return log_content_digest(impl_->reader); }

Status Log::convert(const std::string& out_path, std::uint32_t format_version) const {
  return convert_log(impl_->reader, out_path, format_version);
}

}  // namespace ede
