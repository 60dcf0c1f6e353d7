// ede-sim as a user runs it: summaries, JSON keys, exact CSV, overrides, and clear errors on bad input.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include <signal.h>

#include <chrono>
#include <thread>

#include "ede/ede.hpp"
#include "tool_runner.hpp"

using namespace ede::test;

namespace {
// ede-sim's --json output read by a JSON parser (nlohmann-json, keys kept in order): one object, one line.
nlohmann::ordered_json summary_json(const std::string& out) {
  REQUIRE(!out.empty());
  CHECK(out.find('\n') == out.size() - 1);
  auto j = nlohmann::ordered_json::parse(out, nullptr, false);
  REQUIRE(!j.is_discarded());
  REQUIRE(j.is_object());
  return j;
}

double json_number(const std::string& out, const std::string& key) {
  const auto j = summary_json(out);
  REQUIRE(j.contains(key));
  REQUIRE(j[key].is_number());
  return j[key].get<double>();
}
}  // namespace

TEST_CASE("ede-sim runs the default scene and reports the required JSON keys", "[tool][ede-sim]") {
  const ToolRun r = run_tool("ede-sim", source_path("examples/gas.toml") + " --json --quiet", "json");
  REQUIRE(r.status == 0);
  const auto j = summary_json(r.out);
  // Every key, in the documented order (scripts may rely on it; ede/simulation.hpp: stable keys).
  std::vector<std::string> keys;
  for (const auto& [key, value] : j.items()) keys.push_back(key);
  CHECK(keys == std::vector<std::string>{
                    "scene", "seed", "disks", "scalar", "effects", "status", "stall_message", "events",
                    "events_by_kind", "samples", "stale_predictions", "tc_elastic", "collisions",
                    "collisions_per_particle", "sim_time", "wall_seconds", "setup_seconds", "events_before",
                    "events_per_second", "collisions_per_second", "energy_initial", "energy_final",
                    "momentum_initial", "momentum_final", "engine_bytes", "peak_rss_bytes"});
  CHECK(j["events_by_kind"]["pair"] == 50000);  // stop.collisions_per_particle = 50 with 2000 disks
  std::uint64_t by_kind = 0;
  for (const auto& [kind, count] : j["events_by_kind"].items()) by_kind += count.get<std::uint64_t>();
  CHECK(j["events"].get<std::uint64_t>() == by_kind);
  CHECK(j["momentum_final"].size() == 2);
  CHECK(json_number(r.out, "collisions_per_particle") == Approx(50).margin(1e-9));
  const double e0 = json_number(r.out, "energy_initial"), e1 = json_number(r.out, "energy_final");
  CHECK(std::abs(e1 - e0) / e0 < 1e-12);  // elastic: energy conserved to round-off
  CHECK(j["effects"].get<std::string>().rfind("walls, elastic", 0) == 0);
}

TEST_CASE("the default scene, the README's demo, runs without a warning", "[tool][ede-sim]") {
  const std::string log = std::string(EDE_BINARY_DIR) + "/tests/default-scene.ede";
  const ToolRun r = run_tool("ede-sim", source_path("examples/gas.toml") + " --quiet -o " + log, "default-scene");
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("warning") == std::string::npos);
}

TEST_CASE("ede-sim prints a readable summary", "[tool][ede-sim]") {
  const ToolRun r = run_tool("ede-sim", source_path("examples/gas.toml") + " --quiet", "text");
  REQUIRE(r.status == 0);
  for (const char* label : {"events", "collisions/disk", "simulated time", "wall time", "M events/s",
                            "kinetic energy", "momentum", "peak RSS", "effects"})
    CHECK(r.out.find(label) != std::string::npos);
}

TEST_CASE("ede-sim --final-state writes numbers that read back identically", "[tool][ede-sim]") {
  const std::string csv = std::string(EDE_BINARY_DIR) + "/tests/final-state.csv";
  const ToolRun r = run_tool("ede-sim",
                             source_path("examples/scenes/mixture.toml") + " --quiet --set stop.time=0.05 --final-state " + csv,
                             "csv");
  REQUIRE(r.status == 0);
  const auto rows = lines(read_file(csv));
  REQUIRE(rows.size() > 1);
  CHECK(rows[0] == "id,species,x,y,vx,vy,radius,mass");
  // Each number printed with %.17g parses to a double that prints back to the same text.
  for (std::size_t k = 1; k < rows.size(); k += 37) {
    std::istringstream fields(rows[k]);
    std::string field;
    for (int col = 0; std::getline(fields, field, ','); ++col) {
      if (col < 2) continue;
      char again[40];
      std::snprintf(again, sizeof again, "%.17g", std::strtod(field.c_str(), nullptr));
      REQUIRE(field == again);
    }
  }
}

TEST_CASE("ede-sim --set overrides scene values (parameter scans)", "[tool][ede-sim]") {
  const ToolRun r = run_tool("ede-sim",
                             source_path("examples/gas.toml") +
                                 " --json --quiet --set species.gas.count=300 --set box.boundary=periodic",
                             "set");
  REQUIRE(r.status == 0);
  CHECK(json_number(r.out, "disks") == 300);
  CHECK(summary_json(r.out)["effects"].get<std::string>().rfind("periodic", 0) == 0);
}

TEST_CASE("ede-sim runs float and long double scenes", "[tool][ede-sim]") {
  for (const char* scalar : {"float", "\"long double\""}) {
    const ToolRun r = run_tool("ede-sim",
                               source_path("examples/gas.toml") + " --json --quiet --set 'engine.scalar=" + scalar + "'",
                               "scalar");
    INFO(scalar << ": " << r.err);
    REQUIRE(r.status == 0);
    CHECK(json_number(r.out, "collisions_per_particle") == Approx(50).margin(1e-6));
  }
}

TEST_CASE("ede-sim runs float128 scenes without a log, and refuses to log them", "[tool][ede-sim][float128]") {
  const std::string scene = source_path("examples/gas.toml") + " --quiet --set engine.scalar=float128";
#if EDE_HAVE_FLOAT128
  const std::string csv = std::string(EDE_BINARY_DIR) + "/tests/final-state-float128.csv";
  const ToolRun r = run_tool("ede-sim", scene + " --json --final-state " + csv, "float128");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(summary_json(r.out)["scalar"] == "float128");
  CHECK(json_number(r.out, "collisions_per_particle") == Approx(50).margin(1e-6));
  const auto rows = lines(read_file(csv));
  REQUIRE(rows.size() > 1);
  CHECK(rows[0] == "id,species,x,y,vx,vy,radius,mass");
  CHECK(rows[1].size() > 4 * 30);  // 36 significant digits per number, not double's 17
  const std::string log = std::string(EDE_BINARY_DIR) + "/tests/float128.ede";
  const ToolRun logged = run_tool("ede-sim", scene + " -o " + log, "float128-log");
  CHECK(logged.status == 1);
  CHECK(logged.err.find("run without a log (no -o)") != std::string::npos);
#else
  const ToolRun r = run_tool("ede-sim", scene, "float128");
  CHECK(r.status == 1);
  CHECK(r.err.find("without the __float128 engine") != std::string::npos);
#endif
}

TEST_CASE("ede-sim rejects bad input with a clear message and a non-zero exit", "[tool][ede-sim]") {
  const std::string dir = std::string(EDE_BINARY_DIR) + "/tests/";
  SECTION("missing file") {
    const ToolRun r = run_tool("ede-sim", dir + "no-such-scene.toml", "missing");
    CHECK(r.status == 1);
    CHECK(r.err.find("no-such-scene.toml") != std::string::npos);
  }
  SECTION("typo in a key names file, line and the fix") {
    std::ofstream(dir + "typo.toml") << "[box]\nsize = [1.0, 1.0]\n[[species]]\nname = \"a\"\ncount = 3\nradus = 0.01\n"
                                        "[stop]\ntime = 1\n";
    const ToolRun r = run_tool("ede-sim", dir + "typo.toml", "typo");
    CHECK(r.status == 1);
    CHECK(r.err.find("typo.toml:6") != std::string::npos);
    CHECK(r.err.find("radius") != std::string::npos);
  }
  SECTION("overlapping explicit disks name both disks") {
    std::ofstream(dir + "overlap.toml")
        << "[[species]]\nname = \"a\"\nradius = 0.1\n[species.placement]\nkind = \"explicit\"\n"
           "positions = [[0.5, 0.5], [0.6, 0.5]]\n[stop]\ntime = 1\n";
    const ToolRun r = run_tool("ede-sim", dir + "overlap.toml", "overlap");
    CHECK(r.status == 1);
    CHECK(r.err.find("overlap") != std::string::npos);
    CHECK(r.err.find("overlap.toml") != std::string::npos);
  }
  SECTION("a bad override") {
    const ToolRun r = run_tool("ede-sim", source_path("examples/gas.toml") + " --set physics.restitution=2", "badset");
    CHECK(r.status == 1);
    CHECK(r.err.find("--set") != std::string::npos);
  }
  SECTION("a bad command line: status 2 and CLI11's message; --help: status 0") {
    const ToolRun r = run_tool("ede-sim", "--no-such-flag", "badflag");
    CHECK(r.status == 2);
    CHECK(r.err.find("--no-such-flag") != std::string::npos);
    CHECK(run_tool("ede-sim", source_path("examples/gas.toml") + " --set", "badset-arg").status == 2);
    CHECK(run_tool("ede-sim", "--help", "help").status == 0);
  }
}

TEST_CASE("ede-sim on Ctrl-C: summary so far, what the log kept, how to resume, and the resume completes it exactly",
          "[tool][ede-sim][resume][slow]") {
  // 4000 disks for 6 M events (seconds): SIGINT arrives once the log holds a resumable keyframe.
  const std::string scene = temp_path("sigint.toml");
  std::ofstream(scene) << "seed = 2\n[box]\nsize = [1.0, 1.0]\nboundary = \"periodic\"\n[engine]\nrebuild_interval = "
                          "50000\n[[species]]\nname = \"gas\"\ncount = 4000\nradius = 0.004\n[species.velocity]\n"
                          "kind = \"speed\"\nspeed = 1.0\n[stop]\nevents = 6000000\n";
  const std::string whole = temp_path("sigint-whole.ede"), cut = temp_path("sigint-cut.ede");
  const std::string out = temp_path("sigint.out"), err = temp_path("sigint.err");
  sim_log(scene, "", whole, "sigint-whole");
  std::remove(cut.c_str());
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    std::freopen(out.c_str(), "w", stdout);
    std::freopen(err.c_str(), "w", stderr);
    execl(tool_path("ede-sim").c_str(), "ede-sim", scene.c_str(), "--json", "-o", cut.c_str(), (char*)nullptr);
    _exit(127);
  }
  // The first resumable keyframe after the start is written once 50 000 events have run.
  for (int k = 0; k < 4000; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (auto log = ede::Log::open(cut); log && log.value().info().resumable_keyframes > 1) break;
  }
  kill(pid, SIGINT);
  int raw = 0;
  waitpid(pid, &raw, 0);
  const ToolRun interrupted{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_file(out), read_file(err)};
  INFO(interrupted.err);
  REQUIRE(interrupted.status == 130);
  CHECK(interrupted.out.find("\"status\":\"interrupted\"") != std::string::npos);
  CHECK(interrupted.err.find("interrupted at t = ") != std::string::npos);
  CHECK(interrupted.err.find("ede-sim --resume " + cut) != std::string::npos);
  const ToolRun resumed = run_tool("ede-sim", "--resume " + cut + " -q", "sigint-resume");
  INFO(resumed.err);
  REQUIRE(resumed.status == 0);
  CHECK(resumed.out.find("resumed the run after event") != std::string::npos);
  CHECK(read_file(cut) == read_file(whole));
}

TEST_CASE("one scene run from two directories writes the same log, byte for byte", "[tool][ede-sim][determinism]") {
  // The log records the scene's file name, not the path it was given by (scene/scene_label.hpp).
  const std::string text = read_file(source_path("examples/gas.toml"));
  const std::string dir_a = temp_path("dir-a"), dir_b = temp_path("dir-b");
  REQUIRE(std::system(("mkdir -p '" + dir_a + "/deeper' '" + dir_b + "'").c_str()) == 0);
  std::ofstream(dir_a + "/deeper/gas.toml") << text;
  std::ofstream(dir_b + "/gas.toml") << text;
  const std::string log_a = temp_path("dir-a.ede"), log_b = temp_path("dir-b.ede");
  const std::string args = " -q --set stop.events=20000 -o ";
  REQUIRE(run_tool("ede-sim", "'" + dir_a + "/deeper/gas.toml'" + args + "'" + log_a + "'", "dir-a").status == 0);
  REQUIRE(run_tool("ede-sim", "'" + dir_b + "/gas.toml'" + args + "'" + log_b + "'", "dir-b").status == 0);
  const std::string a = read_file(log_a), b = read_file(log_b);
  REQUIRE(a.size() > 1000);
  CHECK(a == b);
}

TEST_CASE("ede-sim --continue of a sheared run: refused with the reason where the images were shifted, exact "
          "where they were aligned", "[tool][ede-sim][shear]") {
  // 900 disks at packing 0.45 from a lattice, sheared at 0.5 in a 30 x 30 box: the images are aligned
  // every lx / (rate ly) = 2 time units. At t = 3 they are shifted by 15, and a new run (which starts them
  // aligned) would put disks touching across the top edge onto each other: refused, naming the aligned
  // times. From t = 2 the continuation starts, and its first state is the source's at t = 2.
  const std::string scene = temp_path("sheared-continue.toml"), log = temp_path("sheared-continue.ede");
  std::ofstream(scene) << "seed = 6\n[box]\nsize = [30.0, 30.0]\nboundary = \"lees-edwards\"\nshear_rate = 0.5\n"
                          "[physics]\nrestitution = 0.95\n[[species]]\nname = \"gas\"\ncount = 900\n"
                          "radius = 0.37846987830302403\n[species.placement]\nkind = \"lattice\"\n"
                          "[species.velocity]\nkind = \"maxwell\"\ntemperature = 1.0\n[stop]\ntime = 3.0\n";
  REQUIRE(run_tool("ede-sim", scene + " -q -o " + log, "sheared-continue-source").status == 0);
  const ToolRun shifted = run_tool("ede-sim", "-q --continue " + log + " -o " + temp_path("sheared-continued.ede"),
                                   "sheared-continue-shifted");
  CHECK(shifted.status != 0);
  CHECK_THAT(shifted.err, Catch::Matchers::Contains("overlap") && Catch::Matchers::Contains("Lees-Edwards") &&
                              Catch::Matchers::Contains("a multiple of lx / (shear_rate ly) = 2"));
  const std::string aligned = temp_path("sheared-continued-aligned.ede");
  const ToolRun ok = run_tool("ede-sim", "-q --continue " + log + " --at 2 -o " + aligned, "sheared-continue-aligned");
  INFO(ok.err);
  REQUIRE(ok.status == 0);
  const ede::State a = ede::Log::open(log).value().state_at(2).value();
  const ede::State b = ede::Log::open(aligned).value().state_at_event(0).value();
  CHECK(a.shear_offset == 0);
  for (std::size_t i = 0; i < a.size(); ++i) CHECK((a.x[i] == b.x[i] && a.y[i] == b.y[i] && a.vx[i] == b.vx[i]));
}
