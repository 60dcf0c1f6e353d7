// CRC-32 (the zlib/PNG polynomial 0xEDB88320) of a byte range: protects the log's record headers and
// trailer, whose sizes and offsets a single flipped bit could otherwise turn into a huge allocation or a
// jump into the middle of a frame. (zstd checks the payloads itself with its frame checksum.)
#pragma once

#include <cstddef>
#include <cstdint>

namespace ede {

std::uint32_t crc32(const void* data, std::size_t size);

}  // namespace ede
