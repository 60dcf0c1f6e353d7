// The exact VACF and MSD over a log with thermostat events (analysis/transport_*.cpp take a redraw like a
// collision of one disk). In a gas whose disks almost never collide (mean free time ~200 / nu) the Andersen
// thermostat alone decorrelates velocities: each disk keeps its velocity for an exponential time of mean
// 1/nu, then draws an independent one, so C(t) = <v(0).v(t)> = (2 kT / m) e^(-nu t) in 2D, and
// D = (1/2) integral C = kT / (m nu). Tolerances: a few standard errors of 400 disks over 190 / nu.
#include <catch2/catch.hpp>

#include <cmath>

#include "ede/ede.hpp"
#include "ede/transport.hpp"
#include "tool_runner.hpp"  // temp_path

namespace {

const char* kIdealGas = R"(seed = 21
[box]
size = [50.0, 50.0]
boundary = "periodic"
[thermostat]
temperature = 1.0
rate = 1.0
[[species]]
name = "gas"
count = 400
radius = 0.005
[species.velocity]
kind = "maxwell"
temperature = 1.0
[stop]
time = 200.0
)";

}  // namespace

TEST_CASE("thermostat transport: the VACF of a collisionless gas decays as e^(-nu t), D = kT / (m nu)",
          "[analysis][transport][thermostat]") {
  const std::string path = ede::test::temp_path("thermo-ideal.ede");
  {
    auto sim = ede::Simulation::create(ede::parse_scene_text(kIdealGas, "ideal.toml").value(), {.log_path = path}).value();
    REQUIRE(sim.run() == ede::RunStatus::ReachedTime);
    REQUIRE(sim.close());
  }
  const ede::Log log = ede::Log::open(path).value();
  ede::TransportOptions o;
  o.from = 10, o.to = 200, o.lag_step = 0.25, o.max_lag = 4;
  const auto vacf = ede::velocity_autocorrelation(log, o);
  REQUIRE(vacf.ok());
  const ede::VelocityAutocorrelation& v = vacf.value();
  REQUIRE(v.lag.size() == 17);
  CHECK(v.c[0] == Approx(2.0).epsilon(0.03));
  for (std::size_t k = 0; k < v.lag.size(); k += 4) {
    INFO("lag " << v.lag[k]);
    CHECK(v.c[k] == Approx(2.0 * std::exp(-v.lag[k])).margin(0.04));
  }
  // (1/2) integral_0^4 2 e^-t dt = 1 - e^-4 (the trapezoidal rule on steps of 0.25 adds 0.5 %).
  CHECK(v.green_kubo.back() == Approx(1 - std::exp(-4.0)).epsilon(0.03));
  o.max_lag = 30, o.lag_step = 1;
  const auto msd = ede::mean_square_displacement(log, o);
  REQUIRE(msd.ok());
  // The MSD's slope over lags 15-30 from 20 overlapping origins: a standard error of roughly 4 %.
  CHECK(msd.value().diffusion == Approx(1.0).epsilon(0.12));
}
