// LogReader; see log_reader.hpp and schema/FORMAT.md.
#include "log/log_reader.hpp"

#include <capnp/serialize.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#define ZSTD_STATIC_LINKING_ONLY  // ZSTD_estimateDStreamSize_fromFrame, for an out-of-memory message
#include <zstd.h>
#include <zstd_errors.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <kj/exception.h>

#include "ede_log.capnp.h"
#include "log/log_framing.hpp"
#include "log/log_messages.hpp"

namespace ede {

namespace {

constexpr std::uint64_t kInitialBuffer = std::uint64_t(1) << 20;  // decompression starts with 1 MiB

std::string at(const std::string& path, std::uint64_t offset) {
  return path + " (byte " + std::to_string(offset) + ")";
}

std::string mib_text(double bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g MiB", bytes / 1048576);
  return b;
}

// Running out of memory while reading a record is not damage: said as such, with what it needed. Without
// this a zstd allocation failure read "corrupted record (Allocation error: not enough memory)".
Error out_of_memory(const std::string& path, std::uint64_t offset, std::uint64_t payload, std::uint64_t content,
                    std::size_t decoder) {
  std::string need = mib_text(double(payload)) + " compressed";
  if (content) need += ", " + mib_text(double(content)) + " decompressed";
  if (decoder) need += ", " + mib_text(double(decoder)) + " for zstd's decoder";
  return Error{at(path, offset) + ": out of memory while reading this record (" + need +
                   ", on top of what the process holds): the log is not damaged, the memory left is too small "
                   "(ulimit -v or the machine's). Fix: raise the limit or free memory, then read the log again.",
               ErrorKind::Io};
}

bool read_exact(int fd, std::uint64_t offset, void* out, std::size_t n) {
  auto* p = static_cast<unsigned char*>(out);
  while (n > 0) {
    const ssize_t r = ::pread(fd, p, n, off_t(offset));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r;
    offset += std::uint64_t(r);
    n -= std::size_t(r);
  }
  return true;
}

std::size_t scalar_width(ScalarKind s) { return s == ScalarKind::Float ? 4 : s == ScalarKind::Double ? 8 : 10; }

}  // namespace

LogReader::~LogReader() {
  if (fd_ >= 0) ::close(fd_);
}

Result<std::shared_ptr<LogReader>> LogReader::open(const std::string& path, const ReadLimits& limits) {
  std::shared_ptr<LogReader> r(new LogReader());
  r->path_ = path;
  r->limits_ = limits;
  r->fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (r->fd_ < 0) return Error{"cannot open '" + path + "': " + std::strerror(errno), ErrorKind::Io};
  struct stat st{};
  if (::fstat(r->fd_, &st) != 0) return Error{"cannot read '" + path + "': " + std::strerror(errno), ErrorKind::Io};
  r->file_size_ = std::uint64_t(st.st_size);
  unsigned char head[logfmt::kFileHeaderSize];
  if (r->file_size_ < logfmt::kFileHeaderSize || !read_exact(r->fd_, 0, head, sizeof head))
    return Error{path + ": too short to be an ede event log (" + std::to_string(r->file_size_) + " bytes)", ErrorKind::Corrupt};
  std::uint32_t version = 0;
  // check_file_header reads the version only once the magic number matched: a version it then refuses is
  // a log of another format version (Unsupported), anything else is not a log at all (Corrupt).
  if (std::string why = logfmt::check_file_header(head, version); !why.empty())
    return Error{path + ": " + why, version != 0 ? ErrorKind::Unsupported : ErrorKind::Corrupt};

  // The header record comes first; without it nothing else can be read.
  const std::uint64_t first = logfmt::kFileHeaderSize;
  unsigned char rh_bytes[logfmt::kRecordHeaderSize];
  if (r->file_size_ < first + sizeof rh_bytes || !read_exact(r->fd_, first, rh_bytes, sizeof rh_bytes))
    return Error{at(path, first) + ": the log ends before its header record (the run was killed at once?)", ErrorKind::Corrupt};
  std::string why;
  const auto rh = logfmt::decode_record_header(rh_bytes, why);
  if (!rh || rh->kind != logfmt::RecordKind::Header)
    return Error{at(path, first) + ": the first record is not a valid header" + (why.empty() ? "" : ": " + why), ErrorKind::Corrupt};
  if (first + sizeof rh_bytes + rh->payload_size > r->file_size_)
    return Error{at(path, first) + ": the header record is cut short", ErrorKind::Corrupt};
  r->header_.format_version = version;
  if (Status s = r->read_header_record(first, rh->payload_size); !s) return s.error();
  r->header_record_end_ = first + sizeof rh_bytes + rh->payload_size;

  // Complete logs end with a trailer pointing to the index; otherwise (or if it is damaged) walk the records.
  std::string index_problem = "no trailer: the run did not finish (killed, or still running)";
  if (r->file_size_ >= r->header_record_end_ + logfmt::kTrailerSize) {
    unsigned char tr[logfmt::kTrailerSize];
    if (read_exact(r->fd_, r->file_size_ - sizeof tr, tr, sizeof tr)) {
      const auto trailer = logfmt::decode_trailer(tr);
      if (trailer && trailer->trailer_offset == r->file_size_ - sizeof tr &&
          trailer->index_offset >= r->header_record_end_ && trailer->index_offset < trailer->trailer_offset) {
        const Status s = r->read_index(trailer->index_offset);
        if (s) {
          r->complete_ = true;
          return r;
        }
        index_problem = "the index is damaged (" + s.error().message + ")";
        r->damaged_ = true;
      } else if (trailer) {
        index_problem = "the trailer points outside the file";
        r->damaged_ = true;
      } else if (std::memcmp(tr + 24, logfmt::kTrailerMagic.data(), 8) == 0) {
        index_problem = "the trailer is damaged";
        r->damaged_ = true;
      }
    }
  }
  r->chunks_.clear();
  r->keyframes_.clear();
  if (Status s = r->scan_records(r->header_record_end_); !s) return s.error();
  r->incomplete_reason_ = index_problem + "; " + r->incomplete_reason_;
  return r;
}

Result<MessageWords> LogReader::load_message(std::uint64_t offset, std::uint64_t payload_size) const {
  std::uint64_t content = 0;
  std::size_t decoder = 0;
  try {
    return decompress_record(offset, payload_size, content, decoder);
  } catch (const std::bad_alloc&) {
    return out_of_memory(path_, offset, payload_size, content, decoder);
  }
}

// load_message's work; `content` and `decoder` are set as soon as they are known, for its message.
Result<MessageWords> LogReader::decompress_record(std::uint64_t offset, std::uint64_t payload_size,
                                                  std::uint64_t& content, std::size_t& decoder) const {
  const std::uint64_t start = offset + logfmt::kRecordHeaderSize;
  if (payload_size == 0 || payload_size > logfmt::kMaxPayloadBytes || start + payload_size > file_size_)
    return Error{at(path_, offset) + ": record payload outside the file", ErrorKind::Corrupt};
  unsigned char head[ZSTD_FRAMEHEADERSIZE_MAX];  // the declared size, for the message if the buffers do not fit
  const std::size_t head_size = std::size_t(std::min<std::uint64_t>(payload_size, sizeof head));
  if (read_exact(fd_, start, head, head_size)) {
    const unsigned long long declared = ZSTD_getFrameContentSize(head, head_size);
    if (declared != ZSTD_CONTENTSIZE_ERROR && declared != ZSTD_CONTENTSIZE_UNKNOWN) content = declared;
  }
  std::vector<unsigned char> compressed(payload_size);
  if (!read_exact(fd_, start, compressed.data(), compressed.size()))
    return Error{at(path_, offset) + ": cannot read the record", ErrorKind::Corrupt};
  content = ZSTD_getFrameContentSize(compressed.data(), compressed.size());
  if (content == ZSTD_CONTENTSIZE_ERROR || content == ZSTD_CONTENTSIZE_UNKNOWN)
    return Error{at(path_, offset) + ": the record is not a zstd frame with a declared size", ErrorKind::Corrupt};
  if (content == 0 || content > limits_.max_record_bytes || content % 8 != 0)
    return Error{at(path_, offset) + ": implausible record size " + std::to_string(content) + " bytes (limit " +
                 std::to_string(limits_.max_record_bytes) + ")"};
  if (ZSTD_findFrameCompressedSize(compressed.data(), compressed.size()) != payload_size)
    return Error{at(path_, offset) + ": the zstd frame does not fill its record", ErrorKind::Corrupt};
  // Streamed into a buffer that grows only as output arrives: a corrupted declared size cannot make us
  // allocate gigabytes up front; the output must then match the declared size exactly.
  decoder = ZSTD_estimateDStreamSize_fromFrame(compressed.data(), compressed.size());
  if (ZSTD_isError(decoder)) decoder = 0;
  MessageWords words(std::min<std::uint64_t>(content, kInitialBuffer) / 8);
  ZSTD_DStream* stream = ZSTD_createDStream();
  if (!stream) throw std::bad_alloc();
  ZSTD_initDStream(stream);
  ZSTD_inBuffer in{compressed.data(), compressed.size(), 0};
  std::size_t produced = 0;
  std::string problem;
  for (;;) {
    if (produced == words.size() * 8) {
      if (produced >= content) {
        problem = "the record decompresses to more than its declared size";
        break;
      }
      try {
        words.resize(std::min<std::uint64_t>(content, 2 * produced) / 8);
      } catch (const std::bad_alloc&) {
        ZSTD_freeDStream(stream);
        throw;
      }
    }
    ZSTD_outBuffer out{words.data(), words.size() * 8, produced};
    const std::size_t r = ZSTD_decompressStream(stream, &out, &in);
    produced = out.pos;
    if (ZSTD_isError(r) && ZSTD_getErrorCode(r) == ZSTD_error_memory_allocation) {
      ZSTD_freeDStream(stream);
      throw std::bad_alloc();
    }
    if (ZSTD_isError(r)) {
      problem = std::string("corrupted record (") + ZSTD_getErrorName(r) + ")";
      break;
    }
    if (r == 0) break;  // the frame is complete and its checksum verified
    if (in.pos == in.size && out.pos < out.size) {
      problem = "the record's zstd frame is cut short";
      break;
    }
  }
  ZSTD_freeDStream(stream);
  if (problem.empty() && produced != content) problem = "the record decompresses to the wrong size";
  if (!problem.empty()) return Error{at(path_, offset) + ": " + problem, ErrorKind::Corrupt};
  return words;
}

Status LogReader::read_header_record(std::uint64_t offset, std::uint64_t payload_size) {
  auto words = load_message(offset, payload_size);
  if (!words) return words.error();
  try {
    capnp::FlatArrayMessageReader message(as_words(words.value()), reader_options(words.value()));
    const auto h = message.getRoot<logschema::Header>();
    LogHeaderInfo& out = header_;
    out.engine_version = h.getEngineVersion();
    out.compiler = h.getCompiler();
    out.compile_flags = h.getCompileFlags();
    switch (h.getScalar()) {
      case logschema::ScalarType::FLOAT32: out.scalar = ScalarKind::Float; break;
      case logschema::ScalarType::FLOAT64: out.scalar = ScalarKind::Double; break;
      case logschema::ScalarType::FLOAT80: out.scalar = ScalarKind::LongDouble; break;
      default: return Error{at(path_, offset) + ": unknown scalar type in the header", ErrorKind::Corrupt};
    }
    out.seed = h.getSeed();
    out.scene_name = h.getSceneName();
    out.scene_text = h.getSceneText();
    out.disks = h.getDiskCount();
    for (const auto name : h.getSpeciesNames()) out.species_names.emplace_back(name);
    out.lx = h.getBoxX();
    out.ly = h.getBoxY();
    out.lees_edwards = h.getBoundary() == logschema::Boundary::LEES_EDWARDS;
    out.boundary = h.getBoundary() == logschema::Boundary::PERIODIC || out.lees_edwards ? BoundaryKind::Periodic
                                                                                         : BoundaryKind::Walls;
    out.chunk_events = h.getChunkEvents();
    out.keyframe_interval = h.getKeyframeInterval();
    out.rebuild_interval = h.getRebuildInterval();
    out.run_id = h.getRunId();
    const auto radius = h.getRadius(), mass = h.getMass();
    out.radius.assign(radius.begin(), radius.end());
    out.mass.assign(mass.begin(), mass.end());
    for (const std::uint32_t s : h.getSpecies()) out.species.push_back(s);
    out.initial_energy = h.getInitialEnergy();
    out.tc_model = h.getTcModel();
    out.gx = h.getGravityX();
    out.gy = h.getGravityY();
    out.column_encoding = h.getColumnEncoding();
    if (out.column_encoding != out.format_version)
      return Error{at(path_, offset) + ": chunk column encoding " + std::to_string(out.column_encoding) +
                   " in a format version " + std::to_string(out.format_version) + " log (this ede reads encoding " +
                   std::to_string(out.format_version) + " there)"};
    const auto xi = h.getPairOnePlusXi(), xw = h.getWallRestitution();
    out.pair_one_plus_xi.assign(xi.begin(), xi.end());
    out.wall_restitution.assign(xw.begin(), xw.end());
    const auto inertia = h.getInertia(), beta = h.getOnePlusBeta();
    out.inertia.assign(inertia.begin(), inertia.end());
    out.one_plus_beta.assign(beta.begin(), beta.end());
  } catch (const kj::Exception& e) {
    return Error{at(path_, offset) + ": malformed header record (" + e.getDescription().cStr() + ")", ErrorKind::Corrupt};
  }
  const LogHeaderInfo& h = header_;
  const std::size_t w = scalar_width(h.scalar);
  if (h.disks == 0 || h.disks > limits_.max_disks || h.radius.size() != std::size_t(h.disks) * w ||
      h.mass.size() != std::size_t(h.disks) * w || h.species.size() != h.disks)
    return Error{at(path_, offset) + ": the header's per-disk data does not match its disk count", ErrorKind::Corrupt};
  const std::size_t species = std::max<std::size_t>(1, h.species_names.size());
  // wallRestitution: the four box walls, then five scalars per wall segment (FORMAT.md).
  const bool walls_ok = h.wall_restitution.size() >= 4 * w && (h.wall_restitution.size() / w - 4) % 5 == 0 &&
                        h.wall_restitution.size() % w == 0;
  if (h.column_encoding >= 2 && (h.pair_one_plus_xi.size() != species * species * w || !walls_ok))
    return Error{at(path_, offset) + ": the header's restitution tables do not match its species count",
                 ErrorKind::Corrupt};
  if ((!h.inertia.empty() || !h.one_plus_beta.empty()) &&
      (h.column_encoding < 2 || h.inertia.size() != std::size_t(h.disks) * w ||
       h.one_plus_beta.size() != (species * species + 4) * w))
    return Error{at(path_, offset) + ": the header's rotation data (inertia, 1 + beta) does not match its disks and species",
                 ErrorKind::Corrupt};
  for (const std::uint32_t s : h.species)
    if (s >= h.species_names.size()) return Error{at(path_, offset) + ": a disk names a species that does not exist", ErrorKind::Corrupt};
  if (!(h.lx > 0) || !(h.ly > 0) || !std::isfinite(h.lx) || !std::isfinite(h.ly) || h.chunk_events == 0 ||
      !std::isfinite(h.gx) || !std::isfinite(h.gy))
    return Error{at(path_, offset) + ": the header's box or chunk size is invalid", ErrorKind::Corrupt};
  return Ok{};
}

// Every entry checked: inside the file, after the header, chunks contiguous in event numbering.
Status LogReader::read_index(std::uint64_t offset) {
  unsigned char rh_bytes[logfmt::kRecordHeaderSize];
  std::string why;
  if (!read_exact(fd_, offset, rh_bytes, sizeof rh_bytes)) return Error{"cannot read the index record", ErrorKind::Corrupt};
  const auto rh = logfmt::decode_record_header(rh_bytes, why);
  if (!rh || rh->kind != logfmt::RecordKind::Index) return Error{"no index record where the trailer points", ErrorKind::Corrupt};
  auto words = load_message(offset, rh->payload_size);
  if (!words) return words.error();
  try {
    capnp::FlatArrayMessageReader message(as_words(words.value()), reader_options(words.value()));
    const auto idx = message.getRoot<logschema::Index>();
    std::uint64_t next_event = 0;
    for (const auto e : idx.getEntries()) {
      LogRecordRef ref{e.getKind(), e.getOffset(), 0, e.getFirstEvent(), e.getCount(),
                       e.getTimeFirst(), e.getTimeLast(), e.getResumable()};
      if (ref.offset < header_record_end_ || ref.offset + logfmt::kRecordHeaderSize > offset)
        return Error{"an index entry points outside the records", ErrorKind::Corrupt};
      unsigned char entry_header[logfmt::kRecordHeaderSize];
      if (!read_exact(fd_, ref.offset, entry_header, sizeof entry_header)) return Error{"cannot read a record", ErrorKind::Corrupt};
      const auto h = logfmt::decode_record_header(entry_header, why);
      if (!h || std::uint8_t(h->kind) != ref.kind || h->first_event != ref.first_event)
        return Error{"an index entry does not match its record at byte " + std::to_string(ref.offset), ErrorKind::Corrupt};
      ref.payload_size = h->payload_size;
      if (ref.offset + logfmt::kRecordHeaderSize + ref.payload_size > offset)
        return Error{"a record overlaps the index", ErrorKind::Corrupt};
      if (ref.kind == std::uint8_t(logfmt::RecordKind::Chunk)) {
        if (ref.first_event != next_event || ref.count == 0 || ref.count > (1u << 24))
          return Error{"chunks are not contiguous at event " + std::to_string(next_event), ErrorKind::Corrupt};
        next_event += ref.count;
        chunks_.push_back(ref);
      } else if (ref.kind == std::uint8_t(logfmt::RecordKind::Keyframe)) {
        if (ref.first_event != next_event) return Error{"a keyframe is not at a chunk boundary", ErrorKind::Corrupt};
        keyframes_.push_back(ref);
      } else {
        return Error{"unknown record kind in the index", ErrorKind::Corrupt};
      }
    }
    if (idx.getTotalEvents() != next_event) return Error{"the index's event total does not match its chunks", ErrorKind::Corrupt};
    total_events_ = next_event;
    const auto ft = idx.getFinalTime();
    final_time_.assign(ft.begin(), ft.end());
    if (final_time_.size() != scalar_width(header_.scalar)) return Error{"the index's final time is malformed", ErrorKind::Corrupt};
    final_status_ = idx.getStatus();
  } catch (const kj::Exception& e) {
    return Error{std::string("malformed index (") + e.getDescription().cStr() + ")"};
  }
  if (keyframes_.empty() || keyframes_.front().first_event != 0) return Error{"the index lists no initial keyframe"};
  return Ok{};
}

// Walks record headers from `from`, keeping chunks and keyframes, until the file ends or a record is cut
// short or damaged: everything before that point is usable; incomplete_reason_ says where it stopped.
Status LogReader::scan_records(std::uint64_t from) {
  std::uint64_t offset = from, next_event = 0;
  std::string stop = "the last complete record ends at byte " + std::to_string(from);
  for (;;) {
    if (offset == file_size_) break;
    unsigned char rh_bytes[logfmt::kRecordHeaderSize];
    std::string why;
    if (file_size_ - offset < sizeof rh_bytes || !read_exact(fd_, offset, rh_bytes, sizeof rh_bytes)) {
      stop = "a record header is cut short at byte " + std::to_string(offset);
      break;
    }
    const auto h = logfmt::decode_record_header(rh_bytes, why);
    if (!h) {  // the writer writes whole headers: a full one that does not check out is damage
      stop = "damaged record header at byte " + std::to_string(offset) + " (" + why + ")";
      damaged_ = true;
      break;
    }
    if (h->payload_size > file_size_ - offset - sizeof rh_bytes) {
      stop = "the record at byte " + std::to_string(offset) + " is cut short";
      break;
    }
    LogRecordRef ref{std::uint8_t(h->kind), offset, h->payload_size, h->first_event, h->event_count,
                     h->time_first,         h->time_last, h->resumable};
    if (h->kind == logfmt::RecordKind::Chunk) {
      if (h->first_event != next_event || h->event_count == 0 || h->event_count > (1u << 24)) {
        stop = "a chunk out of sequence at byte " + std::to_string(offset);
        damaged_ = true;
        break;
      }
      next_event += h->event_count;
      chunks_.push_back(ref);
    } else if (h->kind == logfmt::RecordKind::Keyframe) {
      if (h->first_event != next_event) {
        stop = "a keyframe out of sequence at byte " + std::to_string(offset);
        damaged_ = true;
        break;
      }
      keyframes_.push_back(ref);
    } else {  // an index: the file was cut before its trailer (killed then), or something follows it (damage)
      const bool last = file_size_ - (offset + sizeof rh_bytes + h->payload_size) < logfmt::kTrailerSize;
      stop = last ? "the run was stopped after its index, before the trailer"
                  : "an unexpected " + std::string(logfmt::to_string(h->kind)) + " record at byte " + std::to_string(offset);
      damaged_ = !last;
      break;
    }
    offset += sizeof rh_bytes + h->payload_size;
    stop = "the last complete record ends at byte " + std::to_string(offset);
  }
  total_events_ = next_event;
  if (keyframes_.empty() || keyframes_.front().first_event != 0)
    return Error{path_ + ": the log holds no initial state (no keyframe was written before it ended: " + stop + ")"};
  incomplete_reason_ = "read up to event " + std::to_string(total_events_) + "; " + stop;
  return Ok{};
}

Result<std::size_t> LogReader::last_resumable_keyframe() const {
  for (std::size_t k = keyframes_.size(); k-- > 0;)
    if (keyframes_[k].resumable) return k;
  return Error{path_ + ": no resumable keyframe"};
}

}  // namespace ede
