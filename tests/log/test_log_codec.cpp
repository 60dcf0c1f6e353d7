// The log's building blocks: framing, CRC, byte columns, scalar bytes and ordered keys, the content hash.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "log/byte_columns.hpp"
#include "log/chunk_codec.hpp"
#include "core/crc32.hpp"
#include "log/log_framing.hpp"
#include "log/scalar_bytes.hpp"
#include "core/xxh3.hpp"

using namespace ede;

TEST_CASE("crc32 matches the standard check value", "[log][codec]") {
  CHECK(crc32("123456789", 9) == 0xCBF43926u);  // CRC-32/ISO-HDLC (zlib, PNG)
  CHECK(crc32("", 0) == 0u);
}

TEST_CASE("the XXH3-128 content hash matches xxHash's reference vectors, however the input is split",
          "[log][codec]") {
  CHECK(Xxh3Hash().hex() == "99aa06d3014798d86001c324468d497f");  // empty input
  Xxh3Hash abc;
  abc.update("a", 1);
  abc.update("bc", 2);
  CHECK(abc.hex() == "06b05ab6733a618578af5f94892f3950");
  std::string long_input;  // several of XXH3's 1024-byte blocks, cut at uneven places
  for (int k = 0; k < 5000; ++k) long_input += char('a' + (k * 7919) % 26);
  Xxh3Hash whole, pieces;
  whole.update(long_input.data(), long_input.size());
  for (std::size_t at = 0, step = 1; at < long_input.size(); at += step, step = step * 3 % 1021 + 1)
    pieces.update(long_input.data() + at, std::min(step, long_input.size() - at));
  CHECK(pieces.hex() == whole.hex());
  CHECK(whole.hex().size() == 32);
}

TEST_CASE("record headers and trailers round-trip and refuse damage", "[log][codec]") {
  logfmt::RecordHeader h;
  h.kind = logfmt::RecordKind::Chunk;
  h.payload_size = 12345;
  h.first_event = 1u << 20;
  h.event_count = 16384;
  h.time_first = 0.25;
  h.time_last = 0.5;
  h.resumable = true;
  unsigned char bytes[logfmt::kRecordHeaderSize];
  logfmt::encode_record_header(h, bytes);
  std::string why;
  const auto back = logfmt::decode_record_header(bytes, why);
  REQUIRE(back);
  CHECK(back->kind == h.kind);
  CHECK(back->payload_size == h.payload_size);
  CHECK(back->first_event == h.first_event);
  CHECK(back->event_count == h.event_count);
  CHECK(back->time_first == h.time_first);
  CHECK(back->resumable);
  for (std::size_t k = 0; k < sizeof bytes; ++k)
    for (int bit = 0; bit < 8; ++bit) {
      unsigned char flipped[sizeof bytes];
      std::memcpy(flipped, bytes, sizeof bytes);
      flipped[k] ^= static_cast<unsigned char>(1 << bit);
      REQUIRE_FALSE(logfmt::decode_record_header(flipped, why));  // the CRC (or the marker) catches every flip
    }
  unsigned char tr[logfmt::kTrailerSize];
  logfmt::encode_trailer({4096, 8192}, tr);
  const auto t = logfmt::decode_trailer(tr);
  REQUIRE(t);
  CHECK(t->index_offset == 4096);
  CHECK(t->trailer_offset == 8192);
  tr[3] ^= 1;
  CHECK_FALSE(logfmt::decode_trailer(tr));
}

TEST_CASE("the file header refuses other files and other versions", "[log][codec]") {
  unsigned char h[logfmt::kFileHeaderSize];
  logfmt::encode_file_header(h);
  std::uint32_t version = 0;
  CHECK(logfmt::check_file_header(h, version).empty());
  CHECK(version == logfmt::kFormatVersion);
  h[8] = 1;  // format version 1: still read
  CHECK(logfmt::check_file_header(h, version).empty());
  CHECK(version == 1);
  h[8] = 3;  // format version 3 (step and thermostat events): read
  CHECK(logfmt::check_file_header(h, version).empty());
  CHECK(version == 3);
  h[8] = 4;  // a newer version
  CHECK(logfmt::check_file_header(h, version).find("version 4") != std::string::npos);
  h[8] = 0;
  CHECK(logfmt::check_file_header(h, version).find("version 0") != std::string::npos);
  std::memcpy(h, "seed = 1", 8);
  CHECK(logfmt::check_file_header(h, version).find("not an ede event log") != std::string::npos);
}

TEST_CASE("varints and zigzag round-trip, overlong and cut varints are refused", "[log][codec]") {
  ByteWriter w;
  const u128 values[] = {0, 1, 127, 128, 300, (u128(1) << 64) + 5, ~u128(0)};
  for (const u128 v : values) w.varint(v);
  for (const i128 v : {i128(0), i128(-1), i128(1), -i128(1) << 100, i128(123456789)}) w.varint(zigzag(v));
  ByteReader r(w.data(), w.size());
  for (const u128 v : values) {
    u128 got = 0;
    REQUIRE(r.varint(got));
    CHECK(got == v);
  }
  for (const i128 v : {i128(0), i128(-1), i128(1), -i128(1) << 100, i128(123456789)}) {
    u128 got = 0;
    REQUIRE(r.varint(got));
    CHECK(unzigzag(got) == v);
  }
  CHECK(r.at_end());
  const unsigned char too_big[] = {0xFF, 0xFF, 0xFF, 0xFF, 0x7F};  // 35 bits into a 32-bit field
  ByteReader r32(too_big, sizeof too_big);
  u128 v = 0;
  CHECK_FALSE(r32.varint(v, 32));
  const unsigned char cut[] = {0x80, 0x80};
  ByteReader rc(cut, sizeof cut);
  CHECK_FALSE(rc.varint(v));
}

TEST_CASE("ByteWriter writes plain LEB128 across its buffer's growth", "[log][codec]") {
  // The reference: one byte at a time, 7 bits each, low first (what the reader and FORMAT.md expect).
  const auto leb128 = [](u128 v, std::vector<unsigned char>& out) {
    do {
      const unsigned char low = static_cast<unsigned char>(v & 0x7F);
      v >>= 7;
      out.push_back(v ? (low | 0x80) : low);
    } while (v);
  };
  ByteWriter w;
  std::vector<unsigned char> expected;
  std::uint64_t state = 12345;
  for (int k = 0; k < 100000; ++k) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const int bits = int(state >> 57);  // 0..127 significant bits
    const u128 v = bits == 0 ? 0 : ((u128(state) << 64 | u128(state * 31)) >> (128 - bits));
    if (k % 7 == 0) {
      w.byte(static_cast<unsigned char>(k));
      expected.push_back(static_cast<unsigned char>(k));
    } else {
      w.varint(v);
      leb128(v, expected);
    }
  }
  REQUIRE(w.size() == expected.size());
  CHECK(w.bytes() == expected);
  CHECK(std::equal(expected.begin(), expected.end(), w.data()));
  w.clear();
  CHECK(w.size() == 0);
  w.varint(300);
  CHECK(w.bytes() == std::vector<unsigned char>{0xAC, 0x02});
}

TEMPLATE_TEST_CASE("residuals of float and double keys equal the 128-bit formula", "[log][codec]", float, double) {
  using T = TestType;
  const auto reference = [](T a, T b) { return zigzag(i128(ordered_key(a)) - i128(ordered_key(b))); };
  const T lim = std::numeric_limits<T>::max(), inf = std::numeric_limits<T>::infinity();
  const T values[] = {-inf, -lim, T(-1), T(-0.0), T(0), std::numeric_limits<T>::denorm_min(), T(0.5), T(1), lim, inf,
                      std::numeric_limits<T>::quiet_NaN(), -std::numeric_limits<T>::quiet_NaN()};
  for (const T a : values)
    for (const T b : values) CHECK(residual(a, b) == reference(a, b));
  const T x = T(0.75);
  CHECK(residual(std::nextafter(x, T(1)), x) == 2);   // +1 in key space
  CHECK(residual(x, std::nextafter(x, T(1))) == 1);   // -1
  CHECK(residual(x, x) == 0);
}

TEST_CASE("byte-plane shuffling round-trips", "[log][codec]") {
  std::vector<unsigned char> in(10 * 8);
  for (std::size_t k = 0; k < in.size(); ++k) in[k] = static_cast<unsigned char>(k * 37);
  const auto s = shuffle_bytes(in, 8);
  CHECK(s[1] == in[8]);  // second value's first byte comes second
  std::vector<unsigned char> back;
  REQUIRE(unshuffle_bytes(s.data(), s.size(), 8, back));
  CHECK(back == in);
  CHECK_FALSE(unshuffle_bytes(s.data(), 7, 8, back));
}

TEMPLATE_TEST_CASE("ordered keys preserve order and invert exactly", "[log][codec]", float, double, long double) {
  using T = TestType;
  const T values[] = {-std::numeric_limits<T>::max(), T(-1e10), T(-1), T(-1e-30), T(-0.0), T(0), T(1e-30),
                      T(0.1), T(1), T(1) + std::numeric_limits<T>::epsilon(), T(3e10), std::numeric_limits<T>::max()};
  for (std::size_t k = 0; k < std::size(values); ++k) {
    const T back = from_ordered_key<T>(ordered_key(values[k]));
    CHECK(std::memcmp(&back, &values[k], kScalarWidth<T>) == 0);
    if (k > 0 && values[k - 1] < values[k]) CHECK(ordered_key(values[k - 1]) < ordered_key(values[k]));
  }
  // Neighbouring values differ by one in key space: deltas of nearby times are tiny.
  const T x = T(0.75);
  CHECK(ordered_key(std::nextafter(x, T(1))) - ordered_key(x) == 1);
}

TEST_CASE("long double is stored without its padding bytes", "[log][codec]") {
  long double a = 1.5L, b = 1.5L;
  std::memset(reinterpret_cast<unsigned char*>(&a) + 10, 0xAB, sizeof(long double) - 10);  // garbage padding
  unsigned char ba[10], bb[10];
  scalar_to_bytes(a, ba);
  scalar_to_bytes(b, bb);
  CHECK(std::memcmp(ba, bb, 10) == 0);
  CHECK(scalar_from_bytes<long double>(ba) == 1.5L);
}
