// RecordWriter: compresses records with zstd and appends them to a log file, on a second thread.
//
// The event loop hands over a finished message (a keyframe), or a function that builds one (a chunk,
// whose columns are coded on the worker: log_writer.cpp), and goes on simulating; one worker builds,
// compresses and writes records strictly in the order they were submitted, with fixed zstd parameters
// (single-threaded frames, checksum and content size on), so the bytes never depend on timing. Each
// record is written with one write(2) of header + payload, except a large one (a keyframe or the header at
// large N), whose compressed size is learnt by compressing it once without keeping the output, then header
// and payload written as zstd makes it, 1 MiB at a time: either way a run killed at any moment leaves
// whole records followed by at most one cut record, which readers detect. The queue is bounded (the event
// loop waits if the worker falls behind), so memory stays bounded. I/O errors are latched and reported by
// finish() and error(): the event loop is never interrupted by an exception. The file is locked (flock,
// exclusive) from open to close, so a second writer of the same path is refused; the lock dies with the
// process, so a killed run's log can be resumed at once. Resumable keyframes are fdatasync'ed, and the
// file is fsync'ed before close; every write, sync and close is checked and its error names the file.
// Rejected: write-to-temporary-then-rename for the log: ede-sim --resume continues the log in place, so a
// killed run's records must be at the path the user gave (a temporary would hide them under another name).
// A record's content is a flat Cap'n Proto message (FlatMessage: log/flat_message.hpp), moved in, never
// copied; a small record's compressed output buffer is not zero-filled (only the pages zstd writes are
// touched), and the content is freed before the write. Rejected for large records: writing the payload
// first and its header last (pwrite into a hole): a kill between them leaves a zeroed header, which
// readers rightly call damage, not a cut; and compressing with a buffered input (ZSTD_compressStream2
// without ZSTD_c_stableInBuffer: measured, another frame than ZSTD_compress2's for a 44 MB keyframe).
// Rejected: compressing on the simulation thread (measured: zstd at level 3 costs as much per event as
// the simulation at small N) and zstd's own multi-threading (its output depends on the job split).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "log/log_framing.hpp"
#include "log/flat_message.hpp"

namespace ede {

class RecordWriter {
 public:
  // Opens `path` for writing from `start_offset` (0: a new file, truncated; else an existing file cut
  // there, for resuming). Check error() after construction.
  // `two_pass_above`: a record whose zstd bound exceeds this is compressed twice instead of held compressed
  // (write_two_pass; the same bytes).
  static constexpr std::size_t kTwoPassAbove = std::size_t(8) << 20;
  RecordWriter(const std::string& path, std::uint64_t start_offset, int zstd_level,
               std::size_t two_pass_above = kTwoPassAbove);
  ~RecordWriter();
  RecordWriter(const RecordWriter&) = delete;
  RecordWriter& operator=(const RecordWriter&) = delete;

  // Raw bytes written before any record (the file header).
  void write_raw(std::vector<unsigned char> bytes);
  // Queues a record; `header.payload_size` is filled in by the worker. Returns the record's sequence
  // number (0, 1, ... in submission order); its file offset is known once flush() returned.
  std::size_t submit(logfmt::RecordHeader header, FlatMessage content);
  // Queues a record whose content `build` makes on the worker, after every record submitted before it
  // was built (so a builder may keep state from one call to the next: it runs in submission order).
  using Builder = std::function<FlatMessage()>;
  std::size_t submit_built(logfmt::RecordHeader header, Builder build);
  // Called on the worker with the content of each built record once it is compressed, instead of freeing
  // it (the chunk coder reuses its block). Set before the first submit_built.
  using Recycler = std::function<void(FlatMessage&&)>;
  void set_recycler(Recycler recycle) { recycle_ = std::move(recycle); }
  // Waits until everything submitted is on disk.
  void flush();
  // File offset of the record with this sequence number (after flush()).
  std::uint64_t offset_of(std::size_t sequence) const;
  std::uint64_t end_offset();  // where the next record will go (flushes first)
  // Flushes, closes, and returns the first error, if any.
  std::string finish();
  std::string error();
  const std::string& path() const { return path_; }

 private:
  struct Job {
    bool raw;
    logfmt::RecordHeader header;
    std::vector<unsigned char> bytes;  // raw
    FlatMessage content;               // a record's
    Builder build;  // when set, makes `content` on the worker
  };
  void work();
  std::string write_job(Job& job);
  std::string write_two_pass(Job& job);

  std::string path_;  // for messages
  int fd_ = -1;
  int level_;
  std::size_t two_pass_above_;
  std::uint64_t offset_;
  std::thread worker_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::deque<Job> queue_;
  bool busy_ = false, stopping_ = false;
  std::vector<std::uint64_t> offsets_;  // per record, in submission order
  std::size_t submitted_ = 0;
  std::string error_;
  void* zstd_context_ = nullptr;
  Recycler recycle_;
  // The compressed output of a record written in one piece, kept from one record to the next (a new block
  // per chunk meant fresh pages, faulted in, for every chunk).
  static constexpr std::size_t kKeptOutput = std::size_t(1) << 20;
  std::unique_ptr<unsigned char[]> compressed_;
  std::size_t compressed_size_ = 0;
};

}  // namespace ede
