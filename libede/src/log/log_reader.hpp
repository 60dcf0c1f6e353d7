// LogReader: opens an event log, checks it, and gives its header, index and records.
//
// Nothing in the file is trusted: the magic number and version are checked first (an unknown version is
// refused with a message saying so), every record header carries a CRC, every size is checked against the
// file before anything is allocated, Cap'n Proto reads run with traversal and nesting limits, and zstd
// frames carry checksums. A log whose writer was killed has no trailer: the reader then walks the records
// to rebuild the index, stops at the last complete one, and says the log is incomplete and how far it
// goes. Errors name the file and the byte offset.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "log/message_words.hpp"
#include "ede/scene.hpp"

namespace ede {

struct LogHeaderInfo {
  std::uint32_t format_version = 0;
  std::string engine_version, compiler, compile_flags;
  ScalarKind scalar = ScalarKind::Double;  // Float, Double or LongDouble: a log never holds Float128
  std::uint64_t seed = 0;
  std::string scene_name, scene_text;
  std::uint32_t disks = 0;
  std::vector<std::string> species_names;
  double lx = 1, ly = 1;
  BoundaryKind boundary = BoundaryKind::Walls;
  bool lees_edwards = false;  // format version 3: boundary Periodic with sliding images (the scene's shear rate)
  std::uint32_t chunk_events = 0;
  std::uint64_t keyframe_interval = 0, rebuild_interval = 0;
  std::uint32_t run_id = 0;  // log/run_id.hpp; 0: not recorded (older logs), records are not checked
  std::vector<unsigned char> radius, mass;  // raw scalars
  std::vector<std::uint32_t> species;
  double initial_energy = 0;
  bool tc_model = false;
  double gx = 0, gy = 0;  // gravity
  std::uint32_t column_encoding = 1;                   // 1 or 2: the format version's chunk columns
  std::vector<unsigned char> pair_one_plus_xi;         // version 2: S x S raw scalars (S species)
  std::vector<unsigned char> wall_restitution;         // version 2: 4 raw scalars, then 5 per segment
  // Rough runs only (FORMAT.md, "Rotation"; else both empty): I per disk (shuffled scalars), and S x S + 4
  // raw scalars 1 + beta (pairs, then the walls).
  std::vector<unsigned char> inertia, one_plus_beta;
  bool rotation() const { return !inertia.empty(); }
};

struct LogRecordRef {
  std::uint8_t kind = 0;          // 2 chunk, 3 keyframe
  std::uint64_t offset = 0;       // of the record header
  std::uint64_t payload_size = 0;
  std::uint64_t first_event = 0;  // chunk: first event; keyframe: events before it
  std::uint64_t count = 0;        // chunk: events
  double time_first = 0, time_last = 0;
  bool resumable = false;
};

// What a reader accepts before it allocates: a log claiming more is refused as implausible (the public
// ede::LogLimits says the same for ede::Log::open).
struct ReadLimits {
  std::uint32_t max_disks = 100000000;
  std::uint64_t max_record_bytes = std::uint64_t(1) << 31;  // one decompressed record
};

class LogReader {
 public:
  static Result<std::shared_ptr<LogReader>> open(const std::string& path, const ReadLimits& limits = {});
  ~LogReader();

  const std::string& path() const { return path_; }
  const LogHeaderInfo& header() const { return header_; }
  const std::vector<LogRecordRef>& chunks() const { return chunks_; }
  const std::vector<LogRecordRef>& keyframes() const { return keyframes_; }
  std::uint64_t total_events() const { return total_events_; }
  std::uint64_t file_size() const { return file_size_; }
  // Complete: closed by an index and trailer. Otherwise `incomplete_reason` says where reading stopped.
  bool complete() const { return complete_; }
  // Damaged: not merely cut short at the end (a killed run) but corrupted: a record header whose checksum
  // fails, a trailer whose index does not check out, bytes that are not records. What precedes the damage
  // is still readable; tools that vouch for a log (verify) must fail on it.
  bool damaged() const { return damaged_; }
  const std::string& incomplete_reason() const { return incomplete_reason_; }
  const std::string& final_status() const { return final_status_; }
  const std::vector<unsigned char>& final_time_bytes() const { return final_time_; }

  // The decompressed Cap'n Proto message of a record, checked: 8-byte words, the size the frame declares.
  // Too little memory for it is an Io error saying so and what the record needed, never "corrupted".
  Result<MessageWords> load_message(std::uint64_t offset, std::uint64_t payload_size) const;

  // Where the file can be cut to continue the run from its last resumable keyframe.
  Result<std::size_t> last_resumable_keyframe() const;

 private:
  LogReader() = default;
  Status read_header_record(std::uint64_t offset, std::uint64_t payload_size);
  Result<MessageWords> decompress_record(std::uint64_t offset, std::uint64_t payload_size, std::uint64_t& content,
                                         std::size_t& decoder) const;
  Status read_index(std::uint64_t offset);
  Status scan_records(std::uint64_t from);

  std::string path_;
  ReadLimits limits_;
  int fd_ = -1;
  std::uint64_t file_size_ = 0;
  LogHeaderInfo header_;
  std::vector<LogRecordRef> chunks_, keyframes_;
  std::uint64_t total_events_ = 0;
  bool complete_ = false;
  bool damaged_ = false;
  std::string incomplete_reason_, final_status_;
  std::vector<unsigned char> final_time_;
  std::uint64_t header_record_end_ = 0;
};

}  // namespace ede
