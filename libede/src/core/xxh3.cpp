// Xxh3Hash over libxxhash's streaming API; see xxh3.hpp.
#include "core/xxh3.hpp"

#include <xxhash.h>

#include <new>

namespace ede {

struct Xxh3Hash::State {
  XXH3_state_t* s = XXH3_createState();
  ~State() { XXH3_freeState(s); }
};

Xxh3Hash::Xxh3Hash() : state_(std::make_unique<State>()) {
  if (!state_->s) throw std::bad_alloc();
  XXH3_128bits_reset(state_->s);
}

Xxh3Hash::~Xxh3Hash() = default;

void Xxh3Hash::update(const void* data, std::size_t size) { XXH3_128bits_update(state_->s, data, size); }

std::string Xxh3Hash::hex() const {
  XXH128_canonical_t canonical;
  XXH128_canonicalFromHash(&canonical, XXH3_128bits_digest(state_->s));
  static constexpr char kHex[] = "0123456789abcdef";
  std::string s;
  for (const unsigned char b : canonical.digest) s += kHex[b >> 4], s += kHex[b & 15];
  return s;
}

}  // namespace ede
