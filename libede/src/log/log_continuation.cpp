// continuation_from: where a resumed run cuts its log and which index entries it keeps (log_writer.hpp).
#include <algorithm>

#include "log/log_framing.hpp"
#include "log/log_writer.hpp"

namespace ede {

LogContinuation continuation_from(const LogReader& log, std::size_t keyframe) {
  const LogRecordRef& kf = log.keyframes()[keyframe];
  LogContinuation c;
  c.cut_offset = kf.offset + logfmt::kRecordHeaderSize + kf.payload_size;
  c.events_before = kf.first_event;
  c.run_id = log.header().run_id;
  for (const auto* list : {&log.chunks(), &log.keyframes()})
    for (const LogRecordRef& e : *list)
      if (e.offset <= kf.offset)
        c.entries.push_back({e.kind, e.offset, e.first_event, e.count, e.time_first, e.time_last, e.resumable});
  std::sort(c.entries.begin(), c.entries.end(), [](const auto& a, const auto& b) { return a.offset < b.offset; });
  return c;
}

}  // namespace ede
