// Small helpers for reading the log's Cap'n Proto messages safely.
//
// Traversal limit: the message's own size in words (times 2, for the few pointer-following reads that
// revisit data) so a malicious message cannot make the reader walk more than it holds; nesting limit 16
// (our messages nest 3 deep).
#pragma once

#include <capnp/message.h>

#include <cstdint>
#include <vector>

#include "log/message_words.hpp"

namespace ede {

inline kj::ArrayPtr<const capnp::word> as_words(const MessageWords& words) {
  return kj::ArrayPtr<const capnp::word>(reinterpret_cast<const capnp::word*>(words.data()), words.size());
}

inline capnp::ReaderOptions reader_options(const MessageWords& words) {
  capnp::ReaderOptions o;
  o.traversalLimitInWords = 2 * words.size() + 64;
  o.nestingLimit = 16;
  return o;
}

}  // namespace ede
