// Byte columns for the log's chunks: LEB128 varints, zigzag signed values, and byte-plane shuffling.
//
// Varints carry what is usually small (time deltas, ids, residuals); fixed-width values that are not small
// but share their high bytes (raw velocities: sign, exponent, leading mantissa) are shuffled into byte
// planes (all first bytes, then all second bytes, ...) so zstd sees long runs of similar bytes.
// The reader side never trusts its input: every read is bounds-checked and reports failure instead of
// reading past the end; a varint longer than its type can hold is an error, not a wrap-around.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <cstdint>
#include <string>
#include <vector>

#include "log/scalar_bytes.hpp"

namespace ede {

inline u128 zigzag(i128 v) { return (u128(v) << 1) ^ u128(v >> 127); }
inline i128 unzigzag(u128 v) { return i128(v >> 1) ^ -i128(v & 1); }

// Appends into a buffer kept larger than its contents (size_ bytes used), so that a byte is one store and a
// compare: as push_backs into a std::vector (an out-of-line call per byte) and a 128-bit shift loop, the
// varints were 18 % of the log writer's instructions.
class ByteWriter {
 public:
  // One byte (a zero residual, a short delta) inline; longer values out of line, with 64-bit shifts once
  // the value fits in 64 bits.
  [[gnu::always_inline]] void varint(u128 v) {
    if (v < 0x80) return byte(static_cast<unsigned char>(v));
    varint_long(v);
  }
  [[gnu::always_inline]] void byte(unsigned char b) {
    if (size_ == buf_.size()) grow(1);
    buf_[size_++] = b;
  }
  // Room for n more bytes, for a caller that writes many values in a row: it writes through the returned
  // pointer, kept in a local variable (so that a byte stored through it cannot be taken to change this
  // writer's own fields, which the compiler would then reload after every byte), then hands back the end.
  unsigned char* begin_write(std::size_t n) {
    if (buf_.size() - size_ < n) grow(n);
    return buf_.data() + size_;
  }
  void end_write(const unsigned char* end) { size_ = std::size_t(end - buf_.data()); }
  // n zero bytes (the zero residuals of an event the engine vouched for).
  void zeros(std::size_t n) {
    if (buf_.size() - size_ < n) grow(n);
    std::memset(buf_.data() + size_, 0, n);
    size_ += n;
  }
  void raw(const unsigned char* p, std::size_t n) {
    if (n == 0) return;
    if (buf_.size() - size_ < n) grow(n);
    std::memcpy(buf_.data() + size_, p, n);
    size_ += n;
  }
  const unsigned char* data() const { return buf_.data(); }
  std::size_t size() const { return size_; }
  std::vector<unsigned char> bytes() const { return {buf_.begin(), buf_.begin() + std::ptrdiff_t(size_)}; }
  void clear() { size_ = 0; }

 private:
  [[gnu::noinline]] void varint_long(u128 v) {
    if (buf_.size() - size_ < kMaxVarint) grow(kMaxVarint);
    unsigned char* out = buf_.data() + size_;
    while (v >> 64 != 0) {
      *out++ = static_cast<unsigned char>(v) | 0x80;
      v >>= 7;
    }
    std::uint64_t w = std::uint64_t(v);
    while (w >= 0x80) {
      *out++ = static_cast<unsigned char>(w) | 0x80;
      w >>= 7;
    }
    *out++ = static_cast<unsigned char>(w);
    size_ = std::size_t(out - buf_.data());
  }
  [[gnu::noinline]] void grow(std::size_t n) {
    buf_.resize(std::max({2 * buf_.size(), size_ + n, std::size_t(256)}));
  }

  static constexpr std::size_t kMaxVarint = 19;  // ceil(128 / 7)
  std::vector<unsigned char> buf_;
  std::size_t size_ = 0;
};

// A varint at p (room for it assured by the caller: at most 10 bytes for 64 bits, 19 for 128); returns the
// end.
[[gnu::always_inline]] inline unsigned char* put_varint(unsigned char* p, std::uint64_t v) {
  while (v >= 0x80) {
    *p++ = static_cast<unsigned char>(v) | 0x80;
    v >>= 7;
  }
  *p++ = static_cast<unsigned char>(v);
  return p;
}
inline unsigned char* put_varint(unsigned char* p, u128 v) {
  while (v >> 64 != 0) {
    *p++ = static_cast<unsigned char>(v) | 0x80;
    v >>= 7;
  }
  return put_varint(p, std::uint64_t(v));
}

class ByteReader {
 public:
  ByteReader(const unsigned char* data, std::size_t size) : p_(data), end_(data + size) {}
  // False (and the reader marked failed) if the input ends or the value exceeds `max_bits`.
  // The one- and two-byte cases (most residuals, time codes, disk ids and partner offsets up to 16383) are
  // inlined into the decoder's loop: as a call, this function was 13 % of replay's instructions. A two-byte
  // value is below 2^14, so it passes every width check of the general loop when max_bits >= 14.
  [[gnu::always_inline]] bool varint(u128& out, int max_bits = 128) {
    if (p_ != end_ && *p_ < 0x80 && max_bits >= 7) {
      out = *p_++;
      return true;
    }
    if (end_ - p_ >= 2 && p_[1] < 0x80 && max_bits >= 14) {
      out = std::uint32_t(p_[0] & 0x7F) | (std::uint32_t(p_[1]) << 7);
      p_ += 2;
      return true;
    }
    return varint_long(out, max_bits);
  }
  [[gnu::noinline]] bool varint_long(u128& out, int max_bits) {
    if (p_ != end_ && *p_ < 0x80 && max_bits >= 7) {
      out = *p_++;
      return true;
    }
    // Up to 9 bytes (63 bits) in 64-bit arithmetic, with the same checks as the general loop below.
    {
      const unsigned char* p = p_;
      std::uint64_t v = 0;
      const int limit = max_bits + 7 < 63 ? max_bits + 7 : 63;
      for (int shift = 0; shift < limit; shift += 7) {
        if (p == end_) return fail();
        const unsigned char b = *p++;
        if (shift >= max_bits && (b & 0x7F)) return fail();
        v |= std::uint64_t(b & 0x7F) << shift;
        if (!(b & 0x80)) {
          if (max_bits < 64 && (v >> max_bits) != 0) return fail();
          p_ = p;
          out = v;
          return true;
        }
      }
      if (limit == max_bits + 7) return fail();
    }
    u128 v = 0;
    for (int shift = 0; shift < max_bits + 7; shift += 7) {
      if (p_ == end_) return fail();
      const unsigned char b = *p_++;
      if (shift >= max_bits && (b & 0x7F)) return fail();
      if (shift < 128) v |= u128(b & 0x7F) << shift;
      if (!(b & 0x80)) {
        if (max_bits < 128 && (v >> max_bits) != 0) return fail();
        out = v;
        return true;
      }
    }
    return fail();
  }
  // Consumes a varint 0 (one zero byte) if that is what comes next: the common residual, read without
  // 128-bit arithmetic.
  bool zero() {
    if (p_ == end_ || *p_ != 0) return false;
    ++p_;
    return true;
  }
  bool byte(unsigned char& out) {
    if (p_ == end_) return fail();
    out = *p_++;
    return true;
  }
  bool raw(unsigned char* out, std::size_t n) {
    if (std::size_t(end_ - p_) < n) return fail();
    std::memcpy(out, p_, n);
    p_ += n;
    return true;
  }
  bool at_end() const { return p_ == end_; }
  bool failed() const { return failed_; }

 private:
  bool fail() {
    failed_ = true;
    return false;
  }
  const unsigned char* p_;
  const unsigned char* end_;
  bool failed_ = false;
};

// Byte-plane shuffle of `count` values of `width` bytes: out[b * count + k] = in[k * width + b].
std::vector<unsigned char> shuffle_bytes(const std::vector<unsigned char>& in, std::size_t width);
// The inverse; false if the size is not a multiple of width.
bool unshuffle_bytes(const unsigned char* in, std::size_t size, std::size_t width, std::vector<unsigned char>& out);

}  // namespace ede
