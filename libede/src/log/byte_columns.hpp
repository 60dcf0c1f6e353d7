// Byte columns for the log's chunks: LEB128 varints, zigzag signed values, and byte-plane shuffling.
//
// Varints carry what is usually small (time deltas, ids, residuals); fixed-width values that are not small
// but share their high bytes (raw velocities: sign, exponent, leading mantissa) are shuffled into byte
// planes (all first bytes, then all second bytes, ...) so zstd sees long runs of similar bytes.
// The reader side never trusts its input: every read is bounds-checked and reports failure instead of
// reading past the end; a varint longer than its type can hold is an error, not a wrap-around.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "log/scalar_bytes.hpp"

namespace ede {

inline u128 zigzag(i128 v) { return (u128(v) << 1) ^ u128(v >> 127); }
inline i128 unzigzag(u128 v) { return i128(v >> 1) ^ -i128(v & 1); }

class ByteWriter {
 public:
  void varint(u128 v) {
    while (v >= 0x80) {
      bytes_.push_back(static_cast<unsigned char>(v) | 0x80);
      v >>= 7;
    }
    bytes_.push_back(static_cast<unsigned char>(v));
  }
  void byte(unsigned char b) { bytes_.push_back(b); }
  void raw(const unsigned char* p, std::size_t n) { bytes_.insert(bytes_.end(), p, p + n); }
  std::vector<unsigned char>& bytes() { return bytes_; }
  const std::vector<unsigned char>& bytes() const { return bytes_; }
  void clear() { bytes_.clear(); }

 private:
  std::vector<unsigned char> bytes_;
};

class ByteReader {
 public:
  ByteReader(const unsigned char* data, std::size_t size) : p_(data), end_(data + size) {}
  // False (and the reader marked failed) if the input ends or the value exceeds `max_bits`.
  bool varint(u128& out, int max_bits = 128) {
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
