// Log (ede/log.hpp): opening, info, states, counts, digests and conversion over LogReader and Replay<T>;
// its events are in log_events.cpp, diff in diff.cpp, and verify, which re-runs the scene, in run/verify.cpp.
//
// The public Log is implemented here in replay/, the room that turns a log into states, above log/, the
// format (LogReader and LogWriter: bytes to records and back), which cannot know Replay
// (docs/architecture.md, "Names"). Every entry point dispatches once on the log's scalar type and then
// works in T; states leave as columns in T (state_of).
#include "ede/log.hpp"

#include <cmath>
#include <memory>
#include <utility>

#include "core/scalar_dispatch.hpp"
#include "core/sliding_images.hpp"
#include "core/state_of.hpp"
#include "log/log_stats.hpp"
#include "replay/log_convert.hpp"
#include "replay/log_digest.hpp"
#include "replay/log_impl.hpp"

namespace ede {

namespace {

LogInfo info_of(const LogReader& r) {
  const LogHeaderInfo& h = r.header();
  LogInfo i;
  i.path = r.path();
  i.format_version = h.format_version;
  i.engine_version = h.engine_version, i.compiler = h.compiler, i.compile_flags = h.compile_flags;
  i.scalar = h.scalar;
  i.seed = h.seed;
  i.scene_name = h.scene_name, i.scene_text = h.scene_text;
  i.disks = h.disks;
  i.species_names = h.species_names;
  i.species_counts.assign(h.species_names.size(), 0);
  for (const std::uint32_t s : h.species) ++i.species_counts[s];  // the reader checked every index
  i.lx = h.lx, i.ly = h.ly, i.boundary = h.boundary, i.lees_edwards = h.lees_edwards;
  if (i.lees_edwards)
    if (auto scene = parse_scene_text(i.scene_text, i.scene_name); scene && scene.value().shear_rate)
      i.shear_rate = *scene.value().shear_rate;
  i.rotates = h.rotation();
  i.tc_model = h.tc_model, i.gx = h.gx, i.gy = h.gy;
  i.initial_energy = h.initial_energy;
  i.chunk_events = h.chunk_events, i.keyframe_interval = h.keyframe_interval, i.rebuild_interval = h.rebuild_interval;
  i.events = r.total_events();
  i.chunks = r.chunks().size(), i.keyframes = r.keyframes().size();
  for (const LogRecordRef& k : r.keyframes()) i.resumable_keyframes += k.resumable ? 1 : 0;
  i.file_size = r.file_size();
  i.start_time = r.keyframes().front().time_first;
  i.end_time = with_scalar(h.scalar, [&]<class T>() { return Time(log_final_time<T>(r, T(i.start_time))); });
  if (!r.chunks().empty())
    i.first_event_time = r.chunks().front().time_first, i.last_event_time = r.chunks().back().time_last;
  i.complete = r.complete(), i.damaged = r.damaged();
  i.incomplete_reason = r.incomplete_reason(), i.final_status = r.final_status();
  return i;
}

// The state of a replay, with the images' offset of a Lees-Edwards log at its time as the run had it
// (core/sliding_images.hpp, in the run's type).
template <class T>
State public_state(const Replay<T>& r, const LogInfo& i) {
  State s = state_of(r.particles(), r.time(), r.events_applied(), i.lx, i.ly, i.boundary, i.species_names);
  if (i.lees_edwards) s.shear_offset = double(images_offset(image_slide(i.shear_rate, T(i.ly)), r.time(), T(i.lx)));
  return s;
}

}  // namespace

Log::Log(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}

Result<Log> Log::open(const std::string& path, const LogLimits& limits) {
  auto reader = LogReader::open(path, ReadLimits{limits.max_disks, limits.max_record_bytes});
  if (!reader) return reader.error();
  auto impl = std::make_shared<Impl>();
  impl->reader = std::move(reader).value();
  impl->info = info_of(*impl->reader);
  return Log(std::move(impl));
}

const LogInfo& Log::info() const { return impl_->info; }

void Log::set_interrupt_check(std::function<bool()> interrupted) { impl_->interrupted = std::move(interrupted); }

Result<Scene> Log::scene() const { return parse_scene_text(impl_->info.scene_text, impl_->info.scene_name); }

Result<State> Log::state_at(Time t) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Result<State> {
    auto replay = impl_->replay_in<T>();
    if (!replay) return replay.error();
    Replay<T>& r = *replay.value();
    if (Status s = r.seek_time(T(t)); !s) return s.error();
    return public_state(r, impl_->info);
  });
}

Result<State> Log::state_at_event(std::uint64_t n) const {
  return with_scalar(impl_->info.scalar, [&]<class T>() -> Result<State> {
    auto replay = impl_->replay_in<T>();
    if (!replay) return replay.error();
    Replay<T>& r = *replay.value();
    if (Status s = r.seek_event(n); !s) return s.error();
    return public_state(r, impl_->info);
  });
}

Result<State> Log::state_at_end() const {
  // The end of a log cut short is its last event: seeking to it by index is exact in every scalar type.
  if (!impl_->info.complete) return state_at_event(impl_->info.events);
  return state_at(impl_->info.end_time);
}

Result<EventCounts> Log::count_events() const {
  auto counts = count_logged_kinds(*impl_->reader);
  if (!counts) return counts.error();
  EventCounts c;
  for (int k = 0; k < kEventKindCount; ++k) c.by_kind[k] = counts.value().by_kind[k];
  return c;
}

Result<std::vector<std::uint64_t>> Log::events_after_collisions(const std::vector<double>& collisions_per_disk) const {
  std::vector<std::uint64_t> pairs;
  for (const double c : collisions_per_disk) {
    if (!std::isfinite(c) || c < 0)
      return Error{"collisions per disk must be finite and >= 0, got " + std::to_string(c)};
    // As the engine counts its schedules (engine_core.hpp, pairs_for).
    pairs.push_back(static_cast<std::uint64_t>(std::ceil(c * double(impl_->info.disks) / 2)));
    if (pairs.size() > 1 && pairs.back() < pairs[pairs.size() - 2])
      return Error{"collisions per disk must be given in ascending order"};
  }
  return events_through_pairs(*impl_->reader, pairs);
}

Result<std::string> Log::content_digest() const { return log_content_digest(impl_->reader); }

Status Log::convert(const std::string& out_path, std::uint32_t format_version) const {
  return convert_log(impl_->reader, out_path, format_version);
}

}  // namespace ede
