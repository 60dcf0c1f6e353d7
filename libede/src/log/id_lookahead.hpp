// IdLookahead: reads a chunk's kind and id columns a few events ahead of the decoder and prefetches the
// replayed records those events will read (disk record, mass, species), so that their cache misses overlap
// the decoding of the events before them.
//
// Why: with more than ~10^4 disks the replayed state no longer fits the core's L2 cache, and decoding an
// event waits on its two disks' records. Measured before this (cachegrind, N = 10^5 log, one thread):
// ~880 instructions and ~7.7 L1 misses per event, 3.8 M events/s against 10.7 M at N = 10^4, where the
// instructions are the same. The ids are plain varints in their own columns, so reading them ahead costs
// a kind byte and two short varints per event; the values are never used for anything but prefetching,
// so a corrupted column can only make a prefetch useless (an id out of range is not prefetched), never
// change a decoded event: the decoder reads the same columns with all its checks.
// Off below kMinDisks (the state fits in L2 and the lookahead's ~25 instructions per event would be pure
// cost). Rejected: decoding whole events ahead into a buffer (a pair's time and velocities need the state
// after every earlier event, so only the ids can run ahead).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/event.hpp"
#include "core/particles.hpp"
#include "log/byte_columns.hpp"

namespace ede {

class IdLookahead {
 public:
  static constexpr std::uint32_t kDistance = 8;       // events ahead: a few memory latencies' worth of decoding
  static constexpr std::size_t kMinDisks = 1u << 15;  // 2 MiB of records: beyond the L2 cache

  IdLookahead() = default;
  IdLookahead(ByteReader kinds, ByteReader disks, ByteReader partners, std::uint32_t count, std::size_t n,
              unsigned char flag)
      : kinds_(kinds), disks_(disks), partners_(partners), count_(count), n_(n), flag_(flag),
        on_(n >= kMinDisks) {}

  // Before the decoder decodes event `decoded` of the chunk: reads ahead up to event decoded + kDistance.
  std::uint32_t ahead() const { return ahead_; }  // events whose ids were read (for tests)
  bool active() const { return on_; }             // false below kMinDisks or once a column ended

  template <class T>
  [[gnu::always_inline]] void before(std::uint32_t decoded, const Particles<T>& p) {
    if (!on_) return;
    const std::uint32_t target = decoded + kDistance < count_ ? decoded + kDistance : count_;
    while (ahead_ < target && read_one(p)) ++ahead_;
  }

 private:
  // Reads one event's kind and ids and prefetches its disks; false (and off from then on) where a column ends.
  template <class T>
  [[gnu::always_inline]] bool read_one(const Particles<T>& p) {
    unsigned char byte;
    if (!kinds_.byte(byte)) return on_ = false;
    const auto kind = static_cast<EventKind>(byte & ~flag_);
    if (kind == EventKind::Thermostat) {  // a disk, no partner
      u128 disk;
      if (!disks_.varint(disk, 32)) return on_ = false;
      if (disk < n_) prefetch(p, std::size_t(disk));
      return true;
    }
    if (kind != EventKind::Pair && kind != EventKind::Wall && kind != EventKind::Wrap && kind != EventKind::Segment &&
        kind != EventKind::Step && kind != EventKind::Shear)
      return true;  // actions carry no ids
    u128 disk, partner;
    if (!disks_.varint(disk, 32) || !partners_.varint(partner, 33)) return on_ = false;
    if (disk < n_) prefetch(p, std::size_t(disk));
    if (kind == EventKind::Pair || kind == EventKind::Step) {
      const i128 j = i128(disk) + unzigzag(partner);
      if (j >= 0 && j < i128(n_)) prefetch(p, std::size_t(j));
    }
    return true;
  }
  template <class T>
  static void prefetch(const Particles<T>& p, std::size_t i) {
    if (i >= p.disk.size()) return;
    __builtin_prefetch(&p.disk[i]);
    if (i < p.masses.size()) __builtin_prefetch(&p.masses[i]);
    if (i < p.species_ids.size()) __builtin_prefetch(&p.species_ids[i]);
  }

  ByteReader kinds_{nullptr, 0}, disks_{nullptr, 0}, partners_{nullptr, 0};
  std::uint32_t count_ = 0, ahead_ = 0;
  std::size_t n_ = 0;
  unsigned char flag_ = 0;
  bool on_ = false;
};

}  // namespace ede
