// Log::Impl: what a public Log holds, and LogAccess, the library's own way into it (the analyses, verify
// and diff reach the log's reader through reader_of). A Log is a LogReader plus one cached Replay per
// scalar type, so successive seeks of the same Log continue from where the last one stopped instead of
// starting at a keyframe again. Every replay a Log's calls make asks `interrupted` before each chunk
// (Log::set_interrupt_check). Rejected: a public Log::impl() (any program could reach the internal
// reader through it); the public header names only the friend, LogAccess, which only this header defines.
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

struct LogAccess {
  using Impl = Log::Impl;
  static const Impl& impl(const Log& log) { return *log.impl_; }
};
using LogImpl = LogAccess::Impl;  // for the library's helpers over a Log's insides (replay/log.cpp)

inline const std::shared_ptr<LogReader>& reader_of(const Log& log) { return LogAccess::impl(log).reader; }

}  // namespace ede
