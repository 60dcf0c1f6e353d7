// Fuzz target: the engine on random small scenes, with every invariant checked.
//
// The bytes choose 2-50 disks (radii, masses up to a ratio of 10^4, velocities), or 128-264 small disks with
// up to three big ones (kept out of the cell lists, big_disks.hpp), the boundary (walls or
// periodic), restitution for pairs and walls, the TC model, in a walled box up to four wall segments
// anywhere (the disks they cross removed), or (walls without segments, or periodic) rough spinning disks with
// random beta for pairs and walls, then run at most 3000 events while writing a log. Checked after every slice of events and at the end:
//   - no pair overlaps by more than 1e-6 of its contact distance, and no prediction lies in the past;
//   - kinetic energy (rotation included) is constant (1e-10 relative) when every collision is elastic
//     (rough disks: beta = +-1), never increases otherwise;
//   - momentum is constant in periodic boxes (no walls), for any restitution;
//   - the log replays to the engine's exact state (every record, bit for bit).
// A violation traps, which libFuzzer reports with the input that caused it.
// The harness returns false on a violated check; the fuzz target traps on it, the test suite fails.
#pragma once

#include "memfile.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/segment.hpp"
#include "engine/engine.hpp"
#include "log/log_reader.hpp"
#include "log/log_writer.hpp"
#include "replay/replay.hpp"

namespace ede::fuzz {

// Reads the fuzzer's bytes as a stream of parameters; past the end it yields zeros.
class Bytes {
 public:
  Bytes(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  std::uint8_t byte() { return k_ < n_ ? d_[k_++] : 0; }
  double unit() { return double(byte()) / 255.0; }  // [0, 1]

 private:
  const std::uint8_t* d_;
  std::size_t n_, k_ = 0;
};

struct Totals {
  double energy = 0, px = 0, py = 0, scale = 0;  // scale: sum of m |v|, for momentum tolerances
};

inline Totals totals(const ede::Particles<double>& p) {
  Totals t;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double m = p.mass(i), vx = p.disk[i].vx, vy = p.disk[i].vy;
    t.energy += 0.5 * m * (vx * vx + vy * vy);
    t.px += m * vx;
    t.py += m * vy;
    t.scale += m * std::hypot(vx, vy);
  }
  for (std::size_t i = 0; i < p.omega.size(); ++i) t.energy += 0.5 * p.inertia[i] * p.omega[i] * p.omega[i];
  return t;
}

// Up to three big disks over a state, removing the disks they would overlap (and skipping a big disk
// that would overlap an earlier big one).
inline void add_big_disks(Bytes& in, ede::InitialState& s) {
  const int count = 1 + in.byte() % 3;
  for (int b = 0; b < count; ++b) {
    const double r = 0.05 + 0.1 * in.unit();
    const double x = r + (1 - 2 * r) * in.unit() * 0.999 + 1e-4;
    const double y = r + (1 - 2 * r) * in.unit() * 0.999 + 1e-4;
    const double m = 1 + 100 * in.unit();
    const double vx = 4 * in.unit() - 2;
    const double vy = 4 * in.unit() - 2;
    ede::InitialState kept;
    kept.species_names = s.species_names;
    bool clear = true;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const bool covered = std::hypot(s.x[i] - x, s.y[i] - y) <= r + s.radius[i] + 1e-9;
      if (covered && s.radius[i] > 0.02) clear = false;  // an earlier big disk: keep it, skip this one
      if (!covered || s.radius[i] > 0.02) kept.add(s.x[i], s.y[i], s.vx[i], s.vy[i], s.radius[i], s.mass[i], 0);
    }
    if (!clear) continue;
    kept.add(x, y, vx, vy, r, m, 0);
    s = kept;
  }
}

// Disks on a jittered grid: one per cell, never overlapping, inside the box. With `big`, 128-264 small
// disks and up to three big ones (radius 0.05-0.15) placed over them, the small disks they cover removed:
// the engine then keeps the big ones out of its cell lists (big_disks.hpp).
inline ede::InitialState make_state(Bytes& in, bool big) {
  ede::InitialState s;
  s.species_names = {"a"};
  const int n = big ? 128 + in.byte() % 137 : 2 + in.byte() % 49;
  const int side = int(std::ceil(std::sqrt(double(n))));
  const double cell = 1.0 / side;
  const bool heavy = in.byte() % 8 == 0;
  const double r_max = big ? 0.01 : 0.05;
  for (int k = 0; k < n; ++k) {
    const double r = std::min(0.45 * cell, 0.003 + r_max * in.unit());
    const double room = cell / 2 - r;
    const double x = (k % side + 0.5) * cell + (2 * in.unit() - 1) * room * 0.99;
    const double y = (k / side + 0.5) * cell + (2 * in.unit() - 1) * room * 0.99;
    const double m = heavy && k == 0 ? 1e4 : 0.1 + 10 * in.unit();
    // Sequenced: the order of evaluation of function arguments is unspecified (GCC and Clang differ),
    // and an input must mean the same scene to every compiler.
    const double vx = 2 * in.unit() - 1;
    const double vy = 2 * in.unit() - 1;
    s.add(x, y, vx, vy, r, m, 0);
  }
  if (big) add_big_disks(in, s);
  return s;
}

// One to four wall segments at random in the box (flag 32, walls only), restitution 1 or, with
// restitution on (flag 2), random; the disks they cross are removed.
inline void add_segments(Bytes& in, bool inelastic, ede::InitialState& s, ede::PhysicsSpec& ph) {
  const int count = 1 + in.byte() % 4;
  for (int k = 0; k < count; ++k) {
    const double ax = 0.02 + 0.96 * in.unit(), ay = 0.02 + 0.96 * in.unit();
    const double bx = 0.02 + 0.96 * in.unit(), by = 0.02 + 0.96 * in.unit();
    const double xi = inelastic ? in.unit() : 1.0;
    if (ax == bx && ay == by) continue;
    ph.segments.push_back({{ax, ay}, {bx, by}, xi});
  }
  ede::InitialState kept;
  kept.species_names = s.species_names;
  kept.lx = s.lx, kept.ly = s.ly;
  for (std::size_t i = 0; i < s.size(); ++i) {
    bool clear = true;
    for (const ede::SegmentSpec& g : ph.segments) {
      const auto seg = ede::make_segment(g.from[0], g.from[1], g.to[0], g.to[1], g.restitution);
      clear = clear && ede::segment_distance(seg, s.x[i], s.y[i]) > s.radius[i] * (1 + 1e-9);
    }
    if (clear) kept.add(s.x[i], s.y[i], s.vx[i], s.vy[i], s.radius[i], s.mass[i], s.species[i]);
  }
  s = kept;
}

inline bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }


#define CHECK_OR_FAIL(cond) \
  do {                        \
    if (!(cond)) return false; \
  } while (0)

inline bool fuzz_engine(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const std::uint8_t flags = in.byte();
  ede::EngineOptions o;
  o.boundary = (flags & 1) ? ede::BoundaryKind::Periodic : ede::BoundaryKind::Walls;
  if (flags & 2) {
    o.physics.restitution = in.unit();
    o.physics.wall_restitution = (flags & 8) ? in.unit() : 1.0;
    if (flags & 4) o.physics.tc = 1e-4 * (1 + in.unit());
  }
  o.stop.events = 3000;
  o.rebuild_interval = 500 + 10 * in.byte();
  o.stall_limit = 20000;
  ede::InitialState s = make_state(in, (flags & 16) != 0);
  if ((flags & 32) && o.boundary == ede::BoundaryKind::Walls) add_segments(in, (flags & 2) != 0, s, o.physics);
  // Rough disks (not with segments): beta for pairs and walls, -1, +1 or anywhere between; spins up to
  // ~|v| / r; I = f m r^2 with f in [0.1, 1].
  const bool rough = (flags & 64) && o.physics.segments.empty();
  if (rough) {
    const auto beta = [&] {
      const std::uint8_t b = in.byte();
      return b < 64 ? -1.0 : b < 128 ? 1.0 : 2 * in.unit() - 1;
    };
    o.physics.roughness = beta();
    o.physics.wall_roughness = beta();
    o.rotation = true;
    for (std::size_t i = 0; i < s.size(); ++i) {
      s.inertia.push_back((0.1 + 0.9 * in.unit()) * s.mass[i] * s.radius[i] * s.radius[i]);
      s.omega.push_back((2 * in.unit() - 1) / s.radius[i]);
    }
  }
  if (s.size() == 0) return true;
  auto made = ede::make_engine<double>(s, o);
  CHECK_OR_FAIL(made.ok());  // the grid placement is valid by construction
  ede::EngineApi<double>& engine = *made.value();

  const MemFile file("fuzz-engine-log");
  if (!file.ok()) return true;
  const std::string path = file.path();
  ede::LogRunInfo info;
  info.species_names = s.species_names;
  info.boundary = o.boundary;
  info.rebuild_interval = o.rebuild_interval;
  info.lx = s.lx, info.ly = s.ly;
  // The header describes the run as the engine runs it (run/log_run_info.cpp): the restitution, roughness
  // and segments replay predicts from, and the TC model.
  info.set_restitution(o.physics);
  info.tc_model = ede::uses_tc_model(o.physics);
  info.rotation = rough;
  info.engine_constants = true;
  ede::LogSettings settings;
  settings.chunk_events = 64;
  settings.keyframe_interval = 256;
  settings.check_exactness = true;  // every prediction the engine vouches for, recomputed
  auto writer = ede::LogWriter<double>::create(path, info, settings);
  CHECK_OR_FAIL(writer.ok());
  engine.add_sink(writer.value().get());

  const Totals start = totals(engine.particles());
  const auto keeps = [](double beta) { return beta == -1 || beta == 1; };
  const bool elastic = o.physics.elastic() && (!rough || (keeps(o.physics.roughness) && keeps(o.physics.wall_roughness)));
  ede::RunStatus status;
  while ((status = engine.run(250)) == ede::RunStatus::Running) {
    CHECK_OR_FAIL(engine.check_invariants(1e-6).empty());
    const Totals now = totals(engine.particles());
    if (elastic) CHECK_OR_FAIL(std::abs(now.energy - start.energy) <= 1e-10 * start.energy + 1e-300);
    CHECK_OR_FAIL(now.energy <= start.energy * (1 + 1e-12) + 1e-300);
    if (o.boundary == ede::BoundaryKind::Periodic) {
      CHECK_OR_FAIL(std::abs(now.px - start.px) <= 1e-10 * start.scale + 1e-300);
      CHECK_OR_FAIL(std::abs(now.py - start.py) <= 1e-10 * start.scale + 1e-300);
    }
  }
  CHECK_OR_FAIL(engine.check_invariants(1e-6).empty());
  CHECK_OR_FAIL(writer.value()->error().empty());

  auto log = ede::LogReader::open(path);
  CHECK_OR_FAIL(log.ok() && log.value()->complete());
  auto replay = ede::Replay<double>::create(log.value());
  CHECK_OR_FAIL(replay.ok());
  CHECK_OR_FAIL(replay.value()->seek_time(engine.time()).ok());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const ede::Disk<double>& a = replay.value()->particles().disk[i];
    const ede::Disk<double>& b = engine.particles().disk[i];
    CHECK_OR_FAIL(same(a.x, b.x) && same(a.y, b.y) && same(a.vx, b.vx) && same(a.vy, b.vy) && same(a.t, b.t));
    if (rough) CHECK_OR_FAIL(same(replay.value()->particles().omega[i], engine.particles().omega[i]));
  }
  (void)status;
  return true;
}

}  // namespace ede::fuzz

#undef CHECK_OR_FAIL
