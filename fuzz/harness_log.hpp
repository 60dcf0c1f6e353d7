// Fuzz target: the log reader and replay on arbitrary bytes.
//
// The bytes become a file (memfd); opening it must give a LogReader or a clear error, and replaying
// everything it holds (the content digest, and seeks by time and event) must succeed or fail with a
// message: no crash, no hang, no sanitizer report, no huge allocation (tight ReadLimits: a log claiming
// more is refused before allocation). Seed corpus: fuzz/corpus/log (small valid logs of several scalar
// types and effects, made by scripts/make_fuzz_corpus.sh), which libFuzzer mutates: flipped bits, cut
// records, forged lengths and offsets.
// The harness returns false on a violated check; the fuzz target traps on it, the test suite fails.
#pragma once

#include "memfile.hpp"
#include <cstddef>
#include <cstdint>
#include <string>

#include "replay/log_digest.hpp"
#include "log/log_reader.hpp"
#include "replay/replay.hpp"

namespace ede::fuzz {

template <class T>
inline void replay_some(const std::shared_ptr<ede::LogReader>& log) {
  auto r = ede::Replay<T>::create(log);
  if (!r) return;
  ede::Replay<T>& replay = *r.value();
  (void)replay.seek_event(log->total_events() / 2);
  (void)replay.seek_time(replay.final_time());
  (void)replay.seek_event(0);
}

inline bool fuzz_log(const std::uint8_t* data, std::size_t size) {
  const MemFile file("fuzz-log");
  if (!file.ok() || !file.write_all(data, size)) return true;
  const std::string path = file.path();
  ede::ReadLimits limits;
  limits.max_disks = 5000;
  limits.max_record_bytes = std::uint64_t(16) << 20;
  auto log = ede::LogReader::open(path, limits);
  if (log) {
    if (log.value()->total_events() <= 200000) (void)ede::log_content_digest(log.value());
    switch (log.value()->header().scalar) {
      case ede::ScalarKind::Float: replay_some<float>(log.value()); break;
      case ede::ScalarKind::Double: replay_some<double>(log.value()); break;
      case ede::ScalarKind::LongDouble: replay_some<long double>(log.value()); break;
      case ede::ScalarKind::Float128: break;  // never in a log (LogHeaderInfo::scalar)
    }
  } else if (log.error().message.empty()) {
    return false;
  }
  return true;
}

}  // namespace ede::fuzz
