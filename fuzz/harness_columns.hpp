// Fuzz target: the chunk column decoder, below zstd and Cap'n Proto.
//
// Mutating whole logs mostly hits zstd's checksums, so the column decoder behind them sees few inputs.
// Here the bytes are the six columns themselves (each preceded by a one-byte length in units of 4), decoded
// against a small replayed state of N disks and applied: every disk id, kind, wall and wrap code, time
// and velocity is checked by the decoder; decoding must fail with a message or succeed, and an applied
// event must leave a state of finite numbers or say it did not (replay then reports corruption).
// Found: a huge but finite time made positions infinite without a word (now reported).
// Both column encodings: the top bit of the second byte picks 2 (predicted times and velocities, against
// a periodic unit box with one species) over 1.
// The harness returns false on a violated check; the fuzz target traps on it, the test suite fails.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "log/chunk_codec.hpp"

namespace ede::fuzz {

inline bool fuzz_columns(const std::uint8_t* data, std::size_t size) {
  if (size < 8) return true;
  const std::size_t n = 2 + data[0] % 30;
  const std::uint32_t count = 1 + data[1] % 64;
  const std::uint32_t encoding = (data[1] & 0x80) ? 2 : 1;
  const auto physics = ede::EventPhysics<double>::box(1.0, 1.0, (data[0] & 0x80) != 0, 0.0, 0.0);
  ede::Particles<double> state;
  state.disk.assign(n, ede::Disk<double>{});
  std::vector<double> masses(n);
  for (std::size_t i = 0; i < n; ++i) {
    state.disk[i].x = 0.5, state.disk[i].y = 0.5, state.disk[i].vx = double(i % 3) - 1, state.disk[i].r = 0.01;
    masses[i] = 1.0 + double(i);
  }
  state.set_masses(std::move(masses));
  state.set_species(std::vector<std::int32_t>(n, 0));
  ede::MessageWords storage((size + 7) / 8 + 1, 0);  // zeroed: the tail past `size` is never a column, but keep it defined
  auto* bytes = reinterpret_cast<unsigned char*>(storage.data());
  std::memcpy(bytes, data, size);
  constexpr int kCols = ede::ChunkDecoder<double>::kColumnCount;  // every column the decoder reads, spins too
  const unsigned char* cols[kCols];
  std::size_t sizes[kCols];
  std::size_t at = 2;
  for (int c = 0; c < kCols; ++c) {
    const std::size_t want = at < size ? std::size_t(data[at]) * 4 : 0;
    at = std::min(at + 1, size);
    sizes[c] = std::min(want, size - at);
    cols[c] = bytes + at;
    at += sizes[c];
  }
  ede::ChunkDecoder<double> decoder(std::move(storage), cols, sizes, 0, count, n, 0.0, encoding, physics);
  if (!decoder.init()) return true;
  while (!decoder.done()) {
    ede::DecodedEvent<double> e;
    const ede::Status s = decoder.next(state, e);
    if (!s) {
      if (s.error().message.empty()) return false;
      return true;
    }
    if (!ede::apply_event(e, state, 1.0, 1.0)) return true;  // reported as corruption by replay
    for (const ede::Disk<double>& d : state.disk)
      if (!std::isfinite(d.x) || !std::isfinite(d.vx) || !std::isfinite(d.t)) return false;
  }
  (void)decoder.check_consumed();
  return true;
}

}  // namespace ede::fuzz
