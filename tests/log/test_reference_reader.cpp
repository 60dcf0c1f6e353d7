// The fast reader against the reference reader (reference_reader.hpp, written from schema/FORMAT.md
// alone) on every example scene, cut to its first 20 000 engine events, in format version 2, and on the
// version 1 fixtures: after every chunk both hold the same records, bit for bit.
#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>

#include "run/log_run_info.hpp"
#include "ede/scene.hpp"
#include "log_test_support.hpp"
#include "reference_compare.hpp"
#include "setup/setup.hpp"

using namespace ede;
using namespace ede::test;

namespace {

std::uint64_t compare_any(const std::string& path) {
  switch (open_log(path)->header().scalar) {
    case ScalarKind::Float: return compare_with_reference<float>(path);
    case ScalarKind::LongDouble: return compare_with_reference<long double>(path);
    default: return compare_with_reference<double>(path);
  }
}

template <class T>
std::string run_example(const Scene& scene, const std::string& file) {
  auto initial = build_initial_state(scene);
  REQUIRE(initial.ok());
  const EngineOptions options = engine_options_from(scene, initial.value().size());
  auto e = make_engine<T>(initial.value(), options);
  REQUIRE(e.ok());
  const std::string path = temp_path(file);
  auto w = LogWriter<T>::create(path, log_run_info(scene, options, initial.value().species_names),
                                LogSettings::from(scene.log));
  REQUIRE(w.ok());
  e.value()->add_sink(w.value().get());
  e.value()->run();
  REQUIRE(w.value()->error().empty());
  return path;
}

}  // namespace

TEST_CASE("the fast reader agrees with the reference reader on every example scene", "[log][v2][reference]") {
  namespace fs = std::filesystem;
  std::vector<fs::path> scenes;
  for (const char* dir : {"/examples", "/examples/scenes"})
    for (const auto& f : fs::directory_iterator(std::string(EDE_SOURCE_DIR) + dir))
      if (f.path().extension() == ".toml") scenes.push_back(f.path());
  std::sort(scenes.begin(), scenes.end());
  REQUIRE(scenes.size() >= 10);
  for (const fs::path& s : scenes) {
    INFO(s.string());
    auto scene = load_scene_file(s.string(), {Override{"stop.events=20000"}});
    REQUIRE(scene.ok());
    if (scene.value().scalar == ScalarKind::Float128) continue;  // no log for float128 runs
    const std::string file = "reference-" + s.stem().string() + ".ede";
    std::string path;
    switch (scene.value().scalar) {
      case ScalarKind::Float: path = run_example<float>(scene.value(), file); break;
      case ScalarKind::LongDouble: path = run_example<long double>(scene.value(), file); break;
      default: path = run_example<double>(scene.value(), file); break;
    }
    const Scene& sc = scene.value();  // steps, the thermostat and shear are version 3's kinds
    CHECK(open_log(path)->header().format_version == (sc.physics.has_steps() || sc.thermostatted() || sc.sheared() ? 3u : 2u));
    CHECK(compare_any(path) == open_log(path)->total_events());
  }
}

TEST_CASE("the fast reader agrees with the reference reader on the version 1 fixtures", "[log][reference]") {
  for (const char* name : {"v1-periodic-gas", "v1-walls-tc", "v1-periodic-long-double"}) {
    INFO(name);
    const std::string path = std::string(EDE_SOURCE_DIR) + "/tests/log/fixtures/" + name + ".ede";
    CHECK(compare_any(path) == open_log(path)->total_events());
  }
}
