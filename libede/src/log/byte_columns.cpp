// Byte-plane shuffling; see byte_columns.hpp.
#include "log/byte_columns.hpp"

namespace ede {

std::vector<unsigned char> shuffle_bytes(const std::vector<unsigned char>& in, std::size_t width) {
  const std::size_t count = in.size() / width;
  std::vector<unsigned char> out(count * width);
  for (std::size_t k = 0; k < count; ++k)
    for (std::size_t b = 0; b < width; ++b) out[b * count + k] = in[k * width + b];
  return out;
}

bool unshuffle_bytes(const unsigned char* in, std::size_t size, std::size_t width, std::vector<unsigned char>& out) {
  if (width == 0 || size % width != 0) return false;
  const std::size_t count = size / width;
  out.assign(size, 0);
  for (std::size_t k = 0; k < count; ++k)
    for (std::size_t b = 0; b < width; ++b) out[k * width + b] = in[b * count + k];
  return true;
}

}  // namespace ede
