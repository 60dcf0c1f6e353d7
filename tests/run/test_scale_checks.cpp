// Extreme scales in every scalar type (run/scale_checks.hpp, run/end_check.hpp; docs/reliability.md):
// a run is exact to its type's contract, or refused before it starts with the quantity, the disks and the
// fix, or stopped with an error. Never a normal end with overlapping disks.
//
// Each run below is a small gas (40 disks) at one corner of the space of scales: box and radii from 1e-300
// to 1e300, speeds, masses, gravity and stop times likewise, in float, double, long double and (where
// built) __float128. A run that ends normally is checked here independently of the library's own end
// check: every pair, in long double from the final state, against the contract's bound 16 eps (L + 2 V t)
// (docs/reliability.md), and "no more events" only with every disk at rest. The test also counts the
// runs that end normally per type, so that it cannot pass by refusing everything.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "ede/ede.hpp"

namespace {

struct Corner {
  double box = 1, speed = 1, mass = 1, gravity = 0, stop_time = 0;  // stop_time 0: three box crossings
};

std::string text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::string scene_text(const Corner& c, const char* scalar) {
  const double stop = c.stop_time > 0 ? c.stop_time : 3 * c.box / c.speed;
  std::string t = "seed = 3\n[box]\nsize = [" + text(c.box) + ", " + text(c.box) + "]\n[engine]\nscalar = \"" +
                  scalar + "\"\n";
  if (c.gravity != 0) t += "[physics]\ngravity = [0.0, " + text(-c.gravity) + "]\n";
  t += "[[species]]\nname = \"gas\"\ncount = 40\nradius = " + text(0.02 * c.box) + "\nmass = " + text(c.mass) +
       "\n[species.velocity]\nkind = \"speed\"\nspeed = " + text(c.speed) + "\n[stop]\nevents = 20000\n";
  if (std::isfinite(stop) && stop > 0) t += "time = " + text(stop) + "\n";
  return t;
}

long double epsilon_of(ede::ScalarKind k) {
  switch (k) {
    case ede::ScalarKind::Float: return std::numeric_limits<float>::epsilon();
    case ede::ScalarKind::Float128: break;  // its state comes rounded to long double
    case ede::ScalarKind::LongDouble: return std::numeric_limits<long double>::epsilon();
    case ede::ScalarKind::Double: return std::numeric_limits<double>::epsilon();
  }
  return std::numeric_limits<long double>::epsilon();
}

// The deepest overlap of a state beyond the contract's bound, all pairs in long double; 0 if none.
long double overlap_beyond_contract(const ede::State& s, ede::ScalarKind kind) {
  long double fastest = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    fastest = std::max(fastest, std::hypot(s.vx.exact(i), s.vy.exact(i)));
  const long double bound =
      16 * epsilon_of(kind) * ((long double)std::max(s.lx, s.ly) + 2 * fastest * (long double)s.time);
  long double worst = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const long double dx = s.x.exact(j) - s.x.exact(i);
      const long double dy = s.y.exact(j) - s.y.exact(i);
      const long double depth =
          s.radius.exact(i) + s.radius.exact(j) - std::hypot(dx, dy);
      if (depth > bound) worst = std::max(worst, depth / (s.radius.exact(i) + s.radius.exact(j)));
    }
  return worst;
}

bool normal_end(ede::RunStatus s) {
  return s == ede::RunStatus::ReachedTime || s == ede::RunStatus::ReachedEvents || s == ede::RunStatus::NoMoreEvents;
}

bool any_moving(const ede::State& s) {
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.vx.exact(i) != 0 || s.vy.exact(i) != 0) return true;
  return false;
}

struct Tally {
  int refused = 0, ended = 0, stopped = 0;
};

// Runs one corner; fails the test on a normal end that breaks the contract, or a refusal without its parts.
void run_corner(const Corner& c, ede::ScalarKind kind, const char* scalar, Tally& tally) {
  const std::string scene_text_ = scene_text(c, scalar);
  INFO(scene_text_);
  auto scene = ede::parse_scene_text(scene_text_, "edge.toml");
  if (!scene) {  // a value the scene format itself refuses (a stop time that rounds to 0, say)
    ++tally.refused;
    CHECK(scene.error().message.find("Fix:") != std::string::npos);
    return;
  }
  auto sim = ede::Simulation::create(scene.value());
  if (!sim) {
    ++tally.refused;
    const std::string& m = sim.error().message;
    INFO(m);
    CHECK(m.find("Fix:") != std::string::npos);
    const bool names_where = m.find("disk") != std::string::npos || m.find("box") != std::string::npos ||
                             m.find("gravity") != std::string::npos || m.find("stop.time") != std::string::npos ||
                             m.find("mass") != std::string::npos;
    CHECK(names_where);
    return;
  }
  const ede::RunStatus status = sim.value().run();
  INFO("status " << ede::to_string(status) << ": " << sim.value().message());
  if (!normal_end(status)) {
    ++tally.stopped;  // an error exit (ede-sim: 3 or 4) with its message
    CHECK(!sim.value().message().empty());
    return;
  }
  ++tally.ended;
  const ede::State s = sim.value().state();
  CHECK(overlap_beyond_contract(s, kind) == 0);
  if (status == ede::RunStatus::NoMoreEvents) CHECK((!any_moving(s) && c.gravity == 0));
}

struct Type {
  ede::ScalarKind kind;
  const char* name;
};

std::vector<Type> types() {
  std::vector<Type> t = {{ede::ScalarKind::Float, "float"},
                         {ede::ScalarKind::Double, "double"},
                         {ede::ScalarKind::LongDouble, "long double"}};
#if EDE_HAVE_FLOAT128
  t.push_back({ede::ScalarKind::Float128, "float128"});
#endif
  return t;
}

const std::vector<double> kDecades = {1e-300, 1e-150, 1e-40, 1e-20, 1e-5, 1, 1e5, 1e20, 1e40, 1e150, 1e300};

}  // namespace

TEST_CASE("every scalar type at the edges of its range: lengths and speeds", "[run][scale_checks]") {
  for (const Type& type : types()) {
    Tally tally;
    for (double box : kDecades)
      for (double speed : kDecades) run_corner({box, speed}, type.kind, type.name, tally);
    INFO(type.name << ": " << tally.refused << " refused, " << tally.ended << " ended, " << tally.stopped << " stopped");
    CHECK(tally.ended >= 9);    // not a test that refuses everything: the middle of each range runs
    CHECK(tally.refused >= 20);  // and the edges of every range are refused, not run
  }
}

TEST_CASE("every scalar type at the edges of its range: masses, gravity and times", "[run][scale_checks]") {
  for (const Type& type : types()) {
    Tally tally;
    for (double mass : kDecades) run_corner({1, 1, mass}, type.kind, type.name, tally);
    for (double g : kDecades) run_corner({1, 1, 1, g}, type.kind, type.name, tally);
    for (double time : kDecades) run_corner({1, 1, 1, 0, time}, type.kind, type.name, tally);
    // Mixed corners: a tiny box with fast disks and strong gravity, a huge one with slow heavy disks.
    run_corner({1e-20, 1e10, 1e-30, 1e25}, type.kind, type.name, tally);
    run_corner({1e20, 1e-10, 1e30, 1e-25}, type.kind, type.name, tally);
    INFO(type.name << ": " << tally.refused << " refused, " << tally.ended << " ended, " << tally.stopped << " stopped");
    CHECK(tally.ended >= 6);
  }
}

TEST_CASE("the issue's float runs are refused with the quantity, the disks and the fix", "[run][scale_checks]") {
  // Speeds ~1e-37: v^2 underflows float (the run ended with exit 0 and 24 overlapping pairs).
  Corner slow{1, 1e-37};
  auto a = ede::Simulation::create(ede::parse_scene_text(scene_text(slow, "float"), "slow.toml").value());
  REQUIRE_FALSE(a);
  CHECK(a.error().message.find("slow.toml: with engine.scalar = \"float\", the smallest diameter (disk ") == 0);
  CHECK(a.error().message.find("underflows the type") != std::string::npos);
  CHECK(a.error().message.find("or use engine.scalar = \"double\"") != std::string::npos);
  // A box of 1e30 at speeds 1e-10: times pass float's largest value (it ended "no more events", exit 0).
  Corner huge{1e30, 1e-10};
  huge.stop_time = 1e30;
  auto b = ede::Simulation::create(ede::parse_scene_text(scene_text(huge, "float"), "huge.toml").value());
  REQUIRE_FALSE(b);
  CHECK(b.error().message.find("overflows the type (largest 3.4e+38)") != std::string::npos);
  CHECK(b.error().message.find("Fix: rescale the units") != std::string::npos);
  // The same runs in double are exact: they end normally without overlaps (run_corner checks).
  Tally tally;
  run_corner(slow, ede::ScalarKind::Double, "double", tally);
  run_corner(huge, ede::ScalarKind::Double, "double", tally);
  CHECK(tally.ended == 2);
}

TEST_CASE("a float run whose clock outgrows the type stops with an error, not a normal end", "[run][scale_checks]") {
  // Box 1e18 at speeds 1e-18: every number fits float, but after ~300 box crossings the clock passes
  // 3.4e38 and every event time is infinite. Without a stop time the run goes that far.
  Corner c{1e18, 1e-18};
  std::string t = scene_text(c, "float");
  t = t.substr(0, t.find("events = 20000")) + "events = 10000000\n";
  auto sim = ede::Simulation::create(ede::parse_scene_text(t, "clock.toml").value()).value();
  CHECK(sim.run() == ede::RunStatus::Inexact);
  CHECK(sim.message().find("no event left") != std::string::npos);
  CHECK(sim.summary().status == ede::to_string(ede::RunStatus::Inexact));
}
