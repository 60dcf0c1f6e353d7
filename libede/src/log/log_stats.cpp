// Counting a log's events by kind from the chunks' kinds columns; see log_stats.hpp.
#include "log/log_stats.hpp"

#include <capnp/serialize.h>
#include <kj/exception.h>

#include <string>

#include "ede_log.capnp.h"
#include "log/chunk_codec.hpp"
#include "log/log_messages.hpp"
#include "log/run_id.hpp"

namespace ede {

namespace {

bool loggable(unsigned char kind, std::uint32_t encoding) {
  switch (static_cast<EventKind>(kind)) {
    case EventKind::Pair:
    case EventKind::Wall:
    case EventKind::Wrap:
    case EventKind::Action:
    case EventKind::Segment:
    case EventKind::Step: return true;
    case EventKind::Thermostat:
    case EventKind::Shear: return encoding >= 3;
    default: return false;
  }
}

// Calls f(kind) for each event of the chunk, in order, after checking its kinds column; f returns false
// to stop. Version 2's TC flag bit is taken off the kind.
template <class F>
Status visit_chunk_kinds(const LogReader& log, const LogRecordRef& ref, F f) {
  auto words = log.load_message(ref.offset, ref.payload_size);
  if (!words) return words.error();
  const std::string where = log.path() + " (chunk at byte " + std::to_string(ref.offset) + ")";
  try {
    capnp::FlatArrayMessageReader message(as_words(words.value()), reader_options(words.value()));
    const auto chunk = message.getRoot<logschema::Chunk>();
    if (Status s = check_run_id(log, chunk.getRunId(), ref.offset, "chunk"); !s) return s;
    const auto kinds = chunk.getKinds();
    if (kinds.size() != ref.count)
      return Error{where + ": its kinds column holds " + std::to_string(kinds.size()) + " bytes for " +
                   std::to_string(ref.count) + " events"};
    // Version 2 marks TC-elastic collisions with a flag bit in the kind byte (FORMAT.md).
    const unsigned char flag = log.header().column_encoding >= 2 ? kTcElasticFlag : 0;
    for (const unsigned char byte : kinds) {
      const unsigned char k = static_cast<unsigned char>(byte & ~flag);
      if (!loggable(k, log.header().column_encoding) || ((byte & flag) && k != 0 && k != 1 && k != 6))
        return Error{where + ": unknown event kind " + std::to_string(byte)};
      if (!f(k)) break;
    }
  } catch (const kj::Exception& e) {
    return Error{where + ": malformed (" + e.getDescription().cStr() + ")"};
  }
  return Ok{};
}

}  // namespace

Result<LogKindCounts> count_logged_kinds(const LogReader& log) {
  LogKindCounts counts;
  for (const LogRecordRef& ref : log.chunks()) {
    if (Status s = visit_chunk_kinds(log, ref, [&](unsigned char k) { return ++counts.by_kind[k], true; }); !s)
      return s.error();
    ++counts.chunks_read;
  }
  return counts;
}

Result<std::vector<std::uint64_t>> events_through_pairs(const LogReader& log, const std::vector<std::uint64_t>& pairs) {
  std::vector<std::uint64_t> out;
  out.reserve(pairs.size());
  std::uint64_t seen = 0;  // pair collisions among the events before `event`
  std::uint64_t event = 0;
  std::size_t next = 0;
  const auto settle = [&] {  // every target reached so far
    while (next < pairs.size() && pairs[next] <= seen) out.push_back(pairs[next] == 0 ? 0 : event), ++next;
  };
  settle();
  for (const LogRecordRef& ref : log.chunks()) {
    if (next == pairs.size()) break;
    event = ref.first_event;
    Status s = visit_chunk_kinds(log, ref, [&](unsigned char k) {
      ++event;
      if (k == static_cast<unsigned char>(EventKind::Pair)) ++seen, settle();
      return next < pairs.size();
    });
    if (!s) return s.error();
  }
  if (next < pairs.size())
    return Error{log.path() + ": the log holds " + std::to_string(seen) + " pair collisions, fewer than the " +
                 std::to_string(pairs[next]) + " asked for"};
  return out;
}

}  // namespace ede
