// ede-bench-elastic: the elastic gas with only the elastic path compiled in. It builds
// Engine<double, WallsBoundary, Elastic> directly and runs it, without make_engine, so this binary holds
// one engine instantiation, not the library's table of them. `ede-bench effects` runs it beside its own
// runs of the same scene (which go through make_engine, with every effect compiled into the binary) to
// show that compiling the other effects in costs the elastic gas nothing. Not a user tool: it prints the
// key=value line of the benchmarks' child processes.
//
//   ede-bench-elastic SCENE.toml [--set key=value]...
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "ede/scene.hpp"
#include "ede/internal/engine_template.hpp"
#include "ede/internal/run.hpp"
#include "report_error.hpp"
#include "study/timed_run.hpp"

namespace {

int fail(const std::string& message) {
  ede::tools::report_error("ede-bench-elastic", message);
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ede;
  std::string path;
  std::vector<std::string> sets;
  CLI::App app{"ede-bench-elastic: the elastic gas in a binary holding the elastic engine alone (ede-bench effects)"};
  app.add_option("scene", path, "scene file (TOML): an elastic gas in a walled box, in double")->required();
  app.add_option("--set", sets, "override a scene value, e.g. --set stop.events=100000 (repeatable)");
  tools::add_version_flags(app, "ede-bench-elastic");
  if (const auto stop = tools::parse_command_line(app, argc, argv)) return *stop;
  std::vector<Override> overrides;
  for (const std::string& s : sets) overrides.push_back({s});
  auto scene = load_scene_file(path, overrides);
  if (!scene) return fail(scene.error().message);
  const Scene& sc = scene.value();
  if (sc.boundary != BoundaryKind::Walls || !sc.physics.elastic() || sc.physics.has_gravity() ||
      sc.physics.tc > 0 || sc.scalar != ScalarKind::Double)
    return fail(path + ": this binary runs elastic gases in a walled box, in double, only");
  // Planned as every run is (plan_run); only the engine is made here, from the one instantiation.
  auto plan = plan_run(sc);
  if (!plan) return fail(plan.error().message);
  const RunPlan& p = plan.value();
  GridShape shape;
  if (Status s = check_engine_input(p.initial, p.options, shape); !s) return fail(s.error().message);
  Engine<double, WallsBoundary, Elastic> engine(p.initial, p.options, shape, nullptr);
  std::printf("%s disks=%zu\n", study::timed_run_report(engine).c_str(), p.initial.size());
  return 0;
}
