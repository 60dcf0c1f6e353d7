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

bool loggable(unsigned char kind) {
  switch (static_cast<EventKind>(kind)) {
    case EventKind::Pair:
    case EventKind::Wall:
    case EventKind::Wrap:
    case EventKind::Action:
    case EventKind::Segment: return true;
    default: return false;
  }
}

Status count_chunk(const LogReader& log, const LogRecordRef& ref, LogKindCounts& out) {
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
      if (!loggable(k) || ((byte & flag) && k != 0 && k != 1))
        return Error{where + ": unknown event kind " + std::to_string(byte)};
      ++out.by_kind[k];
    }
  } catch (const kj::Exception& e) {
    return Error{where + ": malformed (" + e.getDescription().cStr() + ")"};
  }
  ++out.chunks_read;
  return Ok{};
}

}  // namespace

Result<LogKindCounts> count_logged_kinds(const LogReader& log) {
  LogKindCounts counts;
  for (const LogRecordRef& ref : log.chunks())
    if (Status s = count_chunk(log, ref, counts); !s) return s.error();
  return counts;
}

}  // namespace ede
