// log_column_sizes; see ede/log_column_sizes.hpp.
#include <capnp/serialize.h>
#include <kj/exception.h>
#include <zstd.h>

#include <memory>

#include "log/run_id.hpp"
#include "log/log_column_sizes.hpp"
#include "ede_log.capnp.h"
#include "log/log_messages.hpp"

namespace ede {

namespace {

constexpr const char* kColumnNames[] = {"times", "kinds", "disks", "partners", "velocitiesRaw", "velocityResiduals"};
constexpr std::size_t kColumns = sizeof kColumnNames / sizeof kColumnNames[0];

struct ContextDeleter {
  void operator()(ZSTD_CCtx* c) const { ZSTD_freeCCtx(c); }
};

Result<std::uint64_t> compressed_size(ZSTD_CCtx* cctx, const capnp::Data::Reader& d) {
  if (d.size() == 0) return std::uint64_t(0);
  std::vector<unsigned char> out(ZSTD_compressBound(d.size()));
  const std::size_t n = ZSTD_compress2(cctx, out.data(), out.size(), d.begin(), d.size());
  if (ZSTD_isError(n)) return Error{std::string("compressing a column: ") + ZSTD_getErrorName(n)};
  return std::uint64_t(n);
}

Status add_chunk(const LogReader& log, const LogRecordRef& ref, ZSTD_CCtx* cctx, LogColumnSizes& out) {
  auto words = log.load_message(ref.offset, ref.payload_size);
  if (!words) return words.error();
  try {
    capnp::FlatArrayMessageReader message(as_words(words.value()), reader_options(words.value()));
    const auto chunk = message.getRoot<logschema::Chunk>();
    if (Status s = check_run_id(log, chunk.getRunId(), ref.offset, "chunk"); !s) return s;
    const capnp::Data::Reader cols[kColumns] = {chunk.getTimes(),         chunk.getKinds(),
                                                chunk.getDisks(),         chunk.getPartners(),
                                                chunk.getVelocitiesRaw(), chunk.getVelocityResiduals()};
    for (std::size_t c = 0; c < kColumns; ++c) {
      auto z = compressed_size(cctx, cols[c]);
      if (!z) return z.error();
      out.columns[c].bytes += cols[c].size();
      out.columns[c].compressed += z.value();
    }
  } catch (const kj::Exception& e) {
    return Error{log.path() + " (chunk at byte " + std::to_string(ref.offset) + "): malformed (" +
                 e.getDescription().cStr() + ")"};
  }
  out.chunks += 1;
  out.events += ref.count;
  out.payload += ref.payload_size;
  out.message += words.value().size() * 8;
  return Ok{};
}

}  // namespace

Result<LogColumnSizes> log_column_sizes(const LogReader& log, int zstd_level, std::size_t max_chunks) {
  LogColumnSizes out;
  for (const char* name : kColumnNames) out.columns.push_back({name, 0, 0});
  std::unique_ptr<ZSTD_CCtx, ContextDeleter> cctx(ZSTD_createCCtx());
  if (!cctx) return Error{"cannot create a zstd context"};
  ZSTD_CCtx_setParameter(cctx.get(), ZSTD_c_compressionLevel, zstd_level);
  const auto& chunks = log.chunks();
  const std::size_t total = chunks.size();
  const std::size_t take = max_chunks == 0 || max_chunks > total ? total : max_chunks;
  for (std::size_t k = 0; k < take; ++k) {
    const std::size_t c = take == total ? k : k * total / take;
    if (Status s = add_chunk(log, chunks[c], cctx.get(), out); !s) return s.error();
  }
  return out;
}

}  // namespace ede
