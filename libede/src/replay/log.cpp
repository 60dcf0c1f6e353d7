// Log (ede/log.hpp): opening, info, states, events and digests over LogReader and Replay<T>.
//
// Every entry point dispatches once on the log's scalar type and then works in T; states leave as columns
// in T (state_of), events as Event with every value widened exactly to Time.
#include "ede/log.hpp"

#include <cmath>
#include <limits>

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

// The events of `range` in order, as the log's own ReplayedEvent<T>: the one walk behind for_each_event and
// event_columns.
template <class T>
Status walk_events(const Log::Impl& impl, const EventRange& range,
                   const std::function<bool(const ReplayedEvent<T>&)>& f) {
  auto replay = impl.replay_in<T>();
  if (!replay) return replay.error();
  Replay<T>& r = *replay.value();
  const std::uint64_t total = impl.info.events;
  std::uint64_t first = range.from_event.value_or(0), end = std::min(total, range.to_event.value_or(total));
  if (first > total)
    return Error{impl.info.path + ": event " + std::to_string(first) + " is beyond the log's " +
                 std::to_string(total) + " events"};
  const T t1 = range.to_time ? T(*range.to_time) : std::numeric_limits<T>::infinity();
  if (range.from_time) {
    const T t0 = T(*range.from_time);
    if (t0 > r.final_time()) return Ok{};
    auto at = seek_before(r, t0);
    if (!at) return at.error();
    first = std::max(first, at.value());
  }
  if (first >= end) return Ok{};
  return r.for_each_event(first, end, [&](const ReplayedEvent<T>& e) { return e.time <= t1 && f(e); });
}

template <class T>
struct ColumnsOf {
  std::vector<T> time, after[4], at[4], pre[4];
};

}  // namespace

Status Log::for_each_event(const EventRange& range, const std::function<bool(const Event&)>& f) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Status {
    return walk_events<T>(*impl_, range, [&](const ReplayedEvent<T>& e) { return f(event_of(e)); });
  });
}

Result<EventColumns> Log::event_columns(const EventRange& range, bool positions, bool before,
                                        std::size_t expected) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Result<EventColumns> {
    EventColumns out;
    ColumnsOf<T> c;
    out.index.reserve(expected), out.kind.reserve(expected), out.i.reserve(expected), out.j.reserve(expected);
    c.time.reserve(expected);
    for (int k = 0; k < 4; ++k) {
      c.after[k].reserve(expected);
      if (positions) c.at[k].reserve(expected);
      if (before) c.pre[k].reserve(expected);
    }
    Status s = walk_events<T>(*impl_, range, [&](const ReplayedEvent<T>& e) {
      out.index.push_back(e.index), out.kind.push_back(static_cast<std::uint8_t>(e.kind));
      out.i.push_back(e.i), out.j.push_back(e.j);
      c.time.push_back(e.time);
      c.after[0].push_back(e.vix), c.after[1].push_back(e.viy), c.after[2].push_back(e.vjx), c.after[3].push_back(e.vjy);
      if (positions) c.at[0].push_back(e.xi), c.at[1].push_back(e.yi), c.at[2].push_back(e.xj), c.at[3].push_back(e.yj);
      if (before) {
        c.pre[0].push_back(e.vix0), c.pre[1].push_back(e.viy0), c.pre[2].push_back(e.vjx0), c.pre[3].push_back(e.vjy0);
      }
      return true;
    });
    if (!s) return s.error();
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
