// Log::diff: the first event at which two logs differ, found by bisection rather than a full scan.
//
// 1. Headers: the disk count and scalar type must match; other differences (scene text, build) are notes.
// 2. Keyframes at the same event index in both logs: a binary search for the last one whose decompressed
//    record is identical. This assumes that logs which agree at a keyframe agreed on every event before
//    it, which holds because every logged event changes the state the keyframe records.
// 3. From there, chunks that start at the same event in both logs with the same length are compared as
//    decompressed records: identical ones are skipped without decoding. This is sound only while the
//    state before the chunk is the same in both (the velocity columns are coded against it), which the
//    identical keyframe and the identical events since guarantee; if the states at the start point differ
//    (no identical keyframe), chunks are not skipped.
// 4. Everything else is replayed in lockstep (two Replay<T>, next_event on both) until the first event
//    that differs, or one log ends. Where chunk boundaries part (a keyframe in one log only) the lockstep
//    runs until they meet again, and chunk comparison resumes.
// `full` skips step 2 and starts at event 0: every record is read (a damaged one is an error), still
// without replaying identical chunks.
#include "core/engine_revision.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <capnp/message.h>
#include <capnp/serialize.h>
#include <kj/exception.h>

#include "core/scalar_dispatch.hpp"
#include "ede_log.capnp.h"
#include "log/log_framing.hpp"
#include "log/log_messages.hpp"
#include "ede/log.hpp"
#include "replay/event_compare.hpp"
#include "replay/log_impl.hpp"

namespace ede {

namespace {

struct Logs {
  std::shared_ptr<LogReader> a, b;
};

struct Counters {
  bool bisected = false;
  std::size_t common_keyframes = 0, keyframes_compared = 0;
  std::size_t chunks_compared = 0, chunks_identical = 0;
  std::uint64_t lockstep_events = 0;
};

// Why two logs cannot be compared event by event, or "".
std::string incomparable(const LogHeaderInfo& a, const LogHeaderInfo& b) {
  if (a.disks != b.disks) return "A has " + std::to_string(a.disks) + " disks, B has " + std::to_string(b.disks);
  if (a.scalar != b.scalar) return std::string("A was run in ") + to_string(a.scalar) + ", B in " + to_string(b.scalar);
  return "";
}

std::string first_line_difference(const std::string& a, const std::string& b) {
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool more_a = bool(std::getline(sa, la)), more_b = bool(std::getline(sb, lb));
    if (!more_a && !more_b) return "";
    if (!more_a) la = "(end)";
    if (!more_b) lb = "(end)";
    if (la != lb || !more_a || !more_b) return "from line " + std::to_string(line) + ": A '" + la + "', B '" + lb + "'";
  }
}

void print_notes(const LogHeaderInfo& a, const LogHeaderInfo& b, std::string& text) {
  const auto note = [&](const std::string& what, const std::string& x, const std::string& y) {
    if (x != y) text += "note: the " + what + " differ: A '" + x + "', B '" + y + "'\n";
  };
  if (a.scene_text != b.scene_text)
    text += "note: the scene texts differ " + first_line_difference(a.scene_text, b.scene_text) + "\n";
  note("scene names", a.scene_name, b.scene_name);
  note("seeds", std::to_string(a.seed), std::to_string(b.seed));
  note("engine versions", a.engine_version, b.engine_version);
  if (trajectory_revision_of(a.engine_version) != trajectory_revision_of(b.engine_version))
    text += "note: A and B were written by different engine revisions (" + std::to_string(trajectory_revision_of(a.engine_version)) +
            " and " + std::to_string(trajectory_revision_of(b.engine_version)) +
            "): a later revision may take another trajectory for the same scene (CHANGELOG.md), so a difference "
            "from the first events on is expected, not a fault of either log\n";
  note("compilers", a.compiler, b.compiler);
  note("compile flags", a.compile_flags, b.compile_flags);
  note("boundaries", to_string(a.boundary), to_string(b.boundary));
  note("rebuild intervals", std::to_string(a.rebuild_interval), std::to_string(b.rebuild_interval));
  if (a.lx != b.lx || a.ly != b.ly) text += "note: the boxes differ\n";
  if (a.radius != b.radius || a.mass != b.mass || a.species != b.species)
    text += "note: the disks' radii, masses or species differ\n";
  if (a.chunk_events != b.chunk_events || a.keyframe_interval != b.keyframe_interval)
    text += "note: the log settings differ (chunk size or keyframe interval): fewer records line up\n";
}

// Keyframes at the same event index in both logs (indices into each log's keyframes()).
struct CommonKeyframe {
  std::uint64_t event = 0;
  std::vector<std::size_t> in_a, in_b;
};

std::vector<CommonKeyframe> common_keyframes(const LogReader& a, const LogReader& b) {
  std::map<std::uint64_t, CommonKeyframe> by_event;
  for (std::size_t k = 0; k < a.keyframes().size(); ++k) by_event[a.keyframes()[k].first_event].in_a.push_back(k);
  for (std::size_t k = 0; k < b.keyframes().size(); ++k) by_event[b.keyframes()[k].first_event].in_b.push_back(k);
  std::vector<CommonKeyframe> out;
  for (auto& [event, c] : by_event)
    if (!c.in_a.empty() && !c.in_b.empty()) c.event = event, out.push_back(c);
  return out;
}

// A chunk or keyframe message with its run id cleared, in canonical form: two runs with different run ids
// (e.g. another scene text) can still hold identical records, and those must compare equal.
template <class Struct>
kj::Array<capnp::word> without_run_id(const MessageWords& words) {
  capnp::FlatArrayMessageReader message(as_words(words), reader_options(words));
  capnp::MallocMessageBuilder copy;
  copy.setRoot(message.getRoot<Struct>());
  auto root = copy.getRoot<Struct>();
  root.setRunId(0);
  return capnp::canonicalize(root.asReader());
}

Result<bool> same_record(const LogReader& a, const LogRecordRef& ra, const LogReader& b, const LogRecordRef& rb) {
  auto wa = a.load_message(ra.offset, ra.payload_size);
  if (!wa) return wa.error();
  auto wb = b.load_message(rb.offset, rb.payload_size);
  if (!wb) return wb.error();
  if (wa.value() == wb.value()) return true;
  if (a.header().run_id == b.header().run_id) return false;  // the ids cannot be the difference
  try {
    const bool chunk = ra.kind == std::uint8_t(logfmt::RecordKind::Chunk);
    const kj::Array<capnp::word> ca = chunk ? without_run_id<logschema::Chunk>(wa.value())
                                            : without_run_id<logschema::Keyframe>(wa.value());
    const kj::Array<capnp::word> cb = chunk ? without_run_id<logschema::Chunk>(wb.value())
                                            : without_run_id<logschema::Keyframe>(wb.value());
    return ca.size() == cb.size() && std::memcmp(ca.begin(), cb.begin(), ca.size() * sizeof(capnp::word)) == 0;
  } catch (const kj::Exception& e) {
    return Error{a.path() + " or " + b.path() + ": a record is malformed (" + e.getDescription().cStr() + ")",
                 ErrorKind::Corrupt};
  }
}

// Identical if some keyframe of A at that event equals some keyframe of B there (a rebuild keyframe and
// an interval keyframe can share an event index in one log).
Result<bool> same_keyframe(const Logs& logs, const CommonKeyframe& c, Counters& n) {
  ++n.keyframes_compared;
  for (const std::size_t ka : c.in_a)
    for (const std::size_t kb : c.in_b) {
      auto same = same_record(*logs.a, logs.a->keyframes()[ka], *logs.b, logs.b->keyframes()[kb]);
      if (!same) return same.error();
      if (same.value()) return true;
    }
  return false;
}

// The event index of the last common keyframe that is identical in both logs (bisection), or none.
Result<std::optional<std::uint64_t>> last_identical_keyframe(const Logs& logs, Counters& n) {
  const std::vector<CommonKeyframe> common = common_keyframes(*logs.a, *logs.b);
  n.bisected = true;
  n.common_keyframes = common.size();
  std::ptrdiff_t lo = -1, hi = std::ptrdiff_t(common.size());
  while (hi - lo > 1) {
    const std::ptrdiff_t mid = lo + (hi - lo) / 2;
    auto same = same_keyframe(logs, common[std::size_t(mid)], n);
    if (!same) return same.error();
    (same.value() ? lo : hi) = mid;
  }
  if (lo < 0) return std::optional<std::uint64_t>{};
  return std::optional<std::uint64_t>{common[std::size_t(lo)].event};
}

// The chunk that starts at `event`, if any.
const LogRecordRef* chunk_starting_at(const LogReader& log, std::uint64_t event) {
  const auto& chunks = log.chunks();
  const auto it = std::lower_bound(chunks.begin(), chunks.end(), event,
                                   [](const LogRecordRef& c, std::uint64_t e) { return c.first_event < e; });
  return it != chunks.end() && it->first_event == event ? &*it : nullptr;
}

template <class T>
std::string state_difference(const Particles<T>& a, const Particles<T>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Disk<T>&p = a.disk[i], &q = b.disk[i];
    if (!same_bits(p.x, q.x) || !same_bits(p.y, q.y) || !same_bits(p.vx, q.vx) || !same_bits(p.vy, q.vy) ||
        !same_bits(p.t, q.t) || !same_bits(p.r, q.r) || !same_bits(a.mass(i), b.mass(i)) ||
        a.species_of(i) != b.species_of(i))
      return "disk " + std::to_string(i);
  }
  return "";
}

std::string how_it_ends(const LogReader& log) {
  return log.complete() ? "the run ended: " + log.final_status() : "incomplete: " + log.incomplete_reason();
}

template <class T>
class Walk {
 public:
  Walk(const Logs& logs, Replay<T>& a, Replay<T>& b, Counters& n, DiffReport& report)
      : logs_(logs), a_(a), b_(b), n_(n), r_(report) {}

  // Compares from `start` to the end of the shorter log, writing the verdict into the report.
  Status run(std::uint64_t start) {
    pos_ = start;
    if (Status s = position(); !s) return s.error();
    if (const std::string d = state_difference(a_.particles(), b_.particles()); !d.empty()) {
      r_.text += "note: the states at event " + std::to_string(start) + " differ (first at " + d +
                 "): every event is replayed\n";
      skip_chunks_ = false;
    }
    const std::uint64_t na = logs_.a->total_events(), nb = logs_.b->total_events();
    while (pos_ < na && pos_ < nb) {
      auto skipped = skip_identical_chunk();
      if (!skipped) return skipped.error();
      if (skipped.value()) continue;
      if (Status s = position(); !s) return s.error();
      auto ea = a_.next_event();
      if (!ea) return ea.error();
      auto eb = b_.next_event();
      if (!eb) return eb.error();
      ++n_.lockstep_events;
      if (const std::string field = first_difference(ea.value(), eb.value()); !field.empty()) {
        summary();
        r_.first_difference = pos_;
        r_.text += "first difference at event " + std::to_string(pos_) + " (" + field + "):\n  A: " +
                   describe(ea.value()) + "\n  B: " + describe(eb.value()) + "\n";
        return Ok{};
      }
      ++pos_;
    }
    summary();
    return end(na, nb);
  }

 private:
  // Skips the chunk at pos_ if both logs start one there, of the same length and identical content.
  Result<bool> skip_identical_chunk() {
    if (!skip_chunks_) return false;
    const LogRecordRef* ca = chunk_starting_at(*logs_.a, pos_);
    const LogRecordRef* cb = chunk_starting_at(*logs_.b, pos_);
    if (!ca || !cb || ca->count != cb->count) return false;
    ++n_.chunks_compared;
    auto same = same_record(*logs_.a, *ca, *logs_.b, *cb);
    if (!same) return same.error();
    if (!same.value()) return false;
    ++n_.chunks_identical;
    pos_ += ca->count;
    positioned_ = false;
    return true;
  }

  // Both replays at pos_ (after skipped chunks, a seek; in lockstep they are there already).
  Status position() {
    if (positioned_) return Ok{};
    if (Status s = a_.seek_event(pos_); !s) return s;
    if (Status s = b_.seek_event(pos_); !s) return s;
    positioned_ = true;
    return Ok{};
  }

  void summary() {
    std::string keyframes;
    if (n_.bisected)
      keyframes = std::to_string(n_.keyframes_compared) + " of the " + std::to_string(n_.common_keyframes) +
                  " keyframes common to both logs (bisection), ";
    r_.text += "compared: " + keyframes + std::to_string(n_.chunks_compared) + " chunks (" +
               std::to_string(n_.chunks_identical) + " identical, skipped), " + std::to_string(n_.lockstep_events) +
               " events replayed in lockstep\n";
  }

  // Both logs agree on their first min(na, nb) events.
  Status end(std::uint64_t na, std::uint64_t nb) {
    if (na != nb) {
      const bool a_shorter = na < nb;
      Replay<T>& longer = a_shorter ? b_ : a_;
      if (Status s = position(); !s) return s;
      auto next = longer.next_event();
      if (!next) return next.error();
      const std::string shorter = a_shorter ? "A" : "B", other = a_shorter ? "B" : "A";
      r_.first_difference = pos_;
      r_.text += "the first " + std::to_string(pos_) + " events are identical; then " + shorter + " ends (" +
                 how_it_ends(a_shorter ? *logs_.a : *logs_.b) + "), while " + other + " goes on:\n  " + other +
                 ": " + describe(next.value()) + "\n";
      return Ok{};
    }
    const std::string events = std::to_string(na) + " events";
    if (!logs_.a->complete() || !logs_.b->complete()) {
      if (logs_.a->complete() == logs_.b->complete()) {
        r_.identical = true;
        r_.text += "identical: " + events + " (both logs are incomplete)\n";
      } else {
        r_.text += "the " + events + " are identical, but A is " + how_it_ends(*logs_.a) + " and B is " +
                   how_it_ends(*logs_.b) + "\n";
      }
      return Ok{};
    }
    if (!same_bits(a_.final_time(), b_.final_time()) || logs_.a->final_status() != logs_.b->final_status()) {
      r_.text += "the " + events + " are identical, but the runs ended differently: A at t = " +
                 exact(a_.final_time()) + " (" + logs_.a->final_status() + "), B at t = " + exact(b_.final_time()) +
                 " (" + logs_.b->final_status() + ")\n";
      return Ok{};
    }
    r_.identical = true;
    r_.text += "identical: " + events + ", final time " + exact(a_.final_time()) + " (" + logs_.a->final_status() +
               ")\n";
    return Ok{};
  }

  const Logs& logs_;
  Replay<T>& a_;
  Replay<T>& b_;
  Counters& n_;
  DiffReport& r_;
  std::uint64_t pos_ = 0;
  bool positioned_ = false;
  bool skip_chunks_ = true;
};

template <class T>
Result<DiffReport> diff_in(const Logs& logs, bool full, DiffReport report) {
  auto a = Replay<T>::create(logs.a);
  if (!a) return a.error();
  auto b = Replay<T>::create(logs.b);
  if (!b) return b.error();
  Counters n;
  std::uint64_t start = 0;
  if (full) {
    report.text += "comparing every record from event 0 (--full)\n";
  } else {
    auto keyframe = last_identical_keyframe(logs, n);
    if (!keyframe) return keyframe.error();
    start = keyframe.value().value_or(0);
    if (keyframe.value())
      report.text += "last identical keyframe: at event " + std::to_string(start) +
                     " (the records before it are not read)\n";
    else
      report.text += "no identical keyframe (the initial records differ): comparing from event 0\n";
  }
  Walk<T> walk(logs, *a.value(), *b.value(), n, report);
  if (Status s = walk.run(start); !s) return s.error();
  return report;
}

}  // namespace

Result<DiffReport> Log::diff(const Log& other, bool full) const {
  const Logs logs{impl_->reader, other.impl_->reader};
  DiffReport report;
  report.text = "A: " + logs.a->path() + "\nB: " + logs.b->path() + "\n";
  if (const std::string why = incomparable(logs.a->header(), logs.b->header()); !why.empty())
    return Error{"the logs cannot be compared event by event: " + why};
  print_notes(logs.a->header(), logs.b->header(), report.text);
  return with_scalar(logs.a->header().scalar, [&]<class T>() { return diff_in<T>(logs, full, report); });
}

}  // namespace ede
