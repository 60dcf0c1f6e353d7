// Encoding and checking the log's fixed-size framing; see log_framing.hpp and schema/FORMAT.md.
#include "log/log_framing.hpp"

#include <cstring>

#include "core/crc32.hpp"

namespace ede::logfmt {

namespace {

void put_u32(unsigned char* p, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) p[k] = static_cast<unsigned char>(v >> (8 * k));
}
void put_u64(unsigned char* p, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) p[k] = static_cast<unsigned char>(v >> (8 * k));
}
std::uint32_t get_u32(const unsigned char* p) {
  std::uint32_t v = 0;
  for (int k = 0; k < 4; ++k) v |= std::uint32_t(p[k]) << (8 * k);
  return v;
}
std::uint64_t get_u64(const unsigned char* p) {
  std::uint64_t v = 0;
  for (int k = 0; k < 8; ++k) v |= std::uint64_t(p[k]) << (8 * k);
  return v;
}
void put_f64(unsigned char* p, double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, 8);
  put_u64(p, bits);
}
double get_f64(const unsigned char* p) {
  const std::uint64_t bits = get_u64(p);
  double v;
  std::memcpy(&v, &bits, 8);
  return v;
}

}  // namespace

const char* to_string(RecordKind kind) {
  switch (kind) {
    case RecordKind::Header: return "header";
    case RecordKind::Chunk: return "chunk";
    case RecordKind::Keyframe: return "keyframe";
    case RecordKind::Index: return "index";
  }
  return "unknown";
}

void encode_file_header(unsigned char out[kFileHeaderSize], std::uint32_t version) {
  std::memcpy(out, kFileMagic.data(), 8);
  put_u32(out + 8, version);
  put_u32(out + 12, 0);
}

std::string check_file_header(const unsigned char in[kFileHeaderSize], std::uint32_t& version) {
  if (std::memcmp(in, kFileMagic.data(), 8) != 0) return "not an ede event log (wrong magic number)";
  version = get_u32(in + 8);
  if (version < kOldestFormatVersion || version > kNewestFormatVersion)
    return "log format version " + std::to_string(version) + ", but this ede reads versions " +
           std::to_string(kOldestFormatVersion) + " to " + std::to_string(kNewestFormatVersion) +
           "; use the ede version that wrote it (or a newer one)";
  return {};
}

// Layout: marker(4) kind(1) zero(3) payload_size(8) first_event(8) event_count(8) time_first(8)
// time_last(8) flags(4) crc32 of the 52 bytes before it(4).
void encode_record_header(const RecordHeader& h, unsigned char out[kRecordHeaderSize]) {
  std::memset(out, 0, kRecordHeaderSize);
  std::memcpy(out, kRecordMarker.data(), 4);
  out[4] = static_cast<unsigned char>(h.kind);
  put_u64(out + 8, h.payload_size);
  put_u64(out + 16, h.first_event);
  put_u64(out + 24, h.event_count);
  put_f64(out + 32, h.time_first);
  put_f64(out + 40, h.time_last);
  put_u32(out + 48, h.resumable ? 1u : 0u);
  put_u32(out + 52, crc32(out, 52));
}

std::optional<RecordHeader> decode_record_header(const unsigned char in[kRecordHeaderSize], std::string& why) {
  if (std::memcmp(in, kRecordMarker.data(), 4) != 0) {
    why = "no record marker";
    return std::nullopt;
  }
  if (get_u32(in + 52) != crc32(in, 52)) {
    why = "record header checksum mismatch";
    return std::nullopt;
  }
  RecordHeader h;
  const unsigned kind = in[4];
  if (kind < 1 || kind > 4) {
    why = "unknown record kind " + std::to_string(kind);
    return std::nullopt;
  }
  h.kind = static_cast<RecordKind>(kind);
  h.payload_size = get_u64(in + 8);
  h.first_event = get_u64(in + 16);
  h.event_count = get_u64(in + 24);
  h.time_first = get_f64(in + 32);
  h.time_last = get_f64(in + 40);
  h.resumable = (get_u32(in + 48) & 1u) != 0;
  if (h.payload_size == 0 || h.payload_size > kMaxPayloadBytes) {
    why = "implausible payload size " + std::to_string(h.payload_size);
    return std::nullopt;
  }
  return h;
}

// Layout: index_offset(8) trailer_offset(8) crc32 of the 16 bytes before it(4) zero(4) magic(8).
void encode_trailer(const Trailer& t, unsigned char out[kTrailerSize]) {
  std::memset(out, 0, kTrailerSize);
  put_u64(out, t.index_offset);
  put_u64(out + 8, t.trailer_offset);
  put_u32(out + 16, crc32(out, 16));
  std::memcpy(out + 24, kTrailerMagic.data(), 8);
}

std::optional<Trailer> decode_trailer(const unsigned char in[kTrailerSize]) {
  if (std::memcmp(in + 24, kTrailerMagic.data(), 8) != 0) return std::nullopt;
  if (get_u32(in + 16) != crc32(in, 16)) return std::nullopt;
  return Trailer{get_u64(in), get_u64(in + 8)};
}

}  // namespace ede::logfmt
