// SHA-256 (FIPS 180-4), for digests of logs in tests and tools. Small and dependency-free: none of our
// libraries exports one.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace ede {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  std::array<std::uint8_t, 32> finish();
  static std::string hex(const std::array<std::uint8_t, 32>& digest);

 private:
  void block(const std::uint8_t* p);
  std::uint32_t h_[8];
  std::uint8_t buffer_[64];
  std::size_t buffered_ = 0;
  std::uint64_t length_ = 0;
};

}  // namespace ede
