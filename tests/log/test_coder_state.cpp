// CoderState (log/coder_state.hpp): the log writer's 40-byte state gives the predictors and apply_event
// what a Particles<T> gives them, keeps radius, mass and species once only when every disk has the same,
// and writes a changed record back.
#include <catch2/catch.hpp>

#include "log/chunk_codec.hpp"
#include "log/coder_state.hpp"

using namespace ede;

namespace {
Particles<double> three_disks(bool uniform) {
  Particles<double> p;
  p.disk.resize(3);
  for (std::size_t i = 0; i < 3; ++i) {
    Disk<double>& d = p.disk[i];
    d.x = 0.1 + 0.3 * double(i), d.y = 0.5, d.vx = i == 0 ? 1.0 : -1.0, d.vy = 0.25 * double(i), d.t = 0.01 * double(i);
    d.r = uniform ? 0.05 : 0.04 + 0.01 * double(i);
  }
  p.set_masses(uniform ? std::vector<double>{1, 1, 1} : std::vector<double>{1, 2, 3});
  p.set_species(uniform ? std::vector<std::int32_t>{0, 0, 0} : std::vector<std::int32_t>{0, 1, 0});
  return p;
}
}  // namespace

TEST_CASE("CoderState keeps uniform per-disk values once and reads like the Particles it came from", "[log][coder_state]") {
  for (const bool uniform : {true, false}) {
    CAPTURE(uniform);
    const Particles<double> p = three_disks(uniform);
    CoderState<double> s;
    s.assign(p);
    CHECK(s.size() == 3);
    CHECK(s.radius.size() == (uniform ? 1u : 3u));
    CHECK(s.mass.size() == (uniform ? 1u : 3u));
    CHECK(s.species.size() == (uniform ? 1u : 3u));
    EventPhysics<double> ph = EventPhysics<double>::box(1, 1, true, 0, 0);
    ph.species = 2;
    ph.one_plus_xi = {2, 1.9, 1.9, 1.8};
    const auto same_motion = [](const Disk<double>& a, const Disk<double>& b) {
      return a.x == b.x && a.y == b.y && a.vx == b.vx && a.vy == b.vy && a.t == b.t;
    };
    for (std::size_t i = 0; i < 3; ++i) {
      const Disk<double> d = record_of(s, i);
      CHECK(same_motion(d, p.disk[i]));
      CHECK(d.r == p.disk[i].r);
      CHECK(mass_of(s, i) == p.mass(i));
      CHECK(species_of(s, i) == p.species_of(i));
    }
    // The predictors give the same bits on both states.
    CHECK(predict_pair_time(ph, s, 0, 1) == predict_pair_time(ph, p, 0, 1));
    double vs[4], vp[4];
    predict_pair_velocities(ph, s, 0, 1, 0.2, false, vs);
    predict_pair_velocities(ph, p, 0, 1, 0.2, false, vp);
    for (int k = 0; k < 4; ++k) CHECK(vs[k] == vp[k]);
    // apply_event changes the coder's state as it changes replay's.
    DecodedEvent<double> e;
    e.kind = EventKind::Pair, e.i = 0, e.j = 1, e.time = 0.2;
    e.vix = vp[0], e.viy = vp[1], e.vjx = vp[2], e.vjy = vp[3];
    Particles<double> q = p;
    REQUIRE(apply_event(e, q, 1.0, 1.0));
    REQUIRE(apply_event(e, s, 1.0, 1.0));
    for (std::size_t i = 0; i < 3; ++i) CHECK(same_motion(record_of(s, i), q.disk[i]));
    CHECK(record_of(s, 0).t == 0.2);
  }
}
