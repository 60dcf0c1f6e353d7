// ede-bench-elastic: the elastic gas with only the elastic path compiled in. It builds
// Engine<double, WallsBoundary, Elastic> directly and runs it, without make_engine, so this binary holds
// one engine instantiation, not the dozens of ede-bench. `ede-bench effects` runs it beside its own runs
// of the same scene (which go through make_engine, with every effect compiled into the binary) to show
// that compiling the other effects in costs the elastic gas nothing. Not a user tool: it prints the
// key=value line of the benchmarks' child processes.
//
//   ede-bench-elastic SCENE.toml [EVENTS]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "ede/scene.hpp"
#include "setup/setup.hpp"
#include "engine/engine_factory.hpp"
#include "timed_run.hpp"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "ede-bench-elastic: error: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ede;
  if (argc < 2 || argc > 3) return fail("usage: ede-bench-elastic SCENE.toml [EVENTS]");
  std::vector<Override> overrides;
  if (argc == 3) overrides.push_back({std::string("stop.events=") + argv[2]});
  auto scene = load_scene_file(argv[1], overrides);
  if (!scene) return fail(scene.error().message);
  if (scene.value().boundary != BoundaryKind::Walls || !scene.value().physics.elastic() ||
      scene.value().physics.has_gravity() || scene.value().physics.tc > 0 || scene.value().scalar != ScalarKind::Double)
    return fail(std::string(argv[1]) + ": this binary runs elastic gases in a walled box, in double, only");
  auto initial = build_initial_state(scene.value());
  if (!initial) return fail(initial.error().message);
  const EngineOptions options = engine_options_from(scene.value(), initial.value().size());
  GridShape shape;
  if (Status s = check_engine_input(initial.value(), options, shape); !s) return fail(s.error().message);
  Engine<double, WallsBoundary, Elastic> engine(initial.value(), options, shape, nullptr);
  std::printf("%s disks=%zu\n", tools::timed_run_report(engine).c_str(), initial.value().size());
  return 0;
}
