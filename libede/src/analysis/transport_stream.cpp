// The transport analyses' walk over a log window (transport_stream.hpp): option checks, the start state,
// and the events in batches of 2^18 columns (~30 MB with positions).
#include "analysis/transport_stream.hpp"

#include <cmath>

#include "analysis/sheared_guard.hpp"

namespace ede::transport {

Result<Window> open_window(const Log& log, const TransportOptions& o, const char* what) {
  const LogInfo& info = log.info();
  const std::string where = info.path + ": " + what + ": ";
  if (info.gx != 0 || info.gy != 0)
    return Error{where + "the log has gravity, so velocities are not constant between events; this analysis "
                         "needs a run without gravity"};
  if (std::string why = sheared_refusal(log, what); !why.empty()) return Error{why};
  Window w;
  w.from = o.from.value_or(double(info.start_time));
  w.to = o.to.value_or(double(info.end_time));
  if (!(w.from >= double(info.start_time) && w.to <= double(info.end_time) && w.from < w.to))
    return Error{where + "the window " + std::to_string(w.from) + " to " + std::to_string(w.to) +
                 " is not a non-empty part of the log's " + std::to_string(double(info.start_time)) + " to " +
                 std::to_string(double(info.end_time))};
  if (!(o.lag_step > 0) || !(o.max_lag >= o.lag_step) || !(o.max_lag < w.to - w.from))
    return Error{where + "need 0 < lag step <= max lag < window length (" + std::to_string(w.to - w.from) +
                 "); got lag step " + std::to_string(o.lag_step) + ", max lag " + std::to_string(o.max_lag)};
  if (o.max_lag / o.lag_step > 1e6) return Error{where + "more than 10^6 lags: raise the lag step"};
  if (o.groups == 0) return Error{where + "groups must be >= 1"};
  auto s = log.state_at(w.from);
  if (!s) return s.error();
  w.start = std::move(s).value();
  return w;
}

Status for_each_window_event(const Log& log, const Window& w, bool positions,
                             const std::function<void(const StreamEvent&)>& f) {
  constexpr std::uint64_t kBatch = 1 << 18;
  std::uint64_t next = w.start.events;
  const std::uint64_t total = log.info().events;
  while (next < total) {
    EventRange range;
    range.from_event = next;
    range.to_event = std::min(total, next + kBatch);
    range.to_time = w.to;
    auto c = log.event_columns(range, positions, false);
    if (!c) return c.error();
    const EventColumns& e = c.value();
    for (std::size_t k = 0; k < e.size(); ++k) {
      StreamEvent s;
      s.time = e.time[k];
      s.kind = static_cast<EventKind>(e.kind[k]);
      s.i = e.i[k], s.j = e.j[k];
      if (positions) s.xi = e.xi[k], s.yi = e.yi[k], s.xj = e.xj[k], s.yj = e.yj[k];
      s.vix = e.vix[k], s.viy = e.viy[k], s.vjx = e.vjx[k], s.vjy = e.vjy[k];
      f(s);
    }
    if (e.size() < range.to_event.value() - next) break;  // stopped at the window's end
    next += e.size();
  }
  return Ok{};
}

std::vector<std::int32_t> select_disks(const State& s, std::int32_t species, std::size_t& count) {
  std::vector<std::int32_t> local(s.size(), -1);
  count = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (species < 0 || s.species[i] == species) local[i] = std::int32_t(count++);
  return local;
}

double standard_error(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  double mean = 0, ss = 0;
  for (const double x : v) mean += x;
  mean /= double(v.size());
  for (const double x : v) ss += (x - mean) * (x - mean);
  return std::sqrt(ss / double(v.size() - 1) / double(v.size()));
}

}  // namespace ede::transport
