// convert_log: rewrites a complete log in another format version (ede-replay convert), by replaying it
// into the ordinary LogWriter: the same header (scene, seed, the writing engine's name), the same events,
// the same keyframes (periodic ones fall where the writer puts them, resumable ones are replayed from the
// original's), so the converted log's states are bit-identical to the original's and a conversion back
// gives the original's chunks again.
// Rejected: re-coding each chunk's columns in place (both encodings need the replayed state anyway, and the
// writer is the one place that knows the framing).
#include "replay/log_convert.hpp"

#include "core/energy.hpp"
#include "log/log_writer.hpp"
#include "ede/events.hpp"
#include "replay/replay.hpp"

namespace ede {

namespace {

template <class T>
Status convert_as(const std::shared_ptr<const LogReader>& log, const std::string& out_path, std::uint32_t version) {
  const LogHeaderInfo& h = log->header();
  LogRunInfo run;
  run.scene_name = h.scene_name;
  run.scene_text = h.scene_text;
  run.seed = h.seed;
  run.scalar = h.scalar;
  run.species_names = h.species_names;
  run.lx = h.lx, run.ly = h.ly;
  run.boundary = h.boundary;
  run.rebuild_interval = h.rebuild_interval;
  run.tc_model = h.tc_model;
  run.gx = h.gx, run.gy = h.gy;
  run.rotation = h.rotation();  // the replayed state carries each disk's inertia and spin
  run.thermostat = h.format_version >= 3 && version >= 3;  // thermostat events exist in version 3 only
  run.shear = h.lees_edwards;
  run.engine_version = h.engine_version, run.compiler = h.compiler, run.compile_flags = h.compile_flags;
  if (version >= 2) {
    auto scene = parse_scene_text(h.scene_text, h.scene_name);
    if (!scene) return Error{log->path() + ": the scene in the log's header no longer loads: " + scene.error().message};
    run.set_restitution(scene.value().physics);
  }
  LogSettings settings;
  settings.chunk_events = h.chunk_events;
  settings.keyframe_interval = h.keyframe_interval;
  settings.format_version = version;
  auto made_writer = LogWriter<T>::create(out_path, run, settings);
  if (!made_writer) return made_writer.error();
  LogWriter<T>& writer = *made_writer.value();
  auto made = Replay<T>::create(log);
  if (!made) return made.error();
  Replay<T>& replay = *made.value();
  auto made_points = Replay<T>::create(log);  // reads the resumable keyframes' extra fields
  if (!made_points) return made_points.error();

  const auto& keyframes = log->keyframes();
  std::size_t next_keyframe = 0;
  const auto rebuilds_at = [&](std::uint64_t events) -> Status {
    for (; next_keyframe < keyframes.size() && keyframes[next_keyframe].first_event <= events; ++next_keyframe) {
      if (!keyframes[next_keyframe].resumable || keyframes[next_keyframe].first_event != events) continue;
      auto point = made_points.value()->rebuild_point(next_keyframe);
      if (!point) return point.error();
      Particles<T> p = replay.particles();
      for (std::size_t i = 0; i < p.size(); ++i) {
        const Disk<T>& from = point.value().disks[i];
        Disk<T>& d = p.disk[i];
        d.x = from.x, d.y = from.y, d.vx = from.vx, d.vy = from.vy, d.t = from.t, d.last_partner = from.last_partner;
      }
      p.last_collision = point.value().last_collision;
      const StoredRebuildPoint<T>& r = point.value();
      writer.on_rebuild(RebuildPoint<T>{r.time, p, r.counts, r.next_sample_index, r.next_action_index,
                                        r.same_time_events, r.initial_energy});
    }
    return Ok{};
  };

  writer.on_start(replay.time(), replay.particles());
  if (Status s = rebuilds_at(0); !s) return s;
  // The records just before each event, which the writer codes against: the replayed state's, kept one
  // event behind (an event changes the records of its disks, an action every record).
  std::vector<Disk<T>> before = replay.particles().disk;
  for (std::uint64_t n = 0; n < log->total_events(); ++n) {
    auto e = replay.next_event();
    if (!e) return e.error();
    const ReplayedEvent<T>& r = e.value();
    EventOutcome<T> out{r.time, r.kind, false, r.i, r.j, r.vix, r.viy, r.vjx, r.vjy,
                        r.vix0, r.viy0, r.vjx0, r.vjy0, r.wi, r.wj, r.wi0, r.wj0};
    const std::vector<Disk<T>>& now = replay.particles().disk;
    if (r.kind == EventKind::Shear) out.vjx = now[std::size_t(r.i)].x;  // the outcome carries the new x there
    if (r.i >= 0) out.before_i = record_before(before[std::size_t(r.i)]), before[std::size_t(r.i)] = now[std::size_t(r.i)];
    if (r.kind == EventKind::Pair || r.kind == EventKind::Step)
      out.before_j = record_before(before[std::size_t(r.j)]), before[std::size_t(r.j)] = now[std::size_t(r.j)];
    if (r.kind == EventKind::Action) before = now;
    writer.on_event(out, replay.particles());
    if (Status s = rebuilds_at(n + 1); !s) return s;
  }
  writer.on_finish(replay.final_time(), replay.particles(), status_from_text(log->final_status()));
  if (std::string e = writer.error(); !e.empty()) return Error{e};
  return Ok{};
}

}  // namespace

Status convert_log(const std::shared_ptr<const LogReader>& log, const std::string& out_path, std::uint32_t version) {
  if (!log->complete())
    return Error{log->path() + ": the log is incomplete (" + log->incomplete_reason() +
                 "); finish or resume the run before converting it"};
  if (log->damaged()) return Error{log->path() + ": the log is damaged; it cannot be converted"};
  if (version < 1 || version > 3)
    return Error{"format version " + std::to_string(version) + " is not one this ede writes (1, 2 or 3)"};
  if (log->header().format_version >= 3 && version < 3)
    return Error{log->path() + ": a log of format version 3 (a stepped potential's step events, the thermostat's "
                 "redraws, a Lees-Edwards box's shear events) cannot be written in format version " +
                 std::to_string(version) + ", which has none of them; keep version 3"};
  if (log->header().rotation() && version < 2)
    return Error{log->path() + ": a log of rough (rotating) disks cannot be written in format version 1, which has "
                 "no angular velocities; convert it to version 2 (--format-version 2)"};
  switch (log->header().scalar) {
    case ScalarKind::Float: return convert_as<float>(log, out_path, version);
    case ScalarKind::LongDouble: return convert_as<long double>(log, out_path, version);
    default: return convert_as<double>(log, out_path, version);
  }
}

}  // namespace ede
