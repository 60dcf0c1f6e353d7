// RecordWriter (log/record_writer.hpp): a record compressed twice and written in pieces (write_two_pass,
// what a keyframe at large N takes) is the same bytes as one compressed whole (ZSTD_compress2).
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "log/flat_message.hpp"
#include "log/log_framing.hpp"
#include "log/record_writer.hpp"
#include "tool_runner.hpp"  // temp_path, read_file

using namespace ede;
using ede::test::read_file;
using ede::test::temp_path;

namespace {

// Content like a keyframe's shuffled column of positions (the 10^6-disk benchmark's): byte plane 0 zero,
// planes 1-5 random, plane 6 slowly rising, plane 7 constant. With it, at 8 MB, a buffered-input stream
// (ZSTD_compressStream2 without ZSTD_c_stableInBuffer) makes another frame than ZSTD_compress2 (checked
// by removing that parameter: this test then fails).
std::vector<unsigned char> content(std::size_t bytes, std::uint64_t seed) {
  const std::size_t n = bytes / 8;
  std::vector<unsigned char> b(bytes, 0);
  std::uint64_t x = seed * 0x9E3779B97F4A7C15ull + 1;
  for (std::size_t p = 1; p <= 5; ++p)
    for (std::size_t i = 0; i < n; ++i) {
      x ^= x << 13, x ^= x >> 7, x ^= x << 17;
      b[p * n + i] = static_cast<unsigned char>(x >> 24);
    }
  for (std::size_t i = 0; i < n; ++i) {
    b[6 * n + i] = static_cast<unsigned char>(0xc0 + 40 * i / n);
    b[7 * n + i] = 0xef;
  }
  return b;
}

std::string write_records(const std::string& name, std::size_t two_pass_above) {
  const std::string path = temp_path(name);
  RecordWriter out(path, 0, 3, two_pass_above);
  REQUIRE(out.error().empty());
  out.write_raw(std::vector<unsigned char>(logfmt::kFileHeaderSize, 0));
  const std::size_t sizes[] = {4096, 8000000, 100, 3 << 20};  // the big ones exceed one 1 MiB piece compressed
  std::uint64_t seed = 1;
  for (const std::size_t size : sizes) {
    const std::vector<unsigned char> c = content(size, seed++);
    logfmt::RecordHeader h;
    h.kind = logfmt::RecordKind::Keyframe;
    h.first_event = seed;
    out.submit(h, FlatMessage::copy_of(c.data(), c.size()));
  }
  REQUIRE(out.finish().empty());
  return read_file(path);
}

}  // namespace

TEST_CASE("RecordWriter: records compressed in two passes and pieces are the bytes of one-shot compression", "[log][record_writer]") {
  const std::string whole = write_records("record_writer_whole.bin", std::size_t(1) << 40);  // every record one-shot
  const std::string pieces = write_records("record_writer_pieces.bin", 0);                 // every record two-pass
  REQUIRE(whole.size() > (std::size_t(2) << 20));  // the big records took more than one piece
  CHECK(whole.size() == pieces.size());
  const bool same_bytes = whole == pieces;  // not CHECK(whole == pieces): Catch would print 16 MB
  CHECK(same_bytes);
}
