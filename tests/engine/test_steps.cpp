// Stepped potentials (engine/room_step.hpp, engine/step_table.hpp): a square well crossed head-on with the
// energies known in closed form, a shoulder too high to cross (a bounce), a grazing pass through a well,
// the total energy kept to round-off over 10^6 events, and the low-density pressure against the 2D second
// virial coefficient of square wells and shoulders (docs/physics.md, "Stepped potentials").
#include <catch2/catch.hpp>
#include <cmath>

#include "core/energy.hpp"
#include "engine_test_support.hpp"

using namespace ede;
using namespace ede::test;

namespace {

constexpr double kR = 1.0 / 16;  // sigma = 1/8

EngineOptions with_steps(EngineOptions o, std::vector<double> radius, std::vector<double> energy) {
  o.physics.steps.push_back({"", "", std::move(radius), std::move(energy)});
  return o;
}

// Two unit masses approaching head-on along x at unit speeds: relative speed 2, reduced mass 1/2, so the
// kinetic energy of the motion along the line of centres is 1.
InitialState head_on() {
  InitialState s = box();
  s.add(0.2, 0.5, 1, 0, kR, 1, 0);
  s.add(0.8, 0.5, -1, 0, kR, 1, 0);
  return s;
}

double kinetic(const EngineApi<double>& e) { return kinetic_energy(e.particles(), e.time()); }

}  // namespace

TEST_CASE("steps: a head-on pass through a square well trades kinetic for potential energy and back",
          "[steps]") {
  // Well of depth 3/4 at distance 1/4: inside, vn^2 = 4 + 2 (3/4) / (1/2) = 7; after the core collision the
  // pair leaves the well with vn^2 = 7 - 3 = 4 again.
  RecordedRun r = run_recorded(head_on(), with_steps(walls_until(0.5), {0.25}, {-0.75}));
  const auto& ev = r.events();
  REQUIRE(ev.size() == 3);
  CHECK(ev[0].kind == EventKind::Step);
  CHECK(ev[1].kind == EventKind::Pair);
  CHECK(ev[2].kind == EventKind::Step);
  const double s7 = std::sqrt(7.0);
  CHECK(double(ev[0].time) == Approx(0.175).epsilon(1e-14));
  CHECK(double(ev[0].vix) == Approx(s7 / 2).epsilon(1e-14));
  CHECK(double(ev[0].vjx) == Approx(-s7 / 2).epsilon(1e-14));
  CHECK(double(ev[1].time) == Approx(0.175 + 0.125 / s7).epsilon(1e-14));
  CHECK(double(ev[2].time) == Approx(0.175 + 0.25 / s7).epsilon(1e-14));
  CHECK(double(ev[2].vix) == Approx(-1).epsilon(1e-14));
  CHECK(double(ev[2].vjx) == Approx(1).epsilon(1e-14));
  CHECK(r.engine->potential_energy() == 0);
  CHECK(kinetic(*r.engine) == Approx(1).epsilon(1e-14));
}

TEST_CASE("steps: inside a well the potential energy is the well's, and the kinetic energy has grown by it",
          "[steps]") {
  auto e = engine(head_on(), with_steps(walls_until(0.2), {0.25}, {-0.75}));
  CHECK(e->run() == RunStatus::ReachedTime);
  CHECK(e->potential_energy() == -0.75);
  CHECK(kinetic(*e) == Approx(1.75).epsilon(1e-14));
}

TEST_CASE("steps: a shoulder higher than the energy along the line of centres is a hard wall", "[steps]") {
  RecordedRun r = run_recorded(head_on(), with_steps(walls_until(0.3), {0.25}, {1.5}));
  REQUIRE(r.events().size() == 1);
  const auto& e = r.events()[0];
  CHECK(e.kind == EventKind::Step);
  CHECK(double(e.time) == Approx(0.175).epsilon(1e-14));
  CHECK(double(e.vix) == Approx(-1).epsilon(1e-14));
  CHECK(double(e.vjx) == Approx(1).epsilon(1e-14));
  CHECK(r.engine->potential_energy() == 0);
  CHECK(kinetic(*r.engine) == Approx(1).epsilon(1e-14));
}

TEST_CASE("steps: a shoulder lower than that energy is crossed, and the core reached", "[steps]") {
  // Shoulder 1/2 at 1/4: inside vn^2 = 4 - 2 (1/2) / (1/2) = 2.
  RecordedRun r = run_recorded(head_on(), with_steps(walls_until(0.5), {0.25}, {0.5}));
  REQUIRE(r.events().size() == 3);
  CHECK(r.events()[1].kind == EventKind::Pair);
  CHECK(double(r.events()[0].vix) == Approx(std::sqrt(2.0) / 2).epsilon(1e-14));
  CHECK(r.engine->potential_energy() == 0);
}

TEST_CASE("steps: a grazing pass enters and leaves a well and keeps the energy", "[steps]") {
  // Impact parameter just inside the well's radius: far from the core, the pair enters and leaves.
  for (double offset : {0.25 * (1 - 1e-9), 0.25 * (1 - 1e-13)}) {
    InitialState s = box();
    s.add(0.2, 0.5, 1, 0, kR, 1, 0);
    s.add(0.8, 0.5 + offset, -1, 0, kR, 1, 0);
    RecordedRun r = run_recorded(s, with_steps(walls_until(0.45), {0.25}, {-0.75}));
    REQUIRE(r.events().size() == 2);
    CHECK(r.events()[0].kind == EventKind::Step);
    CHECK(r.events()[1].kind == EventKind::Step);
    CHECK(r.engine->potential_energy() == 0);
    CHECK(kinetic(*r.engine) == Approx(1).epsilon(1e-12));
  }
  // Just outside: no event at all.
  InitialState s = box();
  s.add(0.2, 0.5, 1, 0, kR, 1, 0);
  s.add(0.8, 0.5 + 0.25 * (1 + 1e-9), -1, 0, kR, 1, 0);
  CHECK(run_recorded(s, with_steps(walls_until(0.45), {0.25}, {-0.75})).events().empty());
}

TEST_CASE("steps: the engine refuses steps inside the hard core", "[steps]") {
  auto made = make_engine<double>(head_on(), with_steps(walls_until(1), {0.1}, {-1}));
  REQUIRE(!made);
  CHECK(made.error().message.find("inside the hard core") != std::string::npos);
}

namespace {

// The virial of a run's impulses (pair and step events, minimum image), the time integral of the potential
// energy, and the kinetic energy's, for the pressure and temperature of a stepped gas.
class VirialSink final : public Sink<double> {
 public:
  VirialSink(double lx, double u0, double ke0) : lx_(lx), u_(u0), ke_(ke0) {}
  void on_event(const EventOutcome<double>& e, const Particles<double>& p) override {
    if (e.kind != EventKind::Pair && e.kind != EventKind::Step) return;
    const double dt = double(e.time) - t_;
    u_integral_ += u_ * dt, ke_integral_ += ke_ * dt, t_ = double(e.time);
    const std::size_t i = std::size_t(e.i), j = std::size_t(e.j);
    double dx = p.disk[i].x - p.disk[j].x, dy = p.disk[i].y - p.disk[j].y;
    dx -= lx_ * std::nearbyint(dx / lx_);
    dy -= lx_ * std::nearbyint(dy / lx_);
    virial_ += dx * p.mass(i) * (e.vix - e.vix0) + dy * p.mass(i) * (e.viy - e.viy0);
    const double dke = 0.5 * p.mass(i) * (e.vix * e.vix + e.viy * e.viy - e.vix0 * e.vix0 - e.viy0 * e.viy0) +
                       0.5 * p.mass(j) * (e.vjx * e.vjx + e.vjy * e.vjy - e.vjx0 * e.vjx0 - e.vjy0 * e.vjy0);
    ke_ += dke, u_ -= dke;
  }
  void restart(double t) { t_ = t0_ = t, virial_ = u_integral_ = ke_integral_ = 0; }
  // Z = PA / (N kT) over the time since restart, kT the time average of the kinetic energy per disk (2D).
  double z(double n, double t) const {
    const double kt = ke_integral_ / (t_ - t0_) / n;
    return 1 + virial_ / (2 * (t - t0_) * n * kt);
  }
  double kt(double n) const { return ke_integral_ / (t_ - t0_) / n; }

 private:
  double lx_, u_, ke_;
  double t_ = 0, t0_ = 0, virial_ = 0, u_integral_ = 0, ke_integral_ = 0;
};

// A dilute gas of 400 disks (sigma = 0.02) in a periodic box of side 3, density rho = 400 / 9, with steps
// of radius 1.5 sigma. Returns (Z - 1) / rho per block of events, after 2 10^5 events of equilibration.
std::vector<double> b2_blocks(double energy, double* kt_out) {
  InitialState s = lattice_gas(20, 0.01, 3.0, 11, std::sqrt(2.0));  // kT near 1
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o = with_steps(o, {0.03}, {energy});
  auto e = engine(s, o);
  e->run(0);
  VirialSink sink(3.0, e->potential_energy(), kinetic(*e));
  e->add_sink(&sink);
  e->run(200000);
  std::vector<double> blocks;
  double kt = 0;
  for (int b = 0; b < 8; ++b) {
    sink.restart(double(e->time()));
    e->run(250000);
    blocks.push_back((sink.z(400, double(e->time())) - 1) / (400.0 / 9));
    kt += sink.kt(400) / 8;
  }
  *kt_out = kt;
  return blocks;
}

// B2 = (pi sigma^2 / 2) [1 - (lambda^2 - 1)(exp(-e / kT) - 1)] for a step of energy e at lambda sigma.
double b2(double sigma, double lambda, double energy, double kt) {
  return M_PI * sigma * sigma / 2 * (1 - (lambda * lambda - 1) * (std::exp(-energy / kt) - 1));
}

}  // namespace

TEST_CASE("steps: the total energy is kept to round-off over 10^6 events of a square-well gas", "[steps]") {
  InitialState s = lattice_gas(20, 0.01, 1.0, 5);
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o = with_steps(o, {0.025, 0.03}, {0.5, -1.0});  // a shoulder inside a well
  auto e = engine(s, o);
  e->run(0);
  const double total0 = kinetic(*e) + e->potential_energy();
  CHECK(e->run(1000000) == RunStatus::Running);
  CHECK(e->counts().of(EventKind::Step) > 100000);
  CHECK(e->potential_energy() != 0);
  CHECK(kinetic(*e) + e->potential_energy() == Approx(total0).epsilon(1e-11));
  CHECK(e->largest_overlap() < 1e-12);
}

TEST_CASE("steps: the low-density pressure of square wells and shoulders follows B2(T)", "[steps][physics]") {
  // Z - 1 = B2 rho + B3 rho^2 + ...: with rho sigma^2 = 0.018 the third term is a few per cent of the
  // second. Tolerance: 4 standard errors of the 8 blocks' mean, plus 0.15 |B2| for the higher terms.
  for (double energy : {-1.0, 1.0}) {
    double kt = 0;
    const std::vector<double> blocks = b2_blocks(energy, &kt);
    double mean = 0, var = 0;
    for (double v : blocks) mean += v / double(blocks.size());
    for (double v : blocks) var += (v - mean) * (v - mean) / double(blocks.size() - 1);
    const double stderr_mean = std::sqrt(var / double(blocks.size()));
    const double ref = b2(0.02, 1.5, energy, kt);
    INFO("energy " << energy << ": kT " << kt << ", (Z - 1)/rho " << mean << " +- " << stderr_mean << ", B2 " << ref);
    CHECK(std::abs(mean - ref) < 4 * stderr_mean + 0.15 * std::abs(ref));
  }
}

TEST_CASE("steps: the speeds of a square-well gas in equilibrium follow Maxwell-Boltzmann", "[steps][physics]") {
  // 2D MB at kT (m = 1): <v^4> / <v^2>^2 = 2 and half the speeds below sqrt(2 kT ln 2), kT = <v^2> / 2.
  // 40 snapshots of 400 disks, 5000 events apart (~12 collisions per disk): tolerances of about 4
  // standard errors of 16000 independent speeds (0.05 on the ratio, 0.016 on the fraction), wide enough
  // for the snapshots' mild correlation.
  InitialState s = lattice_gas(20, 0.01, 1.0, 17);
  EngineOptions o;
  o.boundary = BoundaryKind::Periodic;
  o = with_steps(o, {0.03}, {-1.0});
  auto e = engine(s, o);
  e->run(300000);
  std::vector<double> v2;
  for (int snap = 0; snap < 40; ++snap) {
    e->run(5000);
    for (const Disk<double>& d : e->particles().disk) v2.push_back(d.vx * d.vx + d.vy * d.vy);
  }
  double m2 = 0, m4 = 0;
  for (double x : v2) m2 += x / double(v2.size()), m4 += x * x / double(v2.size());
  const double kt = m2 / 2;
  std::size_t below = 0;
  for (double x : v2) below += x < 2 * kt * std::log(2.0) ? 1 : 0;
  INFO("kT " << kt << ", <v^4>/<v^2>^2 " << m4 / (m2 * m2) << ", fraction below the median " << double(below) / double(v2.size()));
  CHECK(m4 / (m2 * m2) == Approx(2).margin(0.05));
  CHECK(double(below) / double(v2.size()) == Approx(0.5).margin(0.016));
  CHECK(kt > 0.5);  // the well's potential energy turned into kinetic: hotter than the start (kT = 1/2)
}
