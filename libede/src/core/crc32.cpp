// crc32 over zlib; see crc32.hpp.
#include "core/crc32.hpp"

#include <zlib.h>

namespace ede {

std::uint32_t crc32(const void* data, std::size_t size) {
  return std::uint32_t(::crc32_z(0, static_cast<const Bytef*>(data), size));
}

}  // namespace ede
