// log_content_digest; see log_digest.hpp. Replays the whole log once.
#include "replay/log_digest.hpp"

#include "replay/replay.hpp"
#include "log/scalar_bytes.hpp"
#include "core/xxh3.hpp"

namespace ede {

namespace {

template <class T>
void put_scalar(Xxh3Hash& h, T v) {
  unsigned char b[kScalarWidth<T>];
  scalar_to_bytes(v, b);
  h.update(b, sizeof b);
}

template <class T>
Result<std::string> digest_as(std::shared_ptr<const LogReader> log) {
  auto made = Replay<T>::create(log);
  if (!made) return made.error();
  Replay<T>& replay = *made.value();
  const LogHeaderInfo& info = log->header();
  Xxh3Hash h;
  h.update(info.scene_text.data(), info.scene_text.size());
  const unsigned char scalar = static_cast<unsigned char>(info.scalar);
  h.update(&scalar, 1);
  h.update(info.radius.data(), info.radius.size());
  h.update(info.mass.data(), info.mass.size());
  const Status s = replay.for_each_event(0, log->total_events(), [&](const ReplayedEvent<T>& e) {
    h.update(&e.index, sizeof e.index);
    put_scalar(h, e.time);
    const unsigned char kind = static_cast<unsigned char>(e.kind);
    h.update(&kind, 1);
    h.update(&e.i, sizeof e.i);
    h.update(&e.j, sizeof e.j);
    for (T v : {e.vix, e.viy, e.vjx, e.vjy}) put_scalar(h, v);
    return true;
  });
  if (!s) return s.error();
  for (const Disk<T>& d : replay.particles().disk)
    for (T v : {d.x, d.y, d.vx, d.vy, d.t}) put_scalar(h, v);
  return std::string(kDigestAlgorithm) + ":" + h.hex();
}

}  // namespace

Result<std::string> log_content_digest(std::shared_ptr<const LogReader> log) {
  switch (log->header().scalar) {
    case ScalarKind::Float: return digest_as<float>(log);
    case ScalarKind::LongDouble: return digest_as<long double>(log);
    case ScalarKind::Double: break;
    case ScalarKind::Float128: break;  // never in a log (LogHeaderInfo::scalar)
  }
  return digest_as<double>(log);
}

}  // namespace ede
