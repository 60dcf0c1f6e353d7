// The study's engine variants (study/study_engine.hpp): the textbook contact root and the all-effects
// engine. Neither is for results (ede-bench uses them to show what the stable root and specialization
// buy), but both must be right: the same first collisions as the library's engine (to round-off) and
// energy kept; combinations the studies do not need are refused, not silently run as something else.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/engine_core.hpp"
#include "engine_test_support.hpp"
#include "study/study_engine.hpp"

using namespace ede;
using namespace ede::test;
using ede::study::ContactRoot;
using ede::study::EngineVariant;
using ede::study::make_study_engine;

namespace {

std::unique_ptr<EngineApi<double>> study_engine(const InitialState& s, const EngineOptions& o, EngineVariant v) {
  auto made = make_study_engine<double>(s, o, v);
  if (!made) throw std::runtime_error(made.error().message);
  return std::move(made).value();
}

}  // namespace

TEST_CASE("study variants: the textbook contact root and the all-effects engine run the same physics",
          "[run][study]") {
  const InitialState s = lattice_gas(12, 0.015, 1.0, 6);
  EngineOptions o = walls_until(1e9);
  o.stop.events = 50000;
  EngineVariant textbook, general;
  textbook.contact = ContactRoot::Textbook;
  general.all_effects = true;  // walls, dissipation with TC, gravity compiled in; xi = 1, tc = 0, g = 0
  auto a = engine(s, o);
  auto b = study_engine(s, o, textbook);
  auto c = study_engine(s, o, general);
  CHECK(b->effects().find("textbook contact root") != std::string::npos);
  CHECK(a->effects().find("textbook") == std::string::npos);
  CHECK(c->effects().find("gravity (0, 0)") != std::string::npos);
  CHECK(dynamic_cast<Engine<double, WallsBoundary, Dissipative, UniformGravity>*>(c.get()) != nullptr);
  Recorder<double> ra, rb, rc;
  a->add_sink(&ra);
  b->add_sink(&rb);
  c->add_sink(&rc);
  for (auto* e : {a.get(), b.get(), c.get()}) {
    REQUIRE(e->run() == RunStatus::ReachedEvents);
    CHECK(std::abs(kinetic_energy(e->particles()) - e->initial_kinetic_energy()) < 1e-12 * e->initial_kinetic_energy());
    CHECK(e->check_invariants(1e-9) == "");
  }
  const auto pa = ra.of_kind(EventKind::Pair);
  for (const auto* other : {&rb, &rc}) {
    const auto po = other->of_kind(EventKind::Pair);
    REQUIRE(po.size() > 100);
    for (std::size_t k = 0; k < 100; ++k) {
      CHECK(std::min(po[k].i, po[k].j) == std::min(pa[k].i, pa[k].j));
      CHECK(po[k].time == Approx(pa[k].time).margin(1e-9));
    }
  }
  // The default variant is the library's own choice.
  CHECK(study_engine(s, o, EngineVariant{})->effects() == a->effects());
}

TEST_CASE("study variants: what they are not built for is refused", "[run][study]") {
  const InitialState s = lattice_gas(12, 0.015, 1.0, 6);
  EngineOptions o = walls_until(1e9);
  EngineVariant textbook, general, both;
  textbook.contact = ContactRoot::Textbook;
  general.all_effects = true;
  both = general;
  both.contact = ContactRoot::Textbook;
  EngineOptions inelastic = o;
  inelastic.physics.restitution = 0.9;
  CHECK_FALSE(make_study_engine<double>(s, inelastic, textbook).ok());
  EngineOptions gravity = o;
  gravity.physics.gravity = {0, -1};
  CHECK_FALSE(make_study_engine<double>(s, gravity, textbook).ok());
  CHECK(make_study_engine<double>(s, gravity, general).ok());
  EngineOptions periodic = o;
  periodic.boundary = BoundaryKind::Periodic;
  CHECK(make_study_engine<double>(s, periodic, textbook).ok());
  CHECK_FALSE(make_study_engine<double>(s, periodic, general).ok());
  CHECK_FALSE(make_study_engine<double>(s, o, both).ok());
#if EDE_HAVE_FLOAT128
  CHECK_FALSE(make_study_engine<__float128>(s, o, textbook).ok());
  CHECK(make_study_engine<__float128>(s, o, EngineVariant{}).ok());
#endif
}
