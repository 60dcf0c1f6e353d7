// FlatMessage and FlatMessageBuilder; see flat_message.hpp.
#include "log/flat_message.hpp"

#include <capnp/serialize.h>
#include <sys/mman.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

namespace ede {

namespace {
constexpr std::size_t kMapAtLeast = std::size_t(1) << 20;  // below: calloc (small records: chunks, index)
constexpr std::size_t kPage = 4096;
}  // namespace

FlatMessage& FlatMessage::operator=(FlatMessage&& o) noexcept {
  if (this != &o) {
    release();
    base_ = o.base_, reserved_ = o.reserved_, mapped_ = o.mapped_, begin_ = o.begin_, size_ = o.size_;
    dirty_ = o.dirty_;
    o.base_ = nullptr, o.reserved_ = 0, o.mapped_ = false, o.begin_ = 0, o.size_ = 0, o.dirty_ = 0;
  }
  return *this;
}

FlatMessage FlatMessage::zeroed(std::size_t bytes) {
  FlatMessage m;
  bytes = std::max<std::size_t>(bytes, 8);
  if (bytes >= kMapAtLeast) {
    bytes = (bytes + kPage - 1) / kPage * kPage;
    // MAP_NORESERVE: the reservation's untouched part is address space only, so the kernel's overcommit
    // heuristic does not count it against memory (under strict accounting the flag is ignored, and a
    // refused reservation makes the builder retry smaller: FlatMessageBuilder's constructor).
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    m.base_ = p, m.mapped_ = true;
  } else {
    m.base_ = std::calloc(bytes, 1);
    if (!m.base_) throw std::bad_alloc();
  }
  m.reserved_ = bytes;
  m.size_ = bytes;
  return m;
}

FlatMessage FlatMessage::copy_of(const void* data, std::size_t bytes) {
  FlatMessage m;
  m.base_ = std::malloc(std::max<std::size_t>(bytes, 1));
  if (!m.base_) throw std::bad_alloc();
  if (bytes) std::memcpy(m.base_, data, bytes);
  m.reserved_ = m.size_ = m.dirty_ = bytes;
  return m;
}

void FlatMessage::set_view(std::size_t begin, std::size_t size) {
  begin_ = begin, size_ = size;
  if (!mapped_) return;
  const std::size_t keep = (begin + size + kPage - 1) / kPage * kPage;
  if (keep < reserved_) {
    ::munmap(base() + keep, reserved_ - keep);
    reserved_ = keep;
  }
}

void FlatMessage::release() {
  if (base_) {
    if (mapped_)
      ::munmap(base_, reserved_);
    else
      std::free(base_);
  }
  base_ = nullptr, reserved_ = 0, mapped_ = false, begin_ = size_ = dirty_ = 0;
}

// MallocMessageBuilder's growth (GROW_HEURISTICALLY) at most doubles what was allocated, past the first
// segment: four times the message plus the first segment and the table holds every segment it asks for.
FlatMessageBuilder::FlatMessageBuilder(std::size_t words, FlatMessage* recycled) {
  const std::size_t bytes = 8 * (kTableWords + 2048 + 4 * words);
  if (recycled && recycled->reusable() && recycled->reserved() >= bytes) {
    std::memset(recycled->base(), 0, recycled->dirty());
    recycled->set_dirty(0);
    buffer_ = std::move(*recycled);
    return;
  }
  // A recycler's next message is usually about this one's size, sometimes a little larger: a quarter more
  // room lets this block serve then too.
  const std::size_t room = recycled ? bytes + bytes / 4 : bytes;
  if (recycled) recycled->release();
  try {
    buffer_ = FlatMessage::zeroed(room);
  } catch (const std::bad_alloc&) {  // address space refused: the message itself, later segments spilled
    buffer_ = FlatMessage::zeroed(8 * (kTableWords + 2048 + words));
  }
}

FlatMessageBuilder::~FlatMessageBuilder() {
  for (void* p : spilled_) std::free(p);
}

// MallocMessageBuilder::allocateSegment's sizes (capnp 0.9 message.c++): the first segment max(minimum,
// 1024) and nextSize = its size; then max(minimum, nextSize) and nextSize += size (capped).
kj::ArrayPtr<capnp::word> FlatMessageBuilder::allocateSegment(unsigned minimum_size) {
  constexpr std::size_t kMax = (std::size_t(1) << capnp::SEGMENT_WORD_COUNT_BITS) - 1;  // MAX_SEGMENT_WORDS
  const std::size_t size = std::max<std::size_t>(minimum_size, next_size_);
  if (first_) {
    first_ = false;
    next_size_ = size;
  } else {
    next_size_ = size <= kMax - next_size_ ? next_size_ + size : kMax;
  }
  if (spilled_.empty() && 8 * (carved_ + size) <= buffer_.reserved()) {
    capnp::word* at = reinterpret_cast<capnp::word*>(buffer_.base()) + carved_;
    carved_ += size;
    return kj::arrayPtr(at, size);
  }
  void* p = std::calloc(size, sizeof(capnp::word));
  if (!p) throw std::bad_alloc();
  spilled_.push_back(p);
  return kj::arrayPtr(static_cast<capnp::word*>(p), size);
}

FlatMessage FlatMessageBuilder::finish() {
  const auto segments = getSegmentsForOutput();
  if (!in_place() || segments.size() >= 2 * kTableWords) {
    const kj::Array<capnp::word> flat = capnp::messageToFlatArray(segments);
    return FlatMessage::copy_of(flat.begin(), flat.size() * sizeof(capnp::word));
  }
  // messageToFlatArray's table: the segment count - 1, then each segment's size, 32-bit little-endian
  // (the build is little-endian only: scalar_bytes.hpp), padded to a whole word.
  const std::size_t table_words = (segments.size() + 2) / 2;
  capnp::word* const words = reinterpret_cast<capnp::word*>(buffer_.base());
  const std::size_t begin = kTableWords - table_words;
  auto* table = reinterpret_cast<std::uint32_t*>(words + begin);
  std::memset(table, 0, table_words * sizeof(capnp::word));
  table[0] = std::uint32_t(segments.size() - 1);
  capnp::word* to = words + kTableWords;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    table[k + 1] = std::uint32_t(segments[k].size());
    // Segments were carved in order, so each moves down (or stays): memmove, never past a later one.
    if (segments[k].begin() != to) std::memmove(to, segments[k].begin(), segments[k].size() * sizeof(capnp::word));
    to += segments[k].size();
  }
  const std::size_t end = std::size_t(to - words);
  // The words after the message were either never written (still zero) or a moved segment's old place:
  // a mapping gives them back in set_view; a small block keeps them (freed with it).
  FlatMessage out = std::move(buffer_);
  out.set_view(begin * sizeof(capnp::word), (end - begin) * sizeof(capnp::word));
  out.set_dirty(carved_ * sizeof(capnp::word));  // every word handed out may have been written
  return out;
}

}  // namespace ede
