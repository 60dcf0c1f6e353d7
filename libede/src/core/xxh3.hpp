// XXH3 128-bit (xxHash, Debian's libxxhash) over a stream of bytes, for content digests of logs.
//
// A digest only has to tell two contents apart, not resist an attacker, so a fast non-cryptographic hash
// from a well-kept library does the job: XXH3 hashes at memory speed, where the SHA-256 written here before
// cost time in every `ede-replay info --digest` and was code to maintain. The streaming state lives behind
// a pointer so that xxhash.h stays out of this header. Rejected: XXH64 (64 bits, a collision among the
// many logs of a sweep is less remote), OpenSSL's SHA-256 (a large dependency for one function).
#pragma once

#include <cstddef>
#include <memory>
#include <string>

namespace ede {

class Xxh3Hash {
 public:
  Xxh3Hash();
  ~Xxh3Hash();
  Xxh3Hash(const Xxh3Hash&) = delete;
  Xxh3Hash& operator=(const Xxh3Hash&) = delete;

  void update(const void* data, std::size_t size);
  // The 128-bit hash of everything updated so far, in xxHash's canonical (big-endian) byte order as 32
  // lowercase hex digits: the text `xxh128sum` prints.
  std::string hex() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace ede
