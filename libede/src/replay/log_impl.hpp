// Log::Impl: what a public Log holds, for the library's own code (analysis functions reach the reader
// through it). A Log is a LogReader plus one cached Replay per scalar type, so successive seeks of the
// same Log continue from where the last one stopped instead of starting at a keyframe again. Every replay
// a Log's calls make asks `interrupted` before each chunk (Log::set_interrupt_check).
#pragma once

#include <functional>
#include <memory>
#include <variant>

#include "ede/log.hpp"
#include "log/log_reader.hpp"
#include "replay/replay.hpp"

namespace ede {

struct Log::Impl {
  std::shared_ptr<LogReader> reader;
  LogInfo info;
  std::function<bool()> interrupted;
  mutable std::variant<std::monostate, std::unique_ptr<Replay<float>>, std::unique_ptr<Replay<double>>,
                       std::unique_ptr<Replay<long double>>>
      replay;

  // The cached replay in T (the log's scalar type), made on first use.
  template <class T>
  Result<Replay<T>*> replay_in() const {
    if (auto* r = std::get_if<std::unique_ptr<Replay<T>>>(&replay)) return r->get();
    auto made = Replay<T>::create(reader);
    if (!made) return made.error();
    Replay<T>* p = made.value().get();
    p->set_interrupt_check(&interrupted);
    replay = std::move(made).value();
    return p;
  }
};

inline const std::shared_ptr<LogReader>& reader_of(const Log& log) { return log.impl().reader; }

}  // namespace ede
