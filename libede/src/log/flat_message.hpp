// FlatMessageBuilder: a Cap'n Proto message built straight into the buffer the record writer compresses.
//
// The log's bytes are messageToFlatArray's of a MallocMessageBuilder (default: a first segment of 1024
// words, then segments growing heuristically, and a big column usually gets a segment of its own, reached
// by a far pointer): any other segmenting would change the log. capnp::messageToFlatArray copies such a
// message into a new array, and the log writer then copied that into a std::vector: for a keyframe at
// N = 10^6 two more copies of a 40-50 MB message next to the builder's segments (docs/performance.md,
// "Memory at 10⁶ with the log"). This builder hands out segments of exactly MallocMessageBuilder's sizes
// (so the message's layout, far pointers included, is the same), but carves them one after the other out
// of one zeroed reservation with room for the segment table in front; finish() writes the table and moves
// each segment's used words down against the previous one (the gaps are the segments' unused tails), and
// the reservation IS the flat array, byte for byte messageToFlatArray's, moved to the record writer without
// a copy. Large reservations are anonymous mappings (zero pages, resident only once written, the unused
// end given back), so reserving for the heuristic's growth costs address space, not memory. A message that
// outgrows the reservation gets its further segments from calloc and is flattened by messageToFlatArray
// (the same bytes, one copy): a wrong size estimate costs memory, never bytes.
// Rejected: MallocMessageBuilder with a caller-provided first segment (its destructor zeroes that
// segment, and the message's later segments are separate allocations anyway) and streaming the segments
// into zstd (the record's compressed size goes in its header, written with the payload in one write(2),
// so the compressed output would have to be held whole instead).
#pragma once

#include <capnp/message.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ede {

// Words a Data or List field of `bytes` bytes takes in a message (Cap'n Proto pads to whole words).
constexpr std::size_t message_words_of(std::size_t bytes) { return (bytes + 7) / 8; }

// A flat message (or raw bytes) in memory it owns: a mapping, a malloc'ed block, or nothing. Move-only.
class FlatMessage {
 public:
  FlatMessage() = default;
  FlatMessage(FlatMessage&& o) noexcept { *this = std::move(o); }
  FlatMessage& operator=(FlatMessage&& o) noexcept;
  FlatMessage(const FlatMessage&) = delete;
  FlatMessage& operator=(const FlatMessage&) = delete;
  ~FlatMessage() { release(); }

  // `bytes` zeroed bytes (a mapping when large).
  static FlatMessage zeroed(std::size_t bytes);
  static FlatMessage copy_of(const void* data, std::size_t bytes);

  unsigned char* base() const { return static_cast<unsigned char*>(base_); }
  const unsigned char* data() const { return base() + begin_; }
  std::size_t size() const { return size_; }
  std::size_t reserved() const { return reserved_; }
  // The content is [begin, begin + size) of the block; the rest of a mapping beyond it is given back.
  void set_view(std::size_t begin, std::size_t size);
  void release();
  // A malloc'ed block can be zeroed again and reused for another message (FlatMessageBuilder's `recycled`):
  // only its first `dirty()` bytes may be non-zero.
  bool reusable() const { return base_ != nullptr && !mapped_; }
  std::size_t dirty() const { return dirty_; }
  void set_dirty(std::size_t bytes) { dirty_ = bytes; }

 private:
  void* base_ = nullptr;
  std::size_t reserved_ = 0;  // bytes of the block
  bool mapped_ = false;
  std::size_t begin_ = 0, size_ = 0;
  std::size_t dirty_ = 0;  // bytes from the block's start that may have been written
};

class FlatMessageBuilder final : public capnp::MessageBuilder {
 public:
  // `words`: the expected size of the whole message in words (root pointer, structs, lists, data).
  // `recycled` (a caller that reuses blocks): an earlier message's block, zeroed again and taken if it is
  // large enough, else freed and a block with room to spare reserved instead.
  explicit FlatMessageBuilder(std::size_t words, FlatMessage* recycled = nullptr);
  ~FlatMessageBuilder() override;
  FlatMessageBuilder(const FlatMessageBuilder&) = delete;
  FlatMessageBuilder& operator=(const FlatMessageBuilder&) = delete;

  kj::ArrayPtr<capnp::word> allocateSegment(unsigned minimum_size) override;

  // The message as one flat array (messageToFlatArray's bytes); the builder must not be used after.
  FlatMessage finish();
  // Whether every segment came from the reservation (finish() then copies nothing).
  bool in_place() const { return spilled_.empty(); }

 private:
  static constexpr std::size_t kTableWords = 64;  // room for the table of up to 127 segments
  FlatMessage buffer_;
  std::size_t carved_ = kTableWords;  // words of the reservation handed out, table room included
  std::size_t next_size_ = 1024;      // MallocMessageBuilder's nextSize (SUGGESTED_FIRST_SEGMENT_WORDS)
  bool first_ = true;
  std::vector<void*> spilled_;  // segments that did not fit the reservation (calloc)
};

}  // namespace ede
