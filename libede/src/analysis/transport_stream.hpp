// The walk behind the transport analyses (transport.hpp): the state at the window's start, then every
// logged event up to its end in batches of columns (bounded memory whatever the log's length), each event
// handed on as one plain record in double. Rejected: Log::for_each_event (an Event of ~240 bytes built per
// event, several times slower than columns) and one event_columns call for the whole window (its memory
// grows with the log).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "ede/log.hpp"
#include "ede/transport.hpp"

namespace ede::transport {

struct StreamEvent {
  double time = 0;
  EventKind kind = EventKind::Pair;
  std::int32_t i = -1, j = -1;
  double xi = 0, yi = 0, xj = 0, yj = 0;      // at the event (a wrap: after the move)
  double vix = 0, viy = 0, vjx = 0, vjy = 0;  // after the event
};

struct Window {
  double from = 0, to = 0;
  State start;  // the state at `from`
};

// Checks the options against the log (lags, window, no gravity) and reads the state at the window's start.
Result<Window> open_window(const Log& log, const TransportOptions& o, const char* what);
// Every event after `w.start` with time <= w.to, in order.
Status for_each_window_event(const Log& log, const Window& w, bool positions,
                             const std::function<void(const StreamEvent&)>& f);
// The disks of the species asked for: local index per disk id (-1 when not selected), and the count.
std::vector<std::int32_t> select_disks(const State& s, std::int32_t species, std::size_t& count);

// Standard error of the mean of `values` (n >= 2; 0 otherwise).
double standard_error(const std::vector<double>& values);

}  // namespace ede::transport
