// run_id_of and check_run_id; see run_id.hpp.
#include "log/run_id.hpp"

#include <capnp/message.h>

#include <cstdio>

#include "core/xxh3.hpp"
#include "log/log_reader.hpp"

namespace ede {

std::uint32_t run_id_of(logschema::Header::Reader header) {
  // A first segment the size of the header: the copy in one segment, not MallocMessageBuilder's growth
  // (at N = 10^6 the header's per-disk columns are 20 MB, and this runs next to the engine and the log).
  capnp::MallocMessageBuilder copy(unsigned(header.totalSize().wordCount + 8));
  copy.setRoot(header);
  auto h = copy.getRoot<logschema::Header>();
  h.setEngineVersion("");
  h.setCompiler("");
  h.setCompileFlags("");
  h.setRunId(0);
  return run_id_of_cleared(h.asReader());
}

std::uint32_t run_id_of_cleared(logschema::Header::Reader cleared) {
  const kj::Array<capnp::word> canonical = capnp::canonicalize(cleared);
  Xxh3Hash hash;
  hash.update(canonical.begin(), canonical.size() * sizeof(capnp::word));
  const auto id = std::uint32_t(std::stoul(hash.hex().substr(0, 8), nullptr, 16));
  return id == 0 ? 1 : id;
}

namespace {
std::string hex_id(std::uint32_t id) {
  char text[11];
  std::snprintf(text, sizeof text, "%08lx", static_cast<unsigned long>(id));
  return text;
}
}  // namespace

Status check_run_id(const LogReader& log, std::uint32_t record_id, std::uint64_t offset, const char* what) {
  const std::uint32_t expected = log.header().run_id;
  if (expected == 0 || record_id == expected) return Ok{};
  return Error{log.path() + " (" + what + " at byte " + std::to_string(offset) + "): this record belongs to another run (run id " +
                   hex_id(record_id) + ", the header's is " + hex_id(expected) +
                   "): the file was put together from two logs. The records before it are this run's; "
                   "rerun the scene (or `ede-sim --resume` from an earlier keyframe) to get a whole log",
               ErrorKind::Corrupt};
}

}  // namespace ede
