// The exact MSD and VACF over a log with step events (square wells): a step event changes both disks'
// velocities like a pair collision, and analysis/transport_*.cpp must follow it, or every disk that crossed
// a step drifts on its old velocity until its next hard-core collision. Reference: the displacements and
// velocities of the log's own states (Log::state_at, bit-identical to the engine's) at the MSD's origins
// and lags, the same origins as transport_msd.cpp places them; lags short enough (0.02 against a box of 1,
// speeds ~1) that the nearest image is the displacement. Exact up to the sums' rounding: 1e-9 relative.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

#include "ede/ede.hpp"
#include "ede/transport.hpp"
#include "tool_runner.hpp"  // temp_path

namespace {

const char* kWellGas = R"(seed = 5
[box]
size = [1.0, 1.0]
boundary = "periodic"
[[species]]
name = "gas"
count = 120
radius = 0.01
[species.velocity]
kind = "maxwell"
temperature = 1.0
[[physics.steps]]
radius = [0.03]
energy = [-1.0]
[stop]
time = 2.0
)";

double nearest(double d, double l) { return d - l * std::round(d / l); }

}  // namespace

TEST_CASE("transport with steps: the MSD and the VACF follow the velocities step events change",
          "[analysis][transport][steps]") {
  const std::string path = ede::test::temp_path("transport-steps.ede");
  {
    auto sim = ede::Simulation::create(ede::parse_scene_text(kWellGas, "wells.toml").value(), {.log_path = path}).value();
    REQUIRE(sim.run() == ede::RunStatus::ReachedTime);
    REQUIRE(sim.close());
  }
  const ede::Log log = ede::Log::open(path).value();
  const ede::EventCounts counts = log.count_events().value();
  REQUIRE(counts.of(ede::EventKind::Step) > 1000);  // the step events are there to follow

  ede::TransportOptions o;
  o.from = 0.5, o.to = 2.0, o.lag_step = 0.005, o.max_lag = 0.02, o.origins = 7;
  const auto msd = ede::mean_square_displacement(log, o);
  REQUIRE(msd.ok());
  const auto& m = msd.value();
  REQUIRE(m.lag.size() == 5);
  // transport_msd.cpp's origins: equally spaced from `from` to `to` less the longest lag.
  const double last_origin = *o.to - o.lag_step * double(m.lag.size() - 1);
  for (std::size_t k = 1; k < m.lag.size(); ++k) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t a = 0; a < o.origins; ++a) {
      const double t0 = *o.from + (last_origin - *o.from) * double(a) / double(o.origins - 1);
      const ede::State s0 = log.state_at(t0).value(), s1 = log.state_at(t0 + m.lag[k]).value();
      for (std::size_t i = 0; i < s0.size(); ++i) {
        const double dx = nearest(s1.x[i] - s0.x[i], s0.lx), dy = nearest(s1.y[i] - s0.y[i], s0.ly);
        sum += dx * dx + dy * dy, ++n;
      }
    }
    INFO("lag " << m.lag[k]);
    CHECK(m.msd[k] == Approx(sum / double(n)).epsilon(1e-9));
  }

  // The VACF at lag 0 is the time average of v^2 over the window: against the states' v^2 at many times
  // it agrees within its sampling error; a VACF blind to step events keeps pre-crossing speeds (a disk
  // entering a well speeds up) and the exact check above fails first anyway.
  const auto vacf = ede::velocity_autocorrelation(log, o);
  REQUIRE(vacf.ok());
  double v2 = 0;
  const int samples = 300;
  for (int q = 0; q < samples; ++q) {
    const ede::State s = log.state_at(*o.from + (*o.to - *o.from) * (q + 0.5) / samples).value();
    for (std::size_t i = 0; i < s.size(); ++i) v2 += s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i];
  }
  v2 /= double(samples) * 120.0;
  CHECK(vacf.value().c[0] == Approx(v2).epsilon(0.02));
}
