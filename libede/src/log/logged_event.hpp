// An event as the log writer keeps it from the event loop until its chunk is coded on the writer's worker.
//
// Format version 2 codes every time and velocity as a residual against its predictors. The predictions are
// made on the event loop, from the records the engine hands over with the event (EventOutcome::before_i,
// before_j: in cache there, a cache miss anywhere else), and only where the engine does not vouch for them
// (EventOutcome::v2_*_exact: an ordinary pair collision needs no prediction at all). What the worker gets is
// then small: the time and its prediction, the ids and the kind (LoggedEvent, 32 bytes in double), and,
// only for an event whose velocities were not vouched for, the velocities and their predictions in
// `extra`; the time's prediction is kept apart (`predicted`) only where it differs from the time, so a
// LoggedEvent is 24 bytes in double (32 with the prediction in it): less for the loop to write and the
// worker to read when both share one core and its L2 with the engine's data. The worker turns these into
// residuals and varints, builds the record and compresses it.
// Format version 1 (ede-replay convert, comparisons) keeps in `extra` what its coder reads: the velocities
// after and before the event and the two masses.
// Rejected: the worker keeping a replayed copy of the state to predict from (40 B/disk; its cache misses,
// and the predictions, were most of the log's cost when loop and worker share one core: docs/performance.md,
// "The log's share of one core"), and the loop handing over the records for the worker to predict from
// (152 B an event, more than the predictions they would have moved).
#pragma once

#include <cstdint>
#include <vector>

#include "core/event.hpp"
#include "log/scalar_bytes.hpp"

namespace ede {

// Everything the chunk encoder reads of one event.
template <class T>
struct CodedEvent {
  T time{};
  T predicted_time{};  // format version 2's prediction of the time (+infinity: none)
  EventKind kind{};
  bool tc_elastic = false;
  bool velocities_predicted = true;  // version 2: every velocity and spin residual is 0 (v and pv unused)
  std::int32_t i = -1, j = -1;
  T v[4] = {}, pv[4] = {};  // version 2: velocities after the event and as predicted; version 1: after and before
  T w[2] = {}, pw[2] = {};  // rough runs, version 2: spins after the event and as predicted
  T mi{}, mj{};             // version 1: masses
};

template <class T>
struct LoggedEvent {
  T time;
  std::int32_t i, j;
  EventKind kind;
  bool tc_elastic;
  bool extra;      // the velocities follow in ChunkEvents::extra
  bool predicted;  // the time's prediction differs from the time (bit for bit): it follows in ChunkEvents::predicted
};
static_assert(sizeof(LoggedEvent<double>) == 24);

// Whether a prediction is the time itself, bit for bit (the time code's test: -0 and +0 differ there).
template <class T>
inline bool same_key(T a, T b) {
  return ordered_key(a) == ordered_key(b);
}

// The events of one chunk, in order: each LoggedEvent, and for those with `extra` their values in `extra`
// (version 2: v[4], pv[4], then w[2], pw[2] in rough runs; version 1: v[4], v0[4], mi, mj).
template <class T>
class ChunkEvents {
 public:
  ChunkEvents() = default;
  ChunkEvents(bool rough, bool format_v1) : rough_(rough), v1_(format_v1) {}

  std::size_t size() const { return events_.size(); }
  bool empty() const { return events_.empty(); }
  void reserve(std::size_t n) { events_.reserve(n); }
  void clear() { events_.clear(), extra_.clear(), predicted_.clear(); }
  T time_first() const { return events_.front().time; }
  T time_last() const { return events_.back().time; }

  // An event with nothing in `extra` and its time predicted exactly (version 2, vouched for entirely).
  void push_plain(const LoggedEvent<T>& e) { events_.push_back(e); }

  void push_back(const CodedEvent<T>& e) {
    const bool extra = v1_ || !e.velocities_predicted;
    const bool predicted = !v1_ && !same_key(e.time, e.predicted_time);  // version 1 codes no time prediction
    events_.push_back({e.time, e.i, e.j, e.kind, e.tc_elastic, extra, predicted});
    if (predicted) predicted_.push_back(e.predicted_time);
    if (!extra) return;
    extra_.insert(extra_.end(), e.v, e.v + 4);
    extra_.insert(extra_.end(), e.pv, e.pv + 4);
    if (v1_) {
      extra_.insert(extra_.end(), {e.mi, e.mj});
    } else if (rough_) {
      extra_.insert(extra_.end(), e.w, e.w + 2);
      extra_.insert(extra_.end(), e.pw, e.pw + 2);
    }
  }

  // f(const CodedEvent<T>&) for each event in order.
  template <class F>
  [[gnu::always_inline]] void for_each(F&& f) const {
    const T* x = extra_.data();
    const T* predicted = predicted_.data();
    CodedEvent<T> e;
    for (const LoggedEvent<T>& l : events_) {
      e.time = l.time, e.kind = l.kind, e.tc_elastic = l.tc_elastic;
      e.predicted_time = l.predicted ? *predicted++ : l.time;
      e.i = l.i, e.j = l.j;
      e.velocities_predicted = !l.extra;
      if (l.extra) {
        for (int k = 0; k < 4; ++k) e.v[k] = x[k], e.pv[k] = x[4 + k];
        x += 8;
        if (v1_) {
          e.mi = x[0], e.mj = x[1], x += 2;
        } else if (rough_) {
          e.w[0] = x[0], e.w[1] = x[1], e.pw[0] = x[2], e.pw[1] = x[3], x += 4;
        }
      }
      f(e);
    }
  }

 private:
  std::vector<LoggedEvent<T>> events_;
  std::vector<T> extra_;
  std::vector<T> predicted_;  // the time predictions of the events with `predicted`, in order
  bool rough_ = false, v1_ = false;
};

}  // namespace ede
