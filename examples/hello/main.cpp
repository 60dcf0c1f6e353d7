// hello: a program on the installed library (find_package(ede), <ede/ede.hpp> only). It runs a scene with an
// event log, then opens the log and prints the state at a time, rebuilt from the log alone, exactly.
//   hello SCENE.toml LOG.ede TIME      e.g.  hello examples/gas.toml gas.ede 0.5
#include <cstdio>
#include <ede/ede.hpp>

int main(int argc, char** argv) try {
  if (argc != 4) return std::fprintf(stderr, "usage: hello SCENE.toml LOG.ede TIME\n"), 2;
  const ede::Scene scene = ede::load_scene_file(argv[1]).value();
  ede::Simulation sim = ede::Simulation::create(scene, {.log_path = argv[2]}).value();
  sim.run();
  sim.close().value();
  std::printf("ran %s: %s\n", argv[1], ede::to_string(sim.status()));

  const ede::Log log = ede::Log::open(argv[2]).value();
  const ede::State s = log.state_at(ede::parse_exact(argv[3], log.info().scalar).value()).value();
  auto exact = [&](long double v) { return ede::exact_text(v, s.scalar); };
  std::printf("log: %llu events; at t = %s, after %llu of them, %zu disks\n", (unsigned long long)log.info().events,
              exact(s.time).c_str(), (unsigned long long)s.events, s.size());
  std::printf("disk 0: x %s y %s vx %s vy %s\n", exact(s.x.exact(0)).c_str(), exact(s.y.exact(0)).c_str(),
              exact(s.vx.exact(0)).c_str(), exact(s.vy.exact(0)).c_str());
  return 0;
} catch (const ede::Exception& e) {
  std::fprintf(stderr, "hello: %s\n", e.what());
  return 1;
}
