// IdLookahead reads the kind and id columns ahead of the decoder only to prefetch: on well-formed columns
// it runs exactly kDistance events ahead, and on any bytes at all it stays inside its columns and the
// state (ASan checks the second in the sanitized build) and stops quietly where a column ends.
#include <catch2/catch.hpp>

#include "log/byte_columns.hpp"
#include "log/chunk_codec.hpp"
#include "log/id_lookahead.hpp"

using namespace ede;

namespace {

Particles<double> state_of(std::size_t n) {
  Particles<double> p;
  p.disk.resize(n);
  p.set_masses(std::vector<double>(n, 1.0));
  p.set_species(std::vector<std::int32_t>(n, 0));
  return p;
}

struct Columns {
  ByteWriter kinds, disks, partners;
  void pair(std::uint32_t i, std::int32_t j) {
    kinds.byte(static_cast<unsigned char>(EventKind::Pair));
    disks.varint(i);
    partners.varint(zigzag(i128(j) - i128(i)));
  }
  void wall(std::uint32_t i, unsigned wall) {
    kinds.byte(static_cast<unsigned char>(EventKind::Wall) | kTcElasticFlag);
    disks.varint(i);
    partners.varint(wall);
  }
  void action() { kinds.byte(static_cast<unsigned char>(EventKind::Action)); }
  static ByteReader reader(const ByteWriter& w) { return ByteReader(w.data(), w.size()); }
  IdLookahead lookahead(std::uint32_t count, std::size_t n) const {
    return IdLookahead(reader(kinds), reader(disks), reader(partners), count, n, kTcElasticFlag);
  }
};

}  // namespace

TEST_CASE("IdLookahead runs kDistance events ahead of the decoder on well-formed columns", "[log][lookahead]") {
  const std::size_t n = IdLookahead::kMinDisks + 5;
  const Particles<double> p = state_of(n);
  Columns c;
  const std::uint32_t count = 50;
  for (std::uint32_t k = 0; k < count; ++k) {
    if (k % 7 == 3) c.action();
    else if (k % 5 == 1) c.wall(k * 331 % n, k % 4);
    else c.pair(std::uint32_t(n - 1 - k), std::int32_t(k * 977 % n));
  }
  IdLookahead ahead = c.lookahead(count, n);
  for (std::uint32_t decoded = 0; decoded < count; ++decoded) {
    ahead.before(decoded, p);
    REQUIRE(ahead.ahead() == std::min(decoded + IdLookahead::kDistance, count));
    REQUIRE(ahead.active());
  }
  // Below kMinDisks it does nothing at all.
  IdLookahead off = c.lookahead(count, IdLookahead::kMinDisks - 1);
  off.before(0, p);
  CHECK(off.ahead() == 0);
  CHECK_FALSE(off.active());
}

TEST_CASE("IdLookahead stops quietly where a column ends, and survives any bytes", "[log][lookahead]") {
  const std::size_t n = IdLookahead::kMinDisks;
  const Particles<double> p = state_of(n);
  Columns c;
  for (std::uint32_t k = 0; k < 20; ++k) c.pair(k, std::int32_t(k + 1));
  // The chunk claims 100 events but its columns hold 20: the lookahead reads 20 and stops.
  IdLookahead cut = c.lookahead(100, n);
  for (std::uint32_t decoded = 0; decoded < 100; ++decoded) cut.before(decoded, p);
  CHECK(cut.ahead() == 20);
  CHECK_FALSE(cut.active());
  // Random bytes (ids far out of range, partners below 0, unknown kinds, long varints): no read outside
  // the columns or the state.
  std::uint64_t x = 0x9E3779B97F4A7C15ull;
  const auto next = [&] { return x ^= x << 13, x ^= x >> 7, x ^= x << 17, x; };
  std::size_t reached_end = 0;
  for (int round = 0; round < 200; ++round) {
    std::vector<unsigned char> cols[3];
    for (auto& col : cols) {
      col.resize(next() % 64);
      for (unsigned char& b : col) b = static_cast<unsigned char>(next());
    }
    IdLookahead any(ByteReader(cols[0].data(), cols[0].size()), ByteReader(cols[1].data(), cols[1].size()),
                    ByteReader(cols[2].data(), cols[2].size()), 64, n, kTcElasticFlag);
    for (std::uint32_t decoded = 0; decoded < 64; ++decoded) any.before(decoded, p);
    REQUIRE(any.ahead() <= 64);
    reached_end += any.ahead() == 64;
  }
  CHECK(reached_end < 200);  // most random columns end early
}
