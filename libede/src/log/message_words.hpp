// MessageWords: the buffer a record's Cap'n Proto message is decompressed into (8-byte words).
//
// A std::vector whose growth leaves new words uninitialised: zstd overwrites every word it produces and
// the size is checked against the frame's declared size, so zero-filling first (what a plain
// std::vector<std::uint64_t> does on resize) only cost time — 3.5 % of replay's instructions. Rejected: a
// raw unique_ptr<uint64_t[]> (callers move, size and index it like a vector; keeping the vector interface
// keeps them unchanged).
#pragma once

#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace ede {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() noexcept = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  // Value-initialisation (resize, the size constructor) becomes default-initialisation: no zeroing.
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

using MessageWords = std::vector<std::uint64_t, DefaultInitAllocator<std::uint64_t>>;

}  // namespace ede
