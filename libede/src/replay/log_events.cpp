// Log (ede/log.hpp): its events, one at a time (for_each_event, events), as columns (event_columns) or as
// rows in a caller's buffer (event_rows), over the cached Replay<T> of the Log (replay/log_impl.hpp).
//
// One walk serves all of them: a range becomes a span of event indices, and each event is written through
// an EventFieldSink (a base address and a stride per field) into columns or rows. A long range is
// replayed in pieces cut at keyframes on several threads; the bits written do not depend on how many.
// Rejected: a walk per output form (three copies of the range and threading logic).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <memory>
#include <new>
#include <system_error>
#include <thread>

#include "core/scalar_dispatch.hpp"
#include "ede/log.hpp"
#include "replay/log_impl.hpp"

namespace ede {

namespace {

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

// Where a range of events starts and ends, as event indices: [first, end), and the time bound t1 (every
// event after it is left out). A from_time seeks the cached replay `r`, which then stands at `first`.
template <class T>
struct EventSpan {
  std::uint64_t first = 0, end = 0;
  T t1 = std::numeric_limits<T>::infinity();
};

template <class T>
Result<EventSpan<T>> span_of(const LogImpl& impl, Replay<T>& r, const EventRange& range) {
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
Status walk_events(const LogImpl& impl, const EventRange& range,
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

// Where one walk writes each field of an event: a base address and the stride between events, or no
// base for a field not wanted. event_columns points it at its column vectors (stride: one value),
// event_rows at the fields of the caller's rows (stride: one row), so both share one writer and one walk.
// memcpy: rows need not be aligned (numpy's structured arrays are packed).
struct EventFieldSink {
  struct Field {
    unsigned char* base = nullptr;
    std::size_t stride = 0;
  };
  Field index, time, kind, i, j, after[4], at[4], pre[4], omega[2], omega_pre[2];

  template <class V>
  static void write(const Field& f, std::size_t r, V v) {
    if (f.base) std::memcpy(f.base + r * f.stride, &v, sizeof v);
  }
  // Which groups of fields anyone wants (set by finish()): put() skips a whole absent group with one test
  // instead of one per field, and the walk computes positions and velocities before only when wanted.
  bool want_at = false, want_pre = false, want_omega = false;

  void finish() {
    const auto any = [](std::initializer_list<const Field*> fs) {
      for (const Field* f : fs)
        if (f->base) return true;
      return false;
    };
    want_at = any({&at[0], &at[1], &at[2], &at[3]});
    want_pre = any({&pre[0], &pre[1], &pre[2], &pre[3], &omega_pre[0], &omega_pre[1]});
    want_omega = any({&omega[0], &omega[1]});
  }
  EventExtras extras() const { return {.before = want_pre, .positions = want_at}; }

  // Rows: every field has this stride (one row), so an event's place is computed once, not per field.
  std::size_t row_stride = 0;

  template <class T>
  void put(std::size_t r, const ReplayedEvent<T>& e) const {
    if (row_stride) {
      const std::size_t at_row = r * row_stride;
      put_fields(e, [at_row](const Field& f, auto v) {
        if (f.base) std::memcpy(f.base + at_row, &v, sizeof v);
      });
    } else {
      put_fields(e, [r](const Field& f, auto v) { write(f, r, v); });
    }
  }

  template <class T, class Write>
  [[gnu::always_inline]] void put_fields(const ReplayedEvent<T>& e, Write w) const {
    w(index, e.index), w(time, e.time), w(kind, static_cast<std::uint8_t>(e.kind)), w(i, e.i), w(j, e.j);
    w(after[0], e.vix), w(after[1], e.viy), w(after[2], e.vjx), w(after[3], e.vjy);
    if (want_at) w(at[0], e.xi), w(at[1], e.yi), w(at[2], e.xj), w(at[3], e.yj);
    if (want_pre) {
      w(pre[0], e.vix0), w(pre[1], e.viy0), w(pre[2], e.vjx0), w(pre[3], e.vjy0);
      w(omega_pre[0], e.wi0), w(omega_pre[1], e.wj0);
    }
    if (want_omega) w(omega[0], e.wi), w(omega[1], e.wj);
  }
};

template <class V>
EventFieldSink::Field column_field(std::vector<V>& v) {
  return {reinterpret_cast<unsigned char*>(v.data()), sizeof(V)};
}

EventFieldSink::Field row_field(void* rows, std::size_t row_bytes, std::ptrdiff_t offset) {
  if (offset < 0) return {};
  return {static_cast<unsigned char*>(rows) + offset, row_bytes};
}

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

namespace {

// The events of a span written through `sink`, replayed in pieces cut at keyframes on up to `threads`
// threads. Returns the events written: a prefix of the span (to_time may end it early).
template <class T>
Result<std::uint64_t> write_events(const LogImpl& impl, Replay<T>& cached, const EventSpan<T>& sp,
                                   const EventFieldSink& sink, unsigned threads) {
  if (sp.first >= sp.end) return std::uint64_t(0);
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  const std::vector<std::uint64_t> bounds = piece_bounds(*impl.reader, sp.first, sp.end, threads);
  const std::size_t n = bounds.size() - 1;
  std::vector<std::uint64_t> written(n, 0);
  std::vector<Status> status(n, Ok{});
  // Piece 0 continues the cached replay (a from_time seek left it at `first`); the others replay from
  // their own keyframe on a fresh Replay over the same reader (LogReader is read-only after open).
  const auto write_piece = [&](std::size_t k) {
    Replay<T>* r = &cached;
    std::unique_ptr<Replay<T>> own;
    if (k > 0) {
      auto made = Replay<T>::create(impl.reader);
      if (!made) return void(status[k] = made.error());
      own = std::move(made).value();
      r = own.get();
      r->set_interrupt_check(&impl.interrupted);
    }
    const std::size_t offset = bounds[k] - sp.first;
    // Counted in a local, stored once: written[k] and written[k + 1] share a cache line, and incrementing
    // them per event from two threads made two threads slower than one (measured: 11.2-11.7 against
    // 12.4-13.1 M events/s on this VM).
    std::uint64_t count = 0;
    status[k] = r->for_each_event(bounds[k], bounds[k + 1], [&](const ReplayedEvent<T>& e) {
      if (!(e.time <= sp.t1)) return false;
      sink.put(offset + count++, e);
      return true;
    }, sink.extras());
    written[k] = count;
  };
  const auto run_piece = [&](std::size_t k) noexcept {
    try {
      write_piece(k);
    } catch (const std::bad_alloc&) {  // in a worker thread an escaping exception would end the process
      status[k] = Error{impl.info.path + ": not enough memory to replay events " + std::to_string(bounds[k]) +
                        " to " + std::to_string(bounds[k + 1]) + ": ask for fewer events at a time (first/last)"};
    }
  };
  {
    std::vector<std::jthread> workers;  // joined however this block is left
    std::vector<std::size_t> here;      // pieces no thread could be started for (a thread or memory limit)
    workers.reserve(n), here.reserve(n);
    for (std::size_t k = 1; k < n; ++k) {
      try {
        workers.emplace_back(run_piece, k);
      } catch (const std::system_error&) {
        here.push_back(k);
      }
    }
    run_piece(0);
    for (const std::size_t k : here) run_piece(k);
  }
  // The events kept are a prefix: a piece cut short by t1 is followed by pieces that stopped at their
  // first event (times never decrease).
  std::uint64_t kept = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!status[k]) return status[k].error();
    kept += written[k];
    if (written[k] < bounds[k + 1] - bounds[k]) break;
  }
  return kept;
}

// Every wanted field inside the row (a binding's layout bug must not write past its buffer).
Status check_row_layout(const EventRowLayout& l, std::size_t real_bytes) {
  const std::pair<std::ptrdiff_t, std::size_t> fields[] = {
      {l.index, 8}, {l.time, real_bytes}, {l.kind, 1}, {l.i, 4}, {l.j, 4},
      {l.vix, real_bytes}, {l.viy, real_bytes}, {l.vjx, real_bytes}, {l.vjy, real_bytes},
      {l.xi, real_bytes}, {l.yi, real_bytes}, {l.xj, real_bytes}, {l.yj, real_bytes},
      {l.vix_before, real_bytes}, {l.viy_before, real_bytes}, {l.vjx_before, real_bytes}, {l.vjy_before, real_bytes},
      {l.omega_i, real_bytes}, {l.omega_j, real_bytes}, {l.omega_i_before, real_bytes}, {l.omega_j_before, real_bytes}};
  for (const auto& [offset, bytes] : fields)
    if (offset >= 0 && std::size_t(offset) + bytes > l.row_bytes)
      return Error{"event_rows: a field at byte " + std::to_string(offset) + " of " + std::to_string(bytes) +
                   " bytes does not fit a row of " + std::to_string(l.row_bytes) + " bytes"};
  return Ok{};
}

// The cached replay and the span of `range` in T, for the event walks.
template <class T>
Result<std::pair<Replay<T>*, EventSpan<T>>> prepare_walk(const LogImpl& impl, const EventRange& range) {
  auto replay = impl.replay_in<T>();
  if (!replay) return replay.error();
  auto span = span_of(impl, *replay.value(), range);
  if (!span) return span.error();
  return std::pair{replay.value(), span.value()};
}

}  // namespace

Result<EventColumns> Log::event_columns(const EventRange& range, bool positions, bool before,
                                        unsigned threads) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Result<EventColumns> {
    auto walk = prepare_walk<T>(*impl_, range);
    if (!walk) return walk.error();
    const auto [replay, sp] = walk.value();
    const std::size_t n = sp.first < sp.end ? sp.end - sp.first : 0;
    std::vector<std::uint64_t> index(n);
    std::vector<std::uint8_t> kind(n);
    std::vector<std::int32_t> i(n), j(n);
    std::vector<T> time(n), after[4], at[4], pre[4];
    EventFieldSink sink;
    sink.index = column_field(index), sink.kind = column_field(kind), sink.i = column_field(i);
    sink.j = column_field(j), sink.time = column_field(time);
    for (int k = 0; k < 4; ++k) {
      after[k].resize(n), sink.after[k] = column_field(after[k]);
      if (positions) at[k].resize(n), sink.at[k] = column_field(at[k]);
      if (before) pre[k].resize(n), sink.pre[k] = column_field(pre[k]);
    }
    sink.finish();
    auto kept = write_events(*impl_, *replay, sp, sink, threads);
    if (!kept) return kept.error();
    const std::size_t m = kept.value();
    const auto cut = [m](auto& v) -> auto&& { return v.resize(std::min(v.size(), m)), std::move(v); };
    EventColumns out;
    out.index = cut(index), out.kind = cut(kind), out.i = cut(i), out.j = cut(j), out.time = Column(cut(time));
    out.vix = Column(cut(after[0])), out.viy = Column(cut(after[1]));
    out.vjx = Column(cut(after[2])), out.vjy = Column(cut(after[3]));
    if (positions) {
      out.xi = Column(cut(at[0])), out.yi = Column(cut(at[1]));
      out.xj = Column(cut(at[2])), out.yj = Column(cut(at[3]));
    }
    if (before) {
      out.vix_before = Column(cut(pre[0])), out.viy_before = Column(cut(pre[1]));
      out.vjx_before = Column(cut(pre[2])), out.vjy_before = Column(cut(pre[3]));
    }
    return out;
  });
}

Result<std::uint64_t> Log::event_rows(const EventRange& range, const EventRowLayout& layout,
                                      const std::function<void*(std::uint64_t rows)>& allocate,
                                      unsigned threads) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Result<std::uint64_t> {
    if (Status s = check_row_layout(layout, sizeof(T)); !s) return s.error();
    auto walk = prepare_walk<T>(*impl_, range);
    if (!walk) return walk.error();
    const auto [replay, sp] = walk.value();
    const std::uint64_t room = sp.first < sp.end ? sp.end - sp.first : 0;
    void* rows = allocate(room);
    if (!rows && room > 0) return Error{impl_->info.path + ": no room for the events' rows"};
    const std::size_t w = layout.row_bytes;
    const auto f = [&](std::ptrdiff_t offset) { return row_field(rows, w, offset); };
    EventFieldSink sink;
    sink.index = f(layout.index), sink.time = f(layout.time), sink.kind = f(layout.kind);
    sink.i = f(layout.i), sink.j = f(layout.j);
    const std::ptrdiff_t after[] = {layout.vix, layout.viy, layout.vjx, layout.vjy};
    const std::ptrdiff_t at[] = {layout.xi, layout.yi, layout.xj, layout.yj};
    const std::ptrdiff_t pre[] = {layout.vix_before, layout.viy_before, layout.vjx_before, layout.vjy_before};
    for (int k = 0; k < 4; ++k) sink.after[k] = f(after[k]), sink.at[k] = f(at[k]), sink.pre[k] = f(pre[k]);
    sink.omega[0] = f(layout.omega_i), sink.omega[1] = f(layout.omega_j);
    sink.omega_pre[0] = f(layout.omega_i_before), sink.omega_pre[1] = f(layout.omega_j_before);
    sink.row_stride = w;
    sink.finish();
    return write_events(*impl_, *replay, sp, sink, threads);
  });
}

Result<std::vector<Event>> Log::events(const EventRange& range) const {
  std::vector<Event> out;
  Status s = for_each_event(range, [&](const Event& e) { return out.push_back(e), true; });
  if (!s) return s.error();
  return out;
}

}  // namespace ede
