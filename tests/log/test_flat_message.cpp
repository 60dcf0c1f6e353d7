// FlatMessageBuilder (log/flat_message.hpp): the flat array it builds in place is messageToFlatArray's of a
// MallocMessageBuilder, byte for byte, for a message of one segment, one of several (big columns in
// segments of their own, far pointers), and ones whose size estimate was short (spilled segments, copied).
#include <catch2/catch.hpp>

#include <capnp/message.h>
#include <capnp/serialize.h>

#include <cstring>
#include <vector>

#include "ede_log.capnp.h"
#include "log/flat_message.hpp"

using namespace ede;

namespace {

// A keyframe-like message: `columns` Data fields of `bytes` bytes each, distinct contents.
void fill(capnp::MessageBuilder& message, std::size_t bytes, int columns) {
  auto k = message.initRoot<logschema::Keyframe>();
  k.setEventsBefore(12345);
  k.setRunId(7);
  capnp::Data::Builder (logschema::Keyframe::Builder::*init[])(unsigned) = {
      &logschema::Keyframe::Builder::initX, &logschema::Keyframe::Builder::initY, &logschema::Keyframe::Builder::initVx,
      &logschema::Keyframe::Builder::initVy, &logschema::Keyframe::Builder::initT};
  for (int c = 0; c < columns && c < 5; ++c) {
    auto d = (k.*init[c])(unsigned(bytes));
    for (std::size_t i = 0; i < bytes; ++i) d[i] = static_cast<unsigned char>(i * 7 + std::size_t(c) * 31 + (i >> 9));
  }
  auto partners = k.initLastPartner(unsigned(bytes / 8));
  for (unsigned i = 0; i < partners.size(); ++i) partners.set(i, int(i) - 3);
}

std::vector<unsigned char> malloc_bytes(std::size_t bytes, int columns) {
  capnp::MallocMessageBuilder message;
  fill(message, bytes, columns);
  const kj::Array<capnp::word> flat = capnp::messageToFlatArray(message);
  const auto b = flat.asBytes();
  return {b.begin(), b.end()};
}

std::vector<unsigned char> flat_bytes(std::size_t bytes, int columns, std::size_t estimate, bool& in_place,
                                      std::size_t& segments) {
  FlatMessageBuilder message(estimate);
  fill(message, bytes, columns);
  in_place = message.in_place();
  segments = message.getSegmentsForOutput().size();
  const FlatMessage m = message.finish();
  return {m.data(), m.data() + m.size()};
}

}  // namespace

TEST_CASE("FlatMessageBuilder gives messageToFlatArray's bytes, in one segment and in several", "[log][flat_message]") {
  struct Case {
    std::size_t bytes;
    int columns;
    std::size_t estimate;  // words; 0: the exact size below
    bool in_place;
    bool several;
  };
  const Case cases[] = {
      {40, 5, 0, true, false},            // fits MallocMessageBuilder's first segment (1024 words)
      {200000, 5, 0, true, true},         // big columns: segments of their own, far pointers
      {3 << 20, 3, 0, true, true},        // a mapping (> 1 MiB), segments moved down over the gaps
      {200000, 5, 10, false, true},       // estimate far too short: spilled segments, flattened by a copy
  };
  for (const Case& c : cases) {
    CAPTURE(c.bytes, c.columns, c.estimate);
    const std::size_t exact = 1 + 16 + std::size_t(c.columns) * message_words_of(c.bytes) + message_words_of(c.bytes / 8 * 4);
    bool in_place = false;
    std::size_t segments = 0;
    const std::vector<unsigned char> flat = flat_bytes(c.bytes, c.columns, c.estimate ? c.estimate : exact, in_place, segments);
    const std::vector<unsigned char> expected = malloc_bytes(c.bytes, c.columns);
    CHECK(in_place == c.in_place);
    CHECK((segments > 1) == c.several);
    REQUIRE(flat.size() == expected.size());
    CHECK(std::memcmp(flat.data(), expected.data(), flat.size()) == 0);
  }
}

TEST_CASE("FlatMessageBuilder with a reservation too small for a list still gives messageToFlatArray's bytes", "[log][flat_message]") {
  // A list of 3000 structs does not fit what an estimate of 4 words reserves: it is spilled, and
  // finish() copies, with the same bytes.
  auto build = [](capnp::MessageBuilder& message) {
    auto root = message.initRoot<logschema::Index>();
    auto entries = root.initEntries(3000);
    for (unsigned k = 0; k < entries.size(); ++k) entries[k].setOffset(k * 11);
  };
  capnp::MallocMessageBuilder a;
  build(a);
  const kj::Array<capnp::word> expected = capnp::messageToFlatArray(a);
  FlatMessageBuilder b(4);
  build(b);
  CHECK_FALSE(b.in_place());
  const FlatMessage m = b.finish();
  REQUIRE(m.size() == expected.size() * sizeof(capnp::word));
  CHECK(std::memcmp(m.data(), expected.begin(), m.size()) == 0);
}
