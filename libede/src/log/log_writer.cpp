// LogWriter<T>: chunks, keyframes, index, trailer; see log_writer.hpp and schema/FORMAT.md.
//
// Chunk boundaries are a function of the event index alone (every chunk_events events, and at every
// keyframe), so a resumed run cut at a keyframe writes exactly the chunks the uninterrupted run wrote.
// The event loop only copies each event (with its time's prediction where the engine did not vouch for it,
// made from the records of its disks just before it) into the open chunk's buffer (log/logged_event.hpp);
// the columns are coded on the record writer's worker (ChunkCoder below) from those alone. The worker
// builds records in submission order, so the bytes are those of coding on the loop. Rejected: handing a
// chunk's events over in batches of 2048 (warm buffers, peak RSS at N = 10^4 14.6 -> 11.7 MiB): with loop
// and worker on one core its eight wake-ups per chunk cost more than the warm buffers saved (log cost
// 13.7 % against 12.4 % without, ede-bench peers, 3 rounds, 2026-11-29). Rejected: coding on the event loop (measured: at N = 1e4, log format 2's predictions took the
// logging overhead from 8-14 % to 34 % with a second core free), and a replayed copy of the state on the
// worker (its cache misses were most of the log's cost when loop and worker share one core).
#include "log/log_writer.hpp"
#include "log/run_id.hpp"

#include <capnp/message.h>
#include <capnp/serialize.h>

#include <algorithm>
#include <cstring>
#include <mutex>

#include "core/build_info.hpp"
#include "core/engine_revision.hpp"
#include "core/energy.hpp"
#include "log/chunk_codec.hpp"
#include "log/event_coder.hpp"
#include "log/logged_event.hpp"
#include "ede_log.capnp.h"
#include "log/log_framing.hpp"
#include "log/flat_message.hpp"
#include "log/record_writer.hpp"
#include "log/scalar_bytes.hpp"
#include "scene/scene_label.hpp"

namespace ede {

namespace {

template <class T>
logschema::ScalarType schema_scalar() {
  if constexpr (std::is_same_v<T, float>) return logschema::ScalarType::FLOAT32;
  if constexpr (std::is_same_v<T, double>) return logschema::ScalarType::FLOAT64;
  return logschema::ScalarType::FLOAT80;
}

// The root struct of a record. A run without rotation builds it at the size the schema had before rotation
// (`data_words`, `pointers`: the fields it sets all lie within), because Cap'n Proto lays out a struct at
// its schema's full size, null pointers included: so such a run's records keep their bytes. Rough runs
// build the full struct, rotation fields included. Readers see absent fields as empty either way.
template <class S>
typename S::Builder init_record(capnp::MessageBuilder& message, bool full, std::uint16_t data_words,
                                std::uint16_t pointers) {
  if (full) return message.initRoot<S>();
  return message.getRoot<capnp::AnyPointer>().initAsAnyStruct(data_words, pointers).template as<S>();
}
// The sizes before rotation (data words, pointers); the rotation fields are pointers appended after them.
constexpr std::uint16_t kHeaderWords = 11, kHeaderPointers = 11;
constexpr std::uint16_t kChunkWords = 2, kChunkPointers = 6;
constexpr std::uint16_t kKeyframeWords = 5, kKeyframePointers = 9;
static_assert(capnp::_::structSize<logschema::Header>().data == kHeaderWords &&
              capnp::_::structSize<logschema::Header>().pointers == kHeaderPointers + 2);
static_assert(capnp::_::structSize<logschema::Chunk>().data == kChunkWords &&
              capnp::_::structSize<logschema::Chunk>().pointers == kChunkPointers + 1);
static_assert(capnp::_::structSize<logschema::Keyframe>().data == kKeyframeWords &&
              capnp::_::structSize<logschema::Keyframe>().pointers == kKeyframePointers + 1);

// Words of a record's root struct, pointer included (init_record's sizes, or the schema's).
template <class S>
constexpr std::size_t root_words(bool full, std::uint16_t data_words, std::uint16_t pointers) {
  return 1 + (full ? std::size_t(capnp::_::structSize<S>().data) + capnp::_::structSize<S>().pointers
                   : std::size_t(data_words) + pointers);
}

void set_data(capnp::Data::Builder out, const std::vector<unsigned char>& bytes) {
  if (!bytes.empty()) std::memcpy(out.begin(), bytes.data(), bytes.size());
}
void set_data(capnp::Data::Builder out, ColumnView bytes) {
  if (bytes.size) std::memcpy(out.begin(), bytes.data, bytes.size);
}

// A per-disk column of scalars, byte-plane shuffled (positions and velocities share their high bytes):
// byte b of value i at out[b * n + i], shuffle_bytes' layout, written straight into the message's Data
// (no raw and shuffled copies next to the message being built).
template <class T, class F>
void set_scalar_column(capnp::Data::Builder out, std::size_t n, F value_of) {
  unsigned char* const o = out.begin();
  for (std::size_t i = 0; i < n; ++i) {
    unsigned char b[kScalarWidth<T>];
    scalar_to_bytes<T>(value_of(i), b);
    for (std::size_t k = 0; k < kScalarWidth<T>; ++k) o[k * n + i] = b[k];
  }
}

template <class T>
std::vector<unsigned char> raw_scalars(const std::vector<T>& v) {
  std::vector<unsigned char> b(v.size() * kScalarWidth<T>);
  for (std::size_t k = 0; k < v.size(); ++k) scalar_to_bytes(v[k], b.data() + k * kScalarWidth<T>);
  return b;
}

template <class T>
std::vector<unsigned char> one_scalar(T v) {
  std::vector<unsigned char> b(kScalarWidth<T>);
  scalar_to_bytes(v, b.data());
  return b;
}

}  // namespace

std::uint64_t auto_keyframe_interval(std::size_t disks) {
  return std::max<std::uint64_t>(std::uint64_t(1) << 18, 16 * std::uint64_t(disks));
}

LogSettings LogSettings::from(const LogSpec& spec) {
  LogSettings s;
  if (spec.keyframe_interval) s.keyframe_interval = *spec.keyframe_interval;
  if (spec.chunk_events) s.chunk_events = *spec.chunk_events;
  if (spec.compression_level) s.compression_level = *spec.compression_level;
  return s;
}

// The engine's table (Engine::setup_restitution): every pair at xi, then the named pairs; an elastic engine
// applies none of it, and then every value is 1 anyway.
void LogRunInfo::set_restitution(const PhysicsSpec& physics) {
  const std::size_t n = std::max<std::size_t>(species_names.size(), 1);
  pair_restitution.assign(n * n, physics.restitution);
  const auto index_of = [&](const std::string& name) {
    return std::size_t(std::find(species_names.begin(), species_names.end(), name) - species_names.begin());
  };
  for (const PairRestitution& pr : physics.pairs) {
    const std::size_t a = index_of(pr.a), b = index_of(pr.b);
    if (a < n && b < n) pair_restitution[a * n + b] = pair_restitution[b * n + a] = pr.value;
  }
  for (int w = 0; w < 4; ++w) wall_restitution[w] = physics.wall(w);
  pair_roughness.assign(n * n, physics.roughness);  // Engine::setup_roughness
  for (const PairRestitution& pr : physics.pairs) {
    const std::size_t a = index_of(pr.a), b = index_of(pr.b);
    if (a < n && b < n) pair_roughness[a * n + b] = pair_roughness[b * n + a] = physics.pair_roughness(pr);
  }
  wall_roughness = physics.wall_roughness;
  segments.clear();
  for (const SegmentSpec& s : physics.segments)
    segments.insert(segments.end(), {s.from[0], s.from[1], s.to[0], s.to[1], s.restitution});
}

// What codes the columns on the record writer's worker: the encoder, from the events' values and their
// predictions (made on the event loop, log/event_coder.hpp).
template <class T>
struct ChunkCoder {
  ChunkEncoder<T> chunk;
  std::uint32_t run_id = 0;  // the header's (log/run_id.hpp), repeated in every chunk
  bool rotation = false;     // rough run: chunks carry the spin column

  ChunkCoder(std::uint32_t version, bool rough) : chunk(version, rough), rotation(rough) {}

  FlatMessage code(std::uint64_t first_event, const ChunkEvents<T>& events) {
    chunk.reset(first_event);
    chunk.add_all(events);
    const ChunkColumns c = chunk.columns();
    FlatMessageBuilder message(root_words<logschema::Chunk>(rotation, kChunkWords, kChunkPointers) +
                                   message_words_of(c.times.size) + message_words_of(c.kinds.size) +
                                   message_words_of(c.disks.size) + message_words_of(c.partners.size) +
                                   message_words_of(c.raw.size) + message_words_of(c.residuals.size) +
                                   message_words_of(c.spins.size),
                               &spare);
    auto b = init_record<logschema::Chunk>(message, rotation, kChunkWords, kChunkPointers);
    b.setFirstEvent(first_event);
    b.setCount(chunk.count());
    b.setRunId(run_id);
    set_data(b.initTimes(std::uint32_t(c.times.size)), c.times);
    set_data(b.initKinds(std::uint32_t(c.kinds.size)), c.kinds);
    set_data(b.initDisks(std::uint32_t(c.disks.size)), c.disks);
    set_data(b.initPartners(std::uint32_t(c.partners.size)), c.partners);
    set_data(b.initVelocitiesRaw(std::uint32_t(c.raw.size)), c.raw);
    set_data(b.initVelocityResiduals(std::uint32_t(c.residuals.size)), c.residuals);
    if (rotation) set_data(b.initSpinResiduals(std::uint32_t(c.spins.size)), c.spins);
    return message.finish();
  }

  // A chunk's message once compressed (the record writer's recycler, on the worker like code()): its block
  // is the next chunk's reservation, so a chunk costs no allocation and no zeroing of fresh memory (a new
  // calloc'ed reservation per chunk was ~2 % of a run's instructions at N = 10^4, in memset).
  void recycle(FlatMessage&& m) {
    if (m.reusable()) spare = std::move(m);
  }
  FlatMessage spare;
};

// Chunk buffers handed back by the worker once coded, for the event loop to fill again: a new 16 384-event
// buffer for every chunk meant fresh pages for every chunk (measured: ~6 % of a run at N = 10^4 in page
// faults, with loop and worker on one core).
template <class T>
class ChunkPool {
 public:
  ChunkEvents<T> take(bool rough, bool format_v1) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (spare_.empty()) return ChunkEvents<T>(rough, format_v1);
    ChunkEvents<T> c = std::move(spare_.back());
    spare_.pop_back();
    return c;
  }
  void give(ChunkEvents<T>&& c) {
    c.clear();
    std::lock_guard<std::mutex> lock(mutex_);
    if (spare_.size() < kKept) spare_.push_back(std::move(c));
  }

 private:
  static constexpr std::size_t kKept = 2;
  std::mutex mutex_;
  std::vector<ChunkEvents<T>> spare_;
};

template <class T>
struct LogWriter<T>::Impl {
  LogRunInfo run;
  LogSettings settings;
  RecordWriter out;
  // The header's physics, for the predictions made on the event loop (event_coder) and the header itself.
  EventPhysics<T> physics;
  EventCoder<T> event_coder{physics, settings.format_version, settings.check_exactness, run.engine_constants};
  ChunkCoder<T> coder{settings.format_version, run.rotation};  // the worker's
  ChunkPool<T> pool;
  bool coder_ready = false;
  std::uint64_t next_keyframe = 0;  // the logged-event count at which the next periodic keyframe is written
  // The open chunk, on the event loop: its events as the engine reported them.
  ChunkEvents<T> chunk_events;
  std::uint64_t chunk_first = 0;
  std::uint64_t logged = 0;
  struct Pending {  // an index entry whose offset is known once the record is written
    std::size_t sequence;
    LogContinuation::Entry entry;
  };
  std::vector<LogContinuation::Entry> kept;  // entries of a continued log's first part (offsets known)
  std::vector<Pending> pending;
  std::uint64_t bytes = 0;
  std::uint32_t run_id = 0;  // log/run_id.hpp: the header's digest, or a continued log's
  bool finished = false;

  Impl(const std::string& path, const LogRunInfo& r, const LogSettings& s, std::uint64_t start, int level)
      : run(r), settings(s), out(path, start, level) {
    out.set_recycler([coder = &coder](FlatMessage&& m) { coder->recycle(std::move(m)); });
  }
  // The worker may still be coding a chunk: stop it before the coder goes.
  ~Impl() { out.finish(); }

  // What needs the disks: the physics (predictions), whether masses and species differ between disks, and
  // the automatic keyframe interval. Runs on the event loop before the first chunk is submitted, so before
  // the worker touches the coder.
  void ensure_coder(const Particles<T>& p) {
    if (coder_ready) return;
    if (settings.keyframe_interval == 0) settings.keyframe_interval = auto_keyframe_interval(p.size());
    next_keyframe = (logged / settings.keyframe_interval + 1) * settings.keyframe_interval;
    setup_coder(p);
  }

  void setup_coder(const Particles<T>&) {
    coder_ready = true;
    physics = EventPhysics<T>::box(run.lx, run.ly, run.boundary == BoundaryKind::Periodic, T(run.gx), T(run.gy));
    physics.species = std::max<std::size_t>(run.species_names.size(), 1);
    physics.one_plus_xi.clear();
    for (const double xi : run.pair_restitution) physics.one_plus_xi.push_back(T(1) + T(xi));
    physics.one_plus_xi.resize(physics.species * physics.species, physics.one_plus_xi.empty() ? T(2) : physics.one_plus_xi[0]);
    for (int w = 0; w < 4; ++w) physics.xi_wall[w] = T(run.wall_restitution[w]);
    for (std::size_t k = 0; k + 5 <= run.segments.size(); k += 5) {
      const double* g = &run.segments[k];
      physics.segments.push_back(rules::v2::make_segment(T(g[0]), T(g[1]), T(g[2]), T(g[3]), T(g[4])));
    }
    physics.tc_model = run.tc_model;
    physics.rough = run.rotation;
    if (run.rotation) {
      physics.one_plus_beta.clear();
      for (const double b : run.pair_roughness) physics.one_plus_beta.push_back(T(1) + T(b));
      physics.one_plus_beta.resize(physics.species * physics.species,
                                   physics.one_plus_beta.empty() ? T(0) : physics.one_plus_beta[0]);
      physics.wall_one_plus_beta = T(1) + T(run.wall_roughness);
    }
  }

  // Words of the header's message: texts and the small tables are a guess (a short one only costs a copy);
  // the per-disk columns exact.
  std::size_t header_words(std::size_t n) const {
    const std::size_t column = message_words_of(n * kScalarWidth<T>);
    return root_words<logschema::Header>(run.rotation, kHeaderWords, kHeaderPointers) + 256 +
           message_words_of(run.scene_text.size() + 1) + message_words_of(run.scene_name.size() + 1) +
           2 * run.species_names.size() + 3 * column + message_words_of(4 * n) + (run.rotation ? column : 0) +
           message_words_of(kScalarWidth<T> * (run.pair_restitution.size() + run.segments.size() +
                                               2 * run.pair_roughness.size() + 8));
  }

  // The run id is computed from a message built for it alone (the build texts empty, run id 0: what
  // run_id_of would make of the header), freed before the header itself is built: copying the finished
  // header for it (run_id_of) kept three header-sized arrays alive at once next to the engine (~72 B/disk
  // at N = 1e6, the run's peak RSS with the log).
  void write_header(const Particles<T>& p) {
    const std::size_t words = header_words(p.size());
    // Set before the first chunk is submitted: the worker reads coder.run_id only after that. Format
    // version 1 predates run ids and keeps its bytes (its records carry 0: not checked).
    if (settings.format_version >= 2) {
      FlatMessageBuilder for_id(words);
      auto h = init_record<logschema::Header>(for_id, run.rotation, kHeaderWords, kHeaderPointers);
      fill_header(h, p, true);
      run_id = coder.run_id = run_id_of_cleared(h.asReader());
    }
    FlatMessageBuilder message(words);
    auto h = init_record<logschema::Header>(message, run.rotation, kHeaderWords, kHeaderPointers);
    fill_header(h, p, false);
    h.setRunId(run_id);
    logfmt::RecordHeader rh;
    rh.kind = logfmt::RecordKind::Header;
    out.submit(rh, message.finish());
  }

  // Every field of the header but the run id; `for_id`: the engine version, compiler and flags empty.
  void fill_header(logschema::Header::Builder h, const Particles<T>& p, bool for_id) {
    const std::size_t n = p.size();
    h.setEngineVersion(for_id ? std::string() : run.engine_version.empty() ? engine_version_text() : run.engine_version);
    h.setCompiler(for_id ? std::string() : run.compiler.empty() ? build_compiler() : run.compiler);
    h.setCompileFlags(for_id ? std::string() : run.compile_flags.empty() ? build_flags() : run.compile_flags);
    h.setScalar(schema_scalar<T>());
    h.setSeed(run.seed);
    h.setSceneName(run.scene_name);
    h.setSceneText(run.scene_text);
    h.setDiskCount(std::uint32_t(p.size()));
    auto names = h.initSpeciesNames(std::uint32_t(run.species_names.size()));
    for (std::size_t k = 0; k < run.species_names.size(); ++k) names.set(std::uint32_t(k), run.species_names[k]);
    h.setBoxX(run.lx);
    h.setBoxY(run.ly);
    h.setBoundary(run.shear                                ? logschema::Boundary::LEES_EDWARDS
                  : run.boundary == BoundaryKind::Periodic ? logschema::Boundary::PERIODIC
                                                           : logschema::Boundary::WALLS);
    h.setChunkEvents(settings.chunk_events);
    h.setKeyframeInterval(settings.keyframe_interval);
    h.setRebuildInterval(run.rebuild_interval);
    set_scalar_column<T>(h.initRadius(std::uint32_t(n * kScalarWidth<T>)), n, [&](std::size_t i) { return p.disk[i].r; });
    set_scalar_column<T>(h.initMass(std::uint32_t(n * kScalarWidth<T>)), n, [&](std::size_t i) { return p.mass(i); });
    auto species = h.initSpecies(std::uint32_t(p.size()));
    for (std::size_t i = 0; i < p.size(); ++i) species.set(std::uint32_t(i), std::uint32_t(p.species_of(i)));
    h.setInitialEnergy(kinetic_energy(p));
    h.setTcModel(run.tc_model);
    h.setColumnEncoding(settings.format_version);
    h.setGravityX(run.gx);
    h.setGravityY(run.gy);
    if (settings.format_version >= 2) {
      set_data(h.initPairOnePlusXi(std::uint32_t(physics.one_plus_xi.size() * kScalarWidth<T>)),
               raw_scalars(physics.one_plus_xi));
      std::vector<T> walls(physics.xi_wall, physics.xi_wall + 4);
      for (const double v : run.segments) walls.push_back(T(v));
      set_data(h.initWallRestitution(std::uint32_t(walls.size() * kScalarWidth<T>)), raw_scalars(walls));
      if (run.rotation) {
        set_scalar_column<T>(h.initInertia(std::uint32_t(n * kScalarWidth<T>)), n,
                             [&](std::size_t i) { return p.inertia[i]; });
        std::vector<T> beta = physics.one_plus_beta;
        beta.insert(beta.end(), 4, physics.wall_one_plus_beta);
        set_data(h.initOnePlusBeta(std::uint32_t(beta.size() * kScalarWidth<T>)), raw_scalars(beta));
      }
    }
  }

  void flush_chunk() {
    if (chunk_events.empty()) return;
    logfmt::RecordHeader rh;
    rh.kind = logfmt::RecordKind::Chunk;
    rh.first_event = chunk_first;
    rh.event_count = chunk_events.size();
    rh.time_first = double(chunk_events.time_first());
    rh.time_last = double(chunk_events.time_last());
    const std::size_t seq = out.submit_built(rh, [coder = &coder, pool = &pool, first = chunk_first,
                                                  events = std::move(chunk_events)]() mutable {
      FlatMessage m = coder->code(first, events);
      pool->give(std::move(events));
      return m;
    });
    pending.push_back({seq, {std::uint8_t(logfmt::RecordKind::Chunk), 0, rh.first_event, rh.event_count,
                             rh.time_first, rh.time_last, false}});
    chunk_events = pool.take(run.rotation, settings.format_version < 2);
    chunk_events.reserve(settings.chunk_events);
    chunk_first = logged;
  }

  // A large keyframe (its state columns above the record writer's two-pass size) is built once everything
  // before it is written and freed (the header's message, the chunks queued), so that its message is the
  // largest thing alive next to the engine (docs/performance.md, "Memory at 10⁶ with the log").
  void write_keyframe(const Particles<T>& p, T time, const RebuildPoint<T>* rebuild) {
    flush_chunk();
    if (p.size() * 5 * kScalarWidth<T> > RecordWriter::kTwoPassAbove) out.flush();
    const std::size_t n = p.size();
    FlatMessageBuilder message(keyframe_words(n, rebuild));
    auto k = init_record<logschema::Keyframe>(message, run.rotation, kKeyframeWords, kKeyframePointers);
    k.setEventsBefore(logged);
    k.setRunId(run_id);
    set_data(k.initTime(kScalarWidth<T>), one_scalar(time));
    k.setResumable(rebuild != nullptr);
    const std::uint32_t bytes_per_column = std::uint32_t(n * kScalarWidth<T>);
    const auto column = [&](capnp::Data::Builder out, auto value_of) { set_scalar_column<T>(out, n, value_of); };
    column(k.initX(bytes_per_column), [&](std::size_t i) { return p.disk[i].x; });
    column(k.initY(bytes_per_column), [&](std::size_t i) { return p.disk[i].y; });
    column(k.initVx(bytes_per_column), [&](std::size_t i) { return p.disk[i].vx; });
    column(k.initVy(bytes_per_column), [&](std::size_t i) { return p.disk[i].vy; });
    column(k.initT(bytes_per_column), [&](std::size_t i) { return p.disk[i].t; });
    if (run.rotation) column(k.initOmega(bytes_per_column), [&](std::size_t i) { return p.omega[i]; });
    if (rebuild) write_resume_fields(k, *rebuild);
    logfmt::RecordHeader rh;
    rh.kind = logfmt::RecordKind::Keyframe;
    rh.first_event = logged;
    rh.time_first = rh.time_last = double(time);
    rh.resumable = rebuild != nullptr;
    const std::size_t seq = out.submit(rh, message.finish());
    pending.push_back({seq, {std::uint8_t(logfmt::RecordKind::Keyframe), 0, logged, 0, rh.time_first,
                             rh.time_last, rh.resumable}});
  }

  // The words of a keyframe's message, exactly (write_keyframe, write_resume_fields), so that it is built in
  // one segment and handed to the record writer without a copy.
  std::size_t keyframe_words(std::size_t n, const RebuildPoint<T>* rebuild) const {
    const std::size_t column = message_words_of(n * kScalarWidth<T>);
    std::size_t words = root_words<logschema::Keyframe>(run.rotation, kKeyframeWords, kKeyframePointers) +
                        message_words_of(kScalarWidth<T>) + (run.rotation ? 6 : 5) * column;
    if (rebuild) {
      words += message_words_of(4 * n);
      if (!rebuild->particles.last_collision.empty()) words += column;
      words += kCountedKindsV2 + 3 + (settings.format_version >= 3 ? 1 : 0) + (run.thermostat || run.shear ? 1 : 0) +
               (run.shear ? 1 : 0);
    }
    return words;
  }

  void write_resume_fields(logschema::Keyframe::Builder k, const RebuildPoint<T>& r) {
    const Particles<T>& p = r.particles;
    auto partners = k.initLastPartner(std::uint32_t(p.size()));
    for (std::size_t i = 0; i < p.size(); ++i) partners.set(std::uint32_t(i), p.disk[i].last_partner);
    if (!p.last_collision.empty())
      set_scalar_column<T>(k.initLastCollision(std::uint32_t(p.size() * kScalarWidth<T>)), p.size(),
                           [&](std::size_t i) { return p.last_collision[i]; });
    // The six kinds before segments, stale, tc_elastic; then segment events only in runs with segments
    // (FORMAT.md), so the keyframes of every other run keep their bytes; format version 3: segment and
    // step events, always, then the thermostat's redraws in a run with the thermostat or a Lees-Edwards box,
    // then the shear events in the latter.
    const bool v3 = settings.format_version >= 3;
    const bool segments = !run.segments.empty() || v3;
    const bool redraws = v3 && (run.thermostat || run.shear), shears = v3 && run.shear;
    auto counts = k.initEngineCounts(kCountedKindsV2 + 2 + (segments ? 1 : 0) + (v3 ? 1 : 0) + (redraws ? 1 : 0) +
                                     (shears ? 1 : 0));
    for (int c = 0; c < kCountedKindsV2; ++c) counts.set(std::uint32_t(c), r.counts.by_kind[c]);
    counts.set(kCountedKindsV2, r.counts.stale);
    counts.set(kCountedKindsV2 + 1, r.counts.tc_elastic);
    if (segments) counts.set(kCountedKindsV2 + 2, r.counts.of(EventKind::Segment));
    if (v3) counts.set(kCountedKindsV2 + 3, r.counts.of(EventKind::Step));
    if (redraws) counts.set(kCountedKindsV2 + 4, r.counts.of(EventKind::Thermostat));
    if (shears) counts.set(kCountedKindsV2 + 5, r.counts.of(EventKind::Shear));
    k.setNextSample(r.next_sample_index);
    k.setNextAction(r.next_action_index);
    k.setSameTimeEvents(r.same_time_events);
  }

  void write_index(T final_time, RunStatus status) {
    out.flush();
    std::vector<LogContinuation::Entry> entries = kept;
    for (const Pending& p : pending) {
      LogContinuation::Entry e = p.entry;
      e.offset = out.offset_of(p.sequence);
      entries.push_back(e);
    }
    FlatMessageBuilder message(64 + entries.size() * (capnp::_::structSize<logschema::Index::Entry>().data + capnp::_::structSize<logschema::Index::Entry>().pointers) +
                              message_words_of(std::string(to_string(status)).size() + 1));
    auto idx = message.initRoot<logschema::Index>();
    auto list = idx.initEntries(std::uint32_t(entries.size()));
    for (std::size_t k = 0; k < entries.size(); ++k) {
      auto e = list[std::uint32_t(k)];
      e.setKind(entries[k].kind);
      e.setOffset(entries[k].offset);
      e.setFirstEvent(entries[k].first_event);
      e.setCount(entries[k].count);
      e.setTimeFirst(entries[k].time_first);
      e.setTimeLast(entries[k].time_last);
      e.setResumable(entries[k].resumable);
    }
    idx.setTotalEvents(logged);
    set_data(idx.initFinalTime(kScalarWidth<T>), one_scalar(final_time));
    idx.setStatus(to_string(status));
    logfmt::RecordHeader rh;
    rh.kind = logfmt::RecordKind::Index;
    rh.first_event = logged;
    rh.time_first = rh.time_last = double(final_time);
    const std::size_t seq = out.submit(rh, message.finish());
    out.flush();
    logfmt::Trailer trailer{out.offset_of(seq), out.end_offset()};
    std::vector<unsigned char> bytes(logfmt::kTrailerSize);
    logfmt::encode_trailer(trailer, bytes.data());
    out.write_raw(std::move(bytes));
    bytes_ = out.end_offset();
  }
  std::uint64_t bytes_ = 0;
};

template <class T>
Result<std::unique_ptr<LogWriter<T>>> LogWriter<T>::create(const std::string& path, const LogRunInfo& run,
                                                           const LogSettings& settings,
                                                           const LogContinuation* continuation) {
  if (settings.chunk_events == 0) return Error{"log settings: chunk_events must be positive"};
  // Step, thermostat and shear events exist in format version 3 only: such a run is written in it whatever
  // its settings name, so every way to write a log gets it right.
  if ((run.steps || run.thermostat || run.shear) && settings.format_version < 3) {
    LogSettings v3 = settings;
    v3.format_version = 3;
    return create(path, run, v3, continuation);
  }
  if (settings.format_version < logfmt::kOldestFormatVersion || settings.format_version > logfmt::kNewestFormatVersion)
    return Error{"log settings: format version " + std::to_string(settings.format_version) + " is not one this ede writes"};
  const std::uint64_t start = continuation ? continuation->cut_offset : 0;
  auto impl = std::make_unique<Impl>(path, run, settings, start, settings.compression_level);
  if (std::string e = impl->out.error(); !e.empty()) return Error{e};
  if (continuation) {
    impl->logged = continuation->events_before;
    impl->kept = continuation->entries;
    impl->run_id = impl->coder.run_id = continuation->run_id;
  } else {
    std::vector<unsigned char> header(logfmt::kFileHeaderSize);
    logfmt::encode_file_header(header.data(), settings.format_version);
    impl->out.write_raw(std::move(header));
  }
  if (run.rotation && settings.format_version < 2)
    return Error{"log settings: a run of rough (rotating) disks is written in format version 2 only"};
  impl->chunk_first = impl->logged;
  impl->chunk_events = ChunkEvents<T>(run.rotation, settings.format_version < 2);
  impl->chunk_events.reserve(settings.chunk_events);
  return std::unique_ptr<LogWriter<T>>(new LogWriter<T>(std::move(impl)));
}

template <class T>
LogWriter<T>::LogWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

template <class T>
LogWriter<T>::~LogWriter() = default;

template <class T>
void LogWriter<T>::on_start(T, const Particles<T>& p) {
  impl_->ensure_coder(p);
  impl_->write_header(p);
}

template <class T>
void LogWriter<T>::on_event(const EventOutcome<T>& e, const Particles<T>& p) {
  if (e.kind == EventKind::Cell) return;
  Impl& w = *impl_;
  w.ensure_coder(p);
  w.event_coder.add(e, p, w.chunk_events);
  ++w.logged;
  if (w.chunk_events.size() >= w.settings.chunk_events) w.flush_chunk();
  if (w.logged == w.next_keyframe) {
    w.write_keyframe(p, e.time, nullptr);
    w.next_keyframe += w.settings.keyframe_interval;
  }
}

template <class T>
void LogWriter<T>::on_rebuild(const RebuildPoint<T>& point) {
  Impl& w = *impl_;
  w.ensure_coder(point.particles);
  w.write_keyframe(point.particles, point.time, &point);
}

template <class T>
void LogWriter<T>::on_finish(T time, const Particles<T>&, RunStatus status) {
  Impl& w = *impl_;
  if (w.finished) return;
  w.finished = true;
  w.flush_chunk();
  w.write_index(time, status);
  w.out.finish();
}

template <class T>
std::string LogWriter<T>::error() const {
  if (const std::string& m = impl_->event_coder.mismatch(); !m.empty()) return impl_->out.path() + ": " + m;
  return impl_->out.error();
}

template <class T>
std::uint64_t LogWriter<T>::events_logged() const {
  return impl_->logged;
}

template <class T>
std::uint64_t LogWriter<T>::bytes_written() const {
  return impl_->bytes_;
}

template class LogWriter<float>;
template class LogWriter<double>;
template class LogWriter<long double>;

}  // namespace ede
