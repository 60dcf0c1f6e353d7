// CRC-32 (the zlib/PNG polynomial 0xEDB88320) of a byte range: protects the log's record headers and
// trailer, whose sizes and offsets a single flipped bit could otherwise turn into a huge allocation or a
// jump into the middle of a frame. (zstd checks the payloads itself with its frame checksum.)
//
// Computed by zlib's crc32_z: the same CRC the table-driven code written here before gave, so every log's
// bytes are unchanged (tests/log pins the standard check value; the example scenes' logs were compared byte
// for byte). This wrapper keeps zlib.h, and its global crc32, out of the log code.
#pragma once

#include <cstddef>
#include <cstdint>

namespace ede {

std::uint32_t crc32(const void* data, std::size_t size);

}  // namespace ede
