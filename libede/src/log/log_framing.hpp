// The framing of an event log: file header, record headers, trailer (schema/FORMAT.md).
//
// Fixed-size, little-endian, uncompressed, each protected by a CRC-32, so a reader can walk the records
// without decompressing anything, rebuild the index of a log whose writer was killed, and refuse a
// corrupted size or offset before it allocates or seeks. Encoding and decoding are explicit byte by byte:
// no struct is written with memcpy (padding and endianness stay out of the format).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace ede::logfmt {

constexpr std::uint32_t kFormatVersion = 2;       // what the writer writes by default
constexpr std::uint32_t kNewestFormatVersion = 3;  // the newest a reader reads: 2 plus step and thermostat events
constexpr std::uint32_t kOldestFormatVersion = 1;  // the oldest a reader reads
// Like PNG's: a non-ASCII first byte, and CR LF / SUB / LF to catch text-mode transfers.
constexpr std::array<unsigned char, 8> kFileMagic = {0x89, 'E', 'D', 'E', '\r', '\n', 0x1A, '\n'};
constexpr std::array<unsigned char, 8> kTrailerMagic = {'E', 'D', 'E', '-', 'E', 'N', 'D', '\n'};
constexpr std::array<unsigned char, 4> kRecordMarker = {'E', 'D', 'E', 'R'};

constexpr std::size_t kFileHeaderSize = 16;
constexpr std::size_t kRecordHeaderSize = 56;
constexpr std::size_t kTrailerSize = 32;

// Limits a reader enforces before allocating: a payload larger than this is corruption, not data.
constexpr std::uint64_t kMaxPayloadBytes = std::uint64_t(1) << 31;     // compressed

enum class RecordKind : std::uint8_t { Header = 1, Chunk = 2, Keyframe = 3, Index = 4 };
const char* to_string(RecordKind kind);

struct RecordHeader {
  RecordKind kind = RecordKind::Header;
  std::uint64_t payload_size = 0;   // bytes of the zstd frame that follows
  std::uint64_t first_event = 0;    // chunk: its first event; keyframe: events before it
  std::uint64_t event_count = 0;    // chunk: its events; else 0
  double time_first = 0;            // chunk: first event's time; keyframe: its time (as double)
  double time_last = 0;             // chunk: last event's time; keyframe: its time
  bool resumable = false;           // keyframe taken at an engine rebuild
};

struct Trailer {
  std::uint64_t index_offset = 0;   // file offset of the Index record's header
  std::uint64_t trailer_offset = 0; // file offset of the trailer itself (= size of everything before it)
};

void encode_file_header(unsigned char out[kFileHeaderSize], std::uint32_t version = kFormatVersion);
// Empty if fine, else what is wrong (not an ede log, or a version this reader does not know).
std::string check_file_header(const unsigned char in[kFileHeaderSize], std::uint32_t& version);

void encode_record_header(const RecordHeader& h, unsigned char out[kRecordHeaderSize]);
std::optional<RecordHeader> decode_record_header(const unsigned char in[kRecordHeaderSize], std::string& why);

void encode_trailer(const Trailer& t, unsigned char out[kTrailerSize]);
std::optional<Trailer> decode_trailer(const unsigned char in[kTrailerSize]);

}  // namespace ede::logfmt
