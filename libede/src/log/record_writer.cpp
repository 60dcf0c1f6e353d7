// RecordWriter; see record_writer.hpp.
#include "log/record_writer.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#define ZSTD_STATIC_LINKING_ONLY  // ZSTD_c_stableInBuffer (an experimental parameter of libzstd >= 1.4.5)
#include <zstd.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <new>

namespace ede {

namespace {
constexpr std::size_t kMaxQueued = 4;  // records waiting for the worker before the event loop waits
constexpr std::size_t kStreamPiece = std::size_t(1) << 20;  // write_two_pass's output buffer

std::string write_all(int fd, const unsigned char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return std::strerror(errno);
    }
    p += w;
    n -= std::size_t(w);
  }
  return {};
}
}  // namespace

RecordWriter::RecordWriter(const std::string& path, std::uint64_t start_offset, int zstd_level,
                           std::size_t two_pass_above)
    : path_(path), level_(zstd_level), two_pass_above_(two_pass_above), offset_(start_offset) {
  // Opened without O_TRUNC and locked before anything is cut: a second writer of the same path (another
  // ede-sim -o, a --resume of a log still being written) is refused without touching the first's bytes.
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    error_ = "cannot open '" + path + "' for writing: " + std::strerror(errno);
    return;
  }
  struct stat st {};
  if (::fstat(fd_, &st) == 0 && !S_ISREG(st.st_mode)) {
    error_ = "cannot write the log to '" + path +
             "': it is not a regular file (a device or a pipe); a log must be a file, which ede-sim --resume and "
             "the readers read back. Fix: give a file name.";
    ::close(fd_);
    fd_ = -1;
    return;
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    error_ = err == EWOULDBLOCK
                 ? "'" + path + "' is being written by another process (an ede-sim holds its lock) or read by "
                   "another ede tool: a log is written by one run and replaced by none while it is read. Fix: give "
                   "this run another -o, or wait for the other to finish."
                 : "cannot lock '" + path + "' for writing: " + std::strerror(err);
    ::close(fd_);
    fd_ = -1;
    return;
  }
  if (::ftruncate(fd_, off_t(start_offset)) != 0 || ::lseek(fd_, off_t(start_offset), SEEK_SET) < 0) {
    error_ = "cannot cut '" + path + "' at byte " + std::to_string(start_offset) + ": " + std::strerror(errno);
    return;
  }
  ZSTD_CCtx* cctx = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(cctx, ZSTD_c_compressionLevel, level_);
  ZSTD_CCtx_setParameter(cctx, ZSTD_c_checksumFlag, 1);
  ZSTD_CCtx_setParameter(cctx, ZSTD_c_contentSizeFlag, 1);
  // write_two_pass compresses a whole record in pieces: with a stable input zstd reads the record where it
  // is, as ZSTD_compress2 does, and makes the same frame (buffering the input instead gives other bytes).
  ZSTD_CCtx_setParameter(cctx, ZSTD_c_stableInBuffer, 1);
  zstd_context_ = cctx;
  worker_ = std::thread([this] { work(); });
}

RecordWriter::~RecordWriter() { finish(); }

void RecordWriter::write_raw(std::vector<unsigned char> bytes) {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return queue_.size() < kMaxQueued; });
  queue_.push_back(Job{true, {}, std::move(bytes), {}, {}});
  wake_.notify_one();
}

std::size_t RecordWriter::submit(logfmt::RecordHeader header, FlatMessage content) {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return queue_.size() < kMaxQueued; });
  queue_.push_back(Job{false, header, {}, std::move(content), {}});
  wake_.notify_one();
  return submitted_++;
}

std::size_t RecordWriter::submit_built(logfmt::RecordHeader header, Builder build) {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return queue_.size() < kMaxQueued; });
  queue_.push_back(Job{false, header, {}, {}, std::move(build)});
  wake_.notify_one();
  return submitted_++;
}

void RecordWriter::flush() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return queue_.empty() && !busy_; });
}

std::uint64_t RecordWriter::offset_of(std::size_t sequence) const {
  std::lock_guard lock(mutex_);
  return sequence < offsets_.size() ? offsets_[sequence] : 0;
}

std::uint64_t RecordWriter::end_offset() {
  flush();
  std::lock_guard lock(mutex_);
  return offset_;
}

std::string RecordWriter::error() {
  std::lock_guard lock(mutex_);
  return error_;
}

std::string RecordWriter::finish() {
  if (worker_.joinable()) {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    worker_.join();
  }
  if (fd_ >= 0) {
    if (error_.empty() && ::fsync(fd_) != 0) error_ = "syncing '" + path_ + "' to disk: " + std::strerror(errno);
    if (::close(fd_) != 0 && error_.empty()) error_ = "closing '" + path_ + "': " + std::strerror(errno);
    fd_ = -1;
  }
  if (zstd_context_) {
    ZSTD_freeCCtx(static_cast<ZSTD_CCtx*>(zstd_context_));
    zstd_context_ = nullptr;
  }
  return error_;
}

void RecordWriter::work() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;
      job = std::move(queue_.front());
      queue_.pop_front();
      busy_ = true;
    }
    const std::uint64_t at = offset_;
    std::string problem;
    if (error_.empty()) try {
        problem = write_job(job);
      } catch (const std::bad_alloc&) {
        problem = "out of memory while compressing a record of '" + path_ + "' (" +
                  std::to_string(job.content.size()) + " bytes)";
      }
    {
      std::lock_guard lock(mutex_);
      if (!job.raw) offsets_.push_back(at);
      if (!problem.empty() && error_.empty()) error_ = problem;
      busy_ = false;
    }
    idle_.notify_all();
  }
}

// Runs on the worker: compress, frame, write. Touches offset_ and the zstd context only here.
std::string RecordWriter::write_job(Job& job) {
  if (job.raw) {
    const std::string e = write_all(fd_, job.bytes.data(), job.bytes.size());
    offset_ += job.bytes.size();
    return e.empty() ? e : "writing '" + path_ + "': " + e;
  }
  const bool built = bool(job.build);
  if (built) {
    job.content = job.build();
    job.build = nullptr;  // frees the chunk's events now
  }
  auto* cctx = static_cast<ZSTD_CCtx*>(zstd_context_);
  const std::size_t size = job.content.size();
  const std::size_t bound = ZSTD_compressBound(size);
  if (bound > two_pass_above_) {
    if (std::string e = write_two_pass(job); !e.empty()) return e;
  } else {
    // A chunk's output block is kept for the next (compressed_); a larger record's is its own, freed after.
    const std::size_t need = logfmt::kRecordHeaderSize + bound;
    std::unique_ptr<unsigned char[]> own;
    if (need > kKeptOutput) {
      own.reset(new unsigned char[need]);  // not zero-filled
    } else if (compressed_size_ < need) {
      compressed_.reset();
      compressed_.reset(new unsigned char[kKeptOutput]);
      compressed_size_ = kKeptOutput;
    }
    unsigned char* const out = own ? own.get() : compressed_.get();
    const std::size_t n = ZSTD_compress2(cctx, out + logfmt::kRecordHeaderSize, bound, job.content.data(), size);
    if (built && recycle_)
      recycle_(std::move(job.content));
    else
      job.content.release();  // freed before the write
    if (ZSTD_isError(n)) return std::string("compressing a log record: ") + ZSTD_getErrorName(n);
    job.header.payload_size = n;
    logfmt::encode_record_header(job.header, out);
    const std::string e = write_all(fd_, out, logfmt::kRecordHeaderSize + n);
    offset_ += logfmt::kRecordHeaderSize + n;
    if (!e.empty()) return "writing '" + path_ + "': " + e;
  }
  // A resumable keyframe is where ede-sim --resume restarts: make it durable (a kill needs no sync, the
  // page cache survives it; a power cut does not). Once per keyframe, on this thread: the run never waits.
  if (job.header.resumable && ::fdatasync(fd_) != 0) return "syncing '" + path_ + "' to disk: " + std::strerror(errno);
  return {};
}

// Compresses the record's content whole (ZSTD_e_end, the input stable: ZSTD_compress2's frame) into a
// piece buffer, `sink` taking each piece; returns the frame's size, or 0 with `error` set.
namespace {
template <class Sink>
std::size_t compress_in_pieces(ZSTD_CCtx* cctx, const FlatMessage& content, unsigned char* piece, Sink&& sink,
                               std::string& error) {
  ZSTD_inBuffer in{content.data(), content.size(), 0};
  std::size_t total = 0;
  for (;;) {
    ZSTD_outBuffer out{piece, kStreamPiece, 0};
    const std::size_t left = ZSTD_compressStream2(cctx, &out, &in, ZSTD_e_end);
    if (ZSTD_isError(left)) {
      ZSTD_CCtx_reset(cctx, ZSTD_reset_session_only);
      error = std::string("compressing a log record: ") + ZSTD_getErrorName(left);
      return 0;
    }
    if (!sink(piece, out.pos)) return 0;
    total += out.pos;
    if (left == 0) return total;
  }
}
}  // namespace

// A large record (a keyframe or header at large N) is compressed twice, in 1 MiB pieces: first only to
// learn its compressed size, which its header holds; then header and pieces are written as they come.
// The compressed record is never held whole (at N = 10^6 a keyframe's is ~25 MB), at the price of
// compressing it twice on this thread. A kill between the writes leaves a header whose payload is cut
// short, which readers take for a cut record, as they do a write(2) cut short.
std::string RecordWriter::write_two_pass(Job& job) {
  auto* cctx = static_cast<ZSTD_CCtx*>(zstd_context_);
  const std::unique_ptr<unsigned char[]> piece(new unsigned char[kStreamPiece]);
  std::string error;
  const std::size_t n = compress_in_pieces(cctx, job.content, piece.get(), [](const unsigned char*, std::size_t) { return true; }, error);
  if (n == 0) return error;
  job.header.payload_size = n;
  unsigned char header[logfmt::kRecordHeaderSize];
  logfmt::encode_record_header(job.header, header);
  std::string e = write_all(fd_, header, sizeof header);
  std::uint64_t written = e.empty() ? sizeof header : 0;
  const std::size_t again = e.empty() ? compress_in_pieces(cctx, job.content, piece.get(),
                                                             [&](const unsigned char* p, std::size_t k) {
                                                               e = write_all(fd_, p, k);
                                                               written += e.empty() ? k : 0;
                                                               return e.empty();
                                                             },
                                                             error)
                                      : 0;
  offset_ += written;
  job.content.release();
  if (!e.empty()) return "writing '" + path_ + "': " + e;
  if (again != n) return error.empty() ? "compressing a log record: the second pass made another size" : error;
  return {};
}

}  // namespace ede
