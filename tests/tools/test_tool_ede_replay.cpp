// ede-replay as a user runs it: states byte-identical to the engine's, summaries, event listings, verify
// and diff, and clear errors (never a crash) on missing, foreign, truncated and corrupted files.
//
// Logs are written by ede-sim from the example scenes, shortened with --set, with small chunks and
// keyframe intervals so that every log has several of each and seeks cross keyframes.
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "log/log_reader.hpp"
#include "tool_runner.hpp"

using namespace ede::test;

namespace {

const std::string kSmallRecords = " --set log.chunk_events=128 --set log.keyframe_interval=512";
// periodic.toml (1000 disks) shortened: ~4000 events, 30 chunks, 8 keyframes.
const std::string kPeriodic = " --set stop.time=0.25" + kSmallRecords;

std::string test_file(const std::string& name) { return std::string(EDE_BINARY_DIR) + "/tests/replay-" + name; }

// Runs ede-sim on an example scene with the given options; the log is written to test_file(name).
std::string make_log(const std::string& name, const std::string& scene, const std::string& options) {
  return sim_log(source_path(scene), options, test_file(name), "replay-sim-" + name);
}

ToolRun replay(const std::string& args, const std::string& tag) {
  return run_tool("ede-replay", args, "replay-" + tag);
}

void write_bytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

std::shared_ptr<ede::LogReader> open_reader(const std::string& path) {
  auto r = ede::LogReader::open(path);
  INFO((r ? "" : r.error().message));
  REQUIRE(r);
  return r.value();
}

// Where the records of a complete log end (the index follows).
std::uint64_t end_of_records(const ede::LogReader& log) {
  std::uint64_t end = 0;
  for (const auto* list : {&log.chunks(), &log.keyframes()})
    for (const ede::LogRecordRef& r : *list) end = std::max(end, r.offset + 56 + r.payload_size);
  return end;
}

// The number after `label` in a line of text ("index,..." rows excluded).
std::uint64_t number_after(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  REQUIRE(at != std::string::npos);
  return std::strtoull(text.c_str() + at + label.size(), nullptr, 10);
}

}  // namespace

TEST_CASE("ede-replay --at end is byte-identical to ede-sim --final-state", "[tool][ede-replay]") {
  struct Case {
    const char* scene;
    const char* options;
  };
  const Case cases[] = {
      {"examples/gas.toml", " --set species.gas.count=300 --set stop.time=0.5"},
      {"examples/scenes/periodic.toml", " --set species.gas.count=300 --set stop.time=0.5"},
      {"examples/gas.toml", " --set species.gas.count=300 --set stop.time=0.5 --set engine.scalar=float"},
      {"examples/scenes/periodic.toml", " --set stop.time=0.3 --set 'engine.scalar=\"long double\"'"},
      {"examples/scenes/inelastic-tc.toml",
       " --set species.grains.count=300 --set stop.time=0.5 --set engine.scalar=float"},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string name = "final-" + std::to_string(k++);
    const std::string csv = test_file(name + ".csv");
    const std::string log =
        make_log(name + ".ede", c.scene, std::string(c.options) + kSmallRecords + " --final-state " + csv);
    const ToolRun r = replay(log + " --at end", name);
    INFO(c.scene << c.options << ": " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out == read_file(csv));
    // The same through the subcommand's name, to a file.
    const ToolRun to_file = replay("state " + log + " --at end --csv -o " + test_file(name + "-replayed.csv"), name);
    REQUIRE(to_file.status == 0);
    CHECK(read_file(test_file(name + "-replayed.csv")) == read_file(csv));
  }
}

TEST_CASE("ede-replay --at t equals the engine's own state at sampling times", "[tool][ede-replay]") {
  // A tiny walls scene with sampling; the engine's state at a sample is the state ede-sim reports when it
  // stops at that time. The times are exact binary fractions, the same value in every scalar type.
  const std::string scene = test_file("sampled.toml");
  std::ofstream(scene) << "seed = 3\n[box]\nsize = [1.0, 1.0]\n[[species]]\nname = \"gas\"\ncount = 120\n"
                          "radius = 0.01\n[species.velocity]\nkind = \"speed\"\nspeed = 1.0\n"
                          "[sampling]\ninterval = 0.125\n[stop]\ntime = 0.5\n"
                          "[log]\nchunk_events = 64\nkeyframe_interval = 256\n";
  for (const char* scalar : {"double", "float", "\"long double\""}) {
    const std::string set = std::string(" --set 'engine.scalar=") + scalar + "'";
    const std::string log = sim_log(scene, set, test_file("sampled.ede"), "replay-sampled-sim");
    for (const char* t : {"0.125", "0.25", "0.375"}) {
      const std::string csv = test_file("sampled-engine.csv");
      const ToolRun engine = run_tool(
          "ede-sim", scene + " -q" + set + " --set stop.time=" + t + " --final-state " + csv, "replay-sampled-stop");
      REQUIRE(engine.status == 0);
      const ToolRun r = replay(log + " --at " + t, "sampled");
      INFO(scalar << " t = " << t << ": " << r.err);
      REQUIRE(r.status == 0);
      CHECK(r.out == read_file(csv));
    }
  }
}

TEST_CASE("ede-replay --event N is the state after N events", "[tool][ede-replay]") {
  const std::string log = make_log("by-event.ede", "examples/scenes/periodic.toml", kPeriodic);
  const ToolRun all = replay("events " + log, "by-event-list");
  REQUIRE(all.status == 0);
  const auto rows = lines(all.out);
  REQUIRE(rows.size() > 1200);
  // After event n-1 and before event n, the state at the time of event n-1 is the state after n events.
  int checked = 0;
  for (std::size_t n : {1u, 200u, 511u, 512u, 513u, 1100u}) {
    const std::string t_prev = csv_fields(rows[n])[1], t_next = csv_fields(rows[n + 1])[1];
    if (t_prev == t_next) continue;
    const ToolRun by_event = replay(log + " --event " + std::to_string(n), "by-event-n");
    const ToolRun by_time = replay(log + " --at " + t_prev, "by-event-t");
    REQUIRE(by_event.status == 0);
    REQUIRE(by_time.status == 0);
    CHECK(by_event.out == by_time.out);
    ++checked;
  }
  CHECK(checked >= 4);
  // --event 0 is the initial state: at t = 0, before any event.
  const ToolRun initial = replay(log + " --event 0", "by-event-0");
  REQUIRE(initial.status == 0);
  CHECK(initial.out == replay(log + " --at 0", "by-event-at0").out);
}

TEST_CASE("ede-replay state --collisions-per-disk and export --every-collisions-per-disk", "[tool][ede-replay]") {
  const std::string log = make_log("by-collisions.ede", "examples/scenes/periodic.toml", kPeriodic);
  const ToolRun all = replay("events " + log, "by-coll-list");
  REQUIRE(all.status == 0);
  const auto rows = lines(all.out);
  const std::size_t disks = open_reader(log)->header().disks;
  // The state after the event that is the ceil(1.5 N / 2)-th pair collision.
  const std::size_t target = std::size_t(std::ceil(1.5 * double(disks) / 2));
  std::size_t pairs = 0, n = 0;
  for (std::size_t k = 1; k < rows.size() && pairs < target; ++k)
    if (csv_fields(rows[k])[2] == "pair") ++pairs, n = k;  // row k is event k - 1: n events through it
  REQUIRE(pairs == target);
  const ToolRun by_collisions = replay(log + " --collisions-per-disk 1.5", "by-coll");
  REQUIRE(by_collisions.status == 0);
  CHECK(by_collisions.out == replay(log + " --event " + std::to_string(n), "by-coll-event").out);
  // Past the log's pair collisions: a clear error.
  const ToolRun past = replay(log + " --collisions-per-disk 1e9", "by-coll-past");
  CHECK(past.status == 1);
  CHECK(past.err.find("pair collisions, fewer than") != std::string::npos);
  // Frames every 0.5 collisions per disk, from 0 to the last complete mark.
  const std::string xyz = test_file("by-collisions.xyz");
  REQUIRE(replay("export " + log + " -o " + xyz + " --every-collisions-per-disk 0.5", "by-coll-xyz").status == 0);
  std::ifstream in(xyz);
  std::string line;
  int frames = 0;
  for (std::size_t k = 0; std::getline(in, line); ++k)
    if (line.find("Lattice=") != std::string::npos) ++frames;
  std::size_t total_pairs = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) total_pairs += csv_fields(rows[k])[2] == "pair" ? 1 : 0;
  int expected = 0;
  for (int k = 0; std::ceil(0.5 * k * double(disks) / 2) <= double(total_pairs); ++k) ++expected;
  CHECK(frames == expected);
  CHECK(frames > 3);
  CHECK(replay("export " + log + " -o " + test_file("x.gsd") + " --every-collisions-per-disk 0.5", "coll-gsd").status == 2);
}

TEST_CASE("ede-replay info summarises a log without replaying it", "[tool][ede-replay]") {
  const std::string log_path = test_file("info.ede");
  const ToolRun sim =
      run_tool("ede-sim",
               source_path("examples/scenes/time-reversal.toml") + " -q --set species.gas.count=100 --set stop.time=6" +
                   kSmallRecords + " -o " + log_path,
               "replay-info-sim");
  REQUIRE(sim.status == 0);
  const ToolRun r = replay("info " + log_path + " --scene", "info");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  for (const char* label : {"scene", "seed", "engine", "flags", "scalar", "disks", "box", "species", "events", "time",
                            "chunks", "keyframes", "size", "bytes/event"})
    CHECK(r.out.find(label) != std::string::npos);
  CHECK(r.out.find("complete; the run ended: reached stop.time") != std::string::npos);
  CHECK(r.out.find("gas 100") != std::string::npos);
  CHECK(r.out.find("seed             8") != std::string::npos);
  CHECK(r.out.find("walls") != std::string::npos);
  // The counts by kind are the engine's (ede-sim's summary counts the same events, and cells besides).
  for (const char* kind : {"pair ", "wall ", "wrap ", "action "})
    CHECK(number_after(r.out, kind) == number_after(sim.out, kind));
  CHECK(number_after(r.out, "action ") == 1);
  const auto log = open_reader(log_path);
  CHECK(number_after(r.out, "events           ") == log->total_events());
  CHECK(number_after(r.out, "chunks           ") == log->chunks().size());
  CHECK(number_after(r.out, "keyframes        ") == log->keyframes().size());
  CHECK(r.out.find("time             0 to 6; events from t = ") != std::string::npos);
  // --scene: the effective scene, overrides included.
  CHECK(r.out.find("[[actions]]") != std::string::npos);
  CHECK(r.out.find("species.gas.count=100") != std::string::npos);
}

TEST_CASE("ede-replay events lists a time or index range exactly", "[tool][ede-replay]") {
  const std::string log = make_log("events.ede", "examples/scenes/periodic.toml", kPeriodic);
  const ToolRun all = replay("events " + log, "events-all");
  REQUIRE(all.status == 0);
  const auto rows = lines(all.out);
  REQUIRE(rows[0] == "index,time,kind,i,j,vix,viy,vjx,vjy");
  REQUIRE(rows.size() == open_reader(log)->total_events() + 1);
  int wraps = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const auto f = csv_fields(rows[k]);
    REQUIRE(f.size() == 9);
    CHECK(f[0] == std::to_string(k - 1));
    if (f[2] == "wrap") {
      ++wraps;
      CHECK((f[4] == "0" || f[4] == "1" || f[4] == "2" || f[4] == "3"));
      CHECK((f[5].empty() && f[6].empty() && f[7].empty() && f[8].empty()));
    } else {
      REQUIRE(f[2] == "pair");
      CHECK(!f[8].empty());
    }
  }
  CHECK(wraps > 0);

  SECTION("a time range is every event with T0 <= time <= T1, bounds included") {
    // Bounds equal to logged times, so inclusion is tested at the boundary.
    const std::string t0 = csv_fields(rows[700])[1], t1 = csv_fields(rows[1400])[1];
    const ToolRun r = replay("events " + log + " --from " + t0 + " --to " + t1, "events-time");
    REQUIRE(r.status == 0);
    std::vector<std::string> expected{rows[0]};
    for (std::size_t k = 1; k < rows.size(); ++k) {
      const double t = std::strtod(csv_fields(rows[k])[1].c_str(), nullptr);
      if (t >= std::strtod(t0.c_str(), nullptr) && t <= std::strtod(t1.c_str(), nullptr)) expected.push_back(rows[k]);
    }
    CHECK(lines(r.out) == expected);
    CHECK(expected.size() >= 702);
  }
  SECTION("an index range, bounds included, to a file") {
    const std::string out = test_file("events-range.csv");
    const ToolRun r = replay("events " + log + " --from-event 510 --to-event 520 -o " + out, "events-index");
    REQUIRE(r.status == 0);
    const std::vector<std::string> expected(rows.begin() + 511, rows.begin() + 522);
    const auto got = lines(read_file(out));
    REQUIRE(got.size() == 12);
    CHECK(std::vector<std::string>(got.begin() + 1, got.end()) == expected);
  }
  SECTION("walls and actions: wall rows carry v_i only, the action row no disk") {
    const std::string tr = make_log("events-tr.ede", "examples/scenes/time-reversal.toml",
                                    " --set species.gas.count=100 --set stop.time=6" + kSmallRecords);
    const ToolRun r = replay("events " + tr + " --from 4.9 --to 5.1", "events-tr");
    REQUIRE(r.status == 0);
    int walls = 0, actions = 0;
    for (const std::string& row : lines(r.out)) {
      const auto f = csv_fields(row);
      if (f[2] == "wall") {
        ++walls;
        CHECK((!f[6].empty() && f[7].empty() && f[8].empty()));
      }
      if (f[2] == "action") {
        ++actions;
        CHECK(row.substr(row.find(",action")) == ",action,,,,,,");
        CHECK(f[1] == "5");
      }
    }
    CHECK(walls > 0);
    CHECK(actions == 1);
  }
}

TEST_CASE("ede-replay events --full: positions, velocities before, impulse, impact parameter and relative speeds",
          "[tool][ede-replay]") {
  const std::string log = make_log("events-full.ede", "examples/scenes/time-reversal.toml",
                                   " --set species.gas.count=100 --set stop.time=1" + kSmallRecords);
  const ToolRun r = replay("events " + log + " --full", "events-full");
  REQUIRE(r.status == 0);
  const auto rows = lines(r.out);
  REQUIRE(rows[0] == "index,time,kind,i,j,vix,viy,vjx,vjy,xi,yi,xj,yj,vix_before,viy_before,vjx_before,vjy_before,"
                     "impulse_x,impulse_y,impulse,impact_parameter,relative_speed,normal_speed,tangential_speed");
  const auto num = [](const std::string& s) { return std::strtod(s.c_str(), nullptr); };
  int pairs = 0, walls = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    auto f = csv_fields(rows[k]);
    f.resize(24);
    if (f[2] == "pair") {
      ++pairs;
      // The impulse is m_i (v_i' - v_i) (unit masses here), b in [-1, 1], g_n > 0 and g_n^2 + g_t^2 = g^2.
      CHECK(num(f[17]) == Approx(num(f[5]) - num(f[13])).margin(1e-12));
      CHECK(num(f[18]) == Approx(num(f[6]) - num(f[14])).margin(1e-12));
      CHECK(std::fabs(num(f[20])) <= 1 + 1e-12);
      CHECK(num(f[22]) > 0);
      CHECK(num(f[22]) * num(f[22]) + num(f[23]) * num(f[23]) == Approx(num(f[21]) * num(f[21])).epsilon(1e-9));
    } else if (f[2] == "wall") {
      ++walls;
      CHECK(!f[19].empty());
      CHECK((f[20].empty() && f[23].empty()));
      CHECK(num(f[19]) == Approx(2 * num(f[22])).epsilon(1e-12));  // elastic wall: |J| = 2 m |v_n|
    }
  }
  CHECK(pairs > 50);
  CHECK(walls > 5);
}

TEST_CASE("ede-replay events: a rough log adds the spins after (and with --full before) each event",
          "[tool][ede-replay][rough]") {
  const std::string log = make_log("events-rough.ede", "examples/rough/equipartition.toml",
                                   " --set species.gas.count=200 --set stop.time=0.2" + kSmallRecords);
  const ToolRun narrow = replay("events " + log, "events-rough");
  REQUIRE(narrow.status == 0);
  CHECK(lines(narrow.out)[0] == "index,time,kind,i,j,vix,viy,vjx,vjy,omega_i,omega_j");
  const ToolRun r = replay("events " + log + " --full", "events-rough-full");
  REQUIRE(r.status == 0);
  const auto rows = lines(r.out);
  REQUIRE(rows[0].size() > 60);
  CHECK_THAT(rows[0], Catch::Matchers::EndsWith("tangential_speed,omega_i,omega_j,omega_i_before,omega_j_before"));
  // Each disk's spin before an event is its spin after the previous event that touched it (spins change
  // only in collisions), and rough collisions do change spins.
  std::map<std::string, std::string> spin;
  int checked = 0, changed = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    auto f = csv_fields(rows[k]);
    f.resize(28);
    const bool pair = f[2] == "pair";
    if (f[3].empty()) continue;
    for (int side = 0; side < (pair ? 2 : 1); ++side) {
      const std::string &disk = f[3 + side], &after = f[24 + side], &before = f[26 + side];
      if (spin.count(disk)) {
        ++checked;
        CHECK(spin[disk] == before);
      }
      changed += after != before ? 1 : 0;
      spin[disk] = after;
    }
  }
  CHECK(checked > 100);
  CHECK(changed > 100);
}

TEST_CASE("ede-replay verify re-runs a log's scene and finds it identical", "[tool][ede-replay]") {
  struct Case {
    const char* scene;
    const char* options;
  };
  const Case cases[] = {
      {"examples/gas.toml", " --set species.gas.count=300 --set stop.time=0.5"},
      {"examples/scenes/periodic.toml", " --set species.gas.count=300 --set stop.time=0.5 --set engine.scalar=float"},
      {"examples/scenes/inelastic-tc.toml", " --set species.grains.count=300 --set stop.time=0.5"},
      {"examples/scenes/time-reversal.toml", " --set species.gas.count=100 --set 'engine.scalar=\"long double\"'"},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string log =
        make_log("verify-" + std::to_string(k++) + ".ede", c.scene, std::string(c.options) + kSmallRecords);
    const ToolRun r = replay("verify -q " + log, "verify");
    INFO(c.scene << c.options << ": " << r.out << r.err);
    CHECK(r.status == 0);
    CHECK(r.out.find("verified: " + std::to_string(open_reader(log)->total_events()) + " events identical") !=
          std::string::npos);
  }
}

TEST_CASE("ede-replay verify reports the first event a log's scene does not reproduce", "[tool][ede-replay]") {
  // The events of a run with elastic walls behind the header of a run with wall restitution 0.9999999:
  // the re-run of that header's scene agrees until the first wall collision, then differs in velocity.
  // In format version 1: a version 2 chunk is decoded against its header's restitution (its velocities are
  // residuals against the collision rule), so behind another header it decodes to other events, and the
  // splice would test nothing. ede-replay convert writes both runs as version 1.
  const std::string options = " --set species.gas.count=200 --set stop.time=0.3" + kSmallRecords;
  const auto as_v1 = [&](const std::string& log) {
    const std::string v1 = log.substr(0, log.size() - 4) + "-v1.ede";
    std::remove(v1.c_str());
    REQUIRE(replay("convert " + log + " -o " + v1 + " --format-version 1", "verify-convert").status == 0);
    return v1;
  };
  const std::string elastic = as_v1(make_log("verify-elastic.ede", "examples/gas.toml", options));
  const std::string other = as_v1(
      make_log("verify-other.ede", "examples/gas.toml", options + " --set physics.wall_restitution=0.9999999"));
  const auto a = open_reader(elastic), b = open_reader(other);
  const std::string spliced = test_file("verify-spliced.ede");
  write_bytes(spliced,
              read_file(other).substr(0, b->keyframes()[0].offset) +
                  read_file(elastic).substr(a->keyframes()[0].offset, end_of_records(*a) - a->keyframes()[0].offset));
  const ToolRun r = replay("verify -q " + spliced, "verify-spliced");
  INFO(r.out << r.err);
  CHECK(r.status == 1);
  REQUIRE(r.out.find("DIFFERENT: event ") != std::string::npos);
  const std::uint64_t index = number_after(r.out, "DIFFERENT: event ");
  CHECK(r.out.find("differs (vix)") != std::string::npos);
  CHECK(r.out.find("re-run: t = ") != std::string::npos);
  CHECK(r.out.find("log:    t = ") != std::string::npos);
  // It is the log's first wall collision, after identical pair collisions.
  const ToolRun events = replay("events " + elastic + " --to-event " + std::to_string(index), "verify-spliced-events");
  const auto rows = lines(events.out);
  REQUIRE(rows.size() == index + 2);
  CHECK(index > 0);
  CHECK(csv_fields(rows.back())[2] == "wall");
  for (std::size_t k = 1; k + 1 < rows.size(); ++k) CHECK(csv_fields(rows[k])[2] == "pair");
  CHECK(r.out.find(std::to_string(index) + " events before it are identical") != std::string::npos);
}

TEST_CASE("ede-replay verify checks the keyframes a resume would read", "[tool][ede-replay]") {
  // The sampling interval changes no event but the sample count a resumable keyframe stores: the events
  // of one run behind the header of the other verify event by event, and the first keyframe taken at a
  // rebuild does not.
  const std::string options =
      " --set species.gas.count=200 --set stop.time=0.3 --set engine.rebuild_interval=1500" + kSmallRecords;
  // In format version 1, which has no run ids (FORMAT.md "Run id"): a version 2 splice is refused at its
  // first foreign record before any comparison (tested below).
  const auto as_v1 = [&](const std::string& log) {
    const std::string v1 = log.substr(0, log.size() - 4) + "-v1.ede";
    std::remove(v1.c_str());
    REQUIRE(replay("convert " + log + " -o " + v1 + " --format-version 1", "verify-convert").status == 0);
    return v1;
  };
  const std::string a = as_v1(make_log("verify-sample-a.ede", "examples/gas.toml", options + " --set sampling.interval=0.05"));
  const std::string b = as_v1(make_log("verify-sample-b.ede", "examples/gas.toml", options + " --set sampling.interval=0.07"));
  const ToolRun same_events = replay("diff " + a + " " + b, "verify-sample-diff");
  CHECK(same_events.status == 0);
  const auto ra = open_reader(a), rb = open_reader(b);
  REQUIRE(ra->keyframes().size() >= 2);
  REQUIRE(ra->keyframes()[1].resumable);
  const std::string spliced = test_file("verify-sample-spliced.ede");
  write_bytes(spliced,
              read_file(b).substr(0, rb->keyframes()[0].offset) +
                  read_file(a).substr(ra->keyframes()[0].offset, end_of_records(*ra) - ra->keyframes()[0].offset));
  const ToolRun r = replay("verify -q " + spliced, "verify-sample");
  INFO(r.out << r.err);
  CHECK(r.status == 1);
  CHECK(r.out.find("DIFFERENT: keyframe 1 (at event " + std::to_string(ra->keyframes()[1].first_event)) !=
        std::string::npos);
  CHECK(r.out.find("would not resume the run") != std::string::npos);
  // Each log verifies against its own header, keyframes included.
  const ToolRun own = replay("verify -q " + a, "verify-sample-own");
  CHECK(own.status == 0);
  CHECK(own.out.find(std::to_string(ra->keyframes().size()) + " keyframes") != std::string::npos);
}

TEST_CASE("a log spliced from two runs is refused at the first record of the other run", "[tool][ede-replay]") {
  // Records of one run behind the header of another, every checksum valid: each chunk and keyframe repeats
  // the header's run id (FORMAT.md "Run id"), so every reader stops at the first foreign record, naming it.
  const std::string a = make_log("splice-a.ede", "examples/scenes/periodic.toml", kPeriodic + " --set seed=11");
  const std::string b = make_log("splice-b.ede", "examples/scenes/periodic.toml", kPeriodic + " --set seed=12");
  const auto ra = open_reader(a), rb = open_reader(b);
  REQUIRE(ra->header().run_id != 0);
  REQUIRE(rb->header().run_id != 0);
  REQUIRE(ra->header().run_id != rb->header().run_id);
  REQUIRE(ra->keyframes().size() >= 2);
  // b up to its second keyframe (both at the same event: the keyframe interval is fixed), then a's
  // records from its second keyframe on; no index (the reader walks the records, as after a kill).
  REQUIRE(rb->keyframes().size() >= 2);
  REQUIRE(ra->keyframes()[1].first_event == rb->keyframes()[1].first_event);
  const std::uint64_t cut = rb->keyframes()[1].offset, from = ra->keyframes()[1].offset;
  const std::string spliced = test_file("spliced.ede");
  write_bytes(spliced, read_file(b).substr(0, cut) + read_file(a).substr(from, end_of_records(*ra) - from));
  // The state at the end seeks to the last keyframe, a foreign one past the cut, and names it.
  // Messages are wrapped to the terminal's width: compare them as one line.
  const auto flat = [](std::string text) {
    std::string out;
    for (const char c : text)
      if (!(c == '\n' || (c == ' ' && !out.empty() && out.back() == ' '))) out += c;
      else if (out.empty() || out.back() != ' ') out += ' ';
    return out;
  };
  const ToolRun state = replay(spliced + " --at end", "spliced-state");
  INFO(state.out << state.err);
  CHECK(state.status == 1);
  REQUIRE(flat(state.err).find("(keyframe at byte ") != std::string::npos);
  CHECK(number_after(flat(state.err), "(keyframe at byte ") >= cut);
  CHECK(flat(state.err).find("belongs to another run") != std::string::npos);
  // Listing every event refuses it too: replaying from the start, it meets the first chunk after the cut.
  const ToolRun events = replay("events " + spliced, "spliced-events");
  INFO(events.err);
  CHECK(events.status == 1);
  REQUIRE(flat(events.err).find("(chunk at byte ") != std::string::npos);
  CHECK(number_after(flat(events.err), "(chunk at byte ") > cut);
  CHECK(flat(events.err).find("belongs to another run") != std::string::npos);
  const ToolRun verify = replay("verify -q " + spliced, "spliced-verify");
  INFO(verify.out << verify.err);
  CHECK(verify.status == 1);
  CHECK(flat(verify.out + verify.err).find("belongs to another run") != std::string::npos);
  // Before the foreign records the log reads as b: the state at b's first keyframe is exact.
  const std::string t_kf = std::to_string(rb->keyframes()[1].time_first * 0.5);
  const ToolRun early = replay(spliced + " --at " + t_kf, "spliced-early");
  const ToolRun own = replay(b + " --at " + t_kf, "spliced-own");
  CHECK(early.status == 0);
  CHECK(early.out == own.out);
}

TEST_CASE("ede-replay never crashes on a log with a flipped bit in a chunk", "[tool][ede-replay]") {
  const std::string log = make_log("flip.ede", "examples/scenes/periodic.toml", kPeriodic);
  const auto reader = open_reader(log);
  REQUIRE(reader->chunks().size() > 6);
  const ede::LogRecordRef chunk = reader->chunks()[reader->chunks().size() / 2];
  const std::string original = read_file(log);
  const std::string flipped = test_file("flipped.ede");
  for (int quarter = 1; quarter <= 3; ++quarter) {
    std::string bytes = original;
    bytes[chunk.offset + 56 + chunk.payload_size * std::uint64_t(quarter) / 4] ^= 0x10;
    write_bytes(flipped, bytes);
    const std::string after = std::to_string(chunk.first_event + chunk.count);
    for (const std::string& args : {"verify -q " + flipped, flipped + " --event " + after, "events " + flipped,
                                    "info " + flipped, "diff --full " + log + " " + flipped}) {
      const ToolRun r = replay(args, "flipped");
      INFO(args << ": " << r.out << r.err);
      CHECK(r.status == 1);
      CHECK(r.err.find(flipped) != std::string::npos);
    }
  }
}

TEST_CASE("ede-replay diff finds the first differing event by bisection", "[tool][ede-replay]") {
  // Another rebuild interval changes only round-off: the logs agree for a while, then part.
  const std::string a = make_log("diff-a.ede", "examples/scenes/periodic.toml", kPeriodic);
  const std::string b =
      make_log("diff-b.ede", "examples/scenes/periodic.toml", kPeriodic + " --set engine.rebuild_interval=6000");
  const ToolRun r = replay("diff " + a + " " + b, "diff");
  INFO(r.out << r.err);
  REQUIRE(r.status == 1);
  CHECK(r.out.find("note: the rebuild intervals differ") != std::string::npos);
  const std::uint64_t keyframe = number_after(r.out, "last identical keyframe: at event ");
  const std::uint64_t first = number_after(r.out, "first difference at event ");
  CHECK(keyframe > 0);
  CHECK(keyframe <= first);
  CHECK(r.out.find("keyframes common to both logs (bisection)") != std::string::npos);
  // Not a full scan: far fewer events replayed than the logs hold.
  CHECK(number_after(r.out, "identical, skipped), ") < first);
  // The events of both logs agree before the reported index and differ at it.
  const std::string range =
      " --from-event " + std::to_string(first >= 5 ? first - 5 : 0) + " --to-event " + std::to_string(first);
  const auto ra = lines(replay("events " + a + range, "diff-events-a").out);
  const auto rb = lines(replay("events " + b + range, "diff-events-b").out);
  REQUIRE(ra.size() == rb.size());
  REQUIRE(ra.size() >= 2);
  for (std::size_t k = 1; k + 1 < ra.size(); ++k) CHECK(ra[k] == rb[k]);
  CHECK(ra.back() != rb.back());
  CHECK(r.out.find("  A: t = " + csv_fields(ra.back())[1]) != std::string::npos);
  CHECK(r.out.find("  B: t = " + csv_fields(rb.back())[1]) != std::string::npos);
  // --full reaches the same event.
  const ToolRun full = replay("diff --full " + a + " " + b, "diff-full");
  CHECK(full.status == 1);
  CHECK(number_after(full.out, "first difference at event ") == first);
}

TEST_CASE("ede-replay diff: identical logs, a log that ends first, logs that cannot be compared",
          "[tool][ede-replay]") {
  const std::string options = " --set species.gas.count=300" + kSmallRecords;
  const std::string a = make_log("same-a.ede", "examples/scenes/periodic.toml", options + " --set stop.time=0.4");
  const std::string b = make_log("same-b.ede", "examples/scenes/periodic.toml", options + " --set stop.time=0.4");
  const ToolRun same = replay("diff " + a + " " + b, "diff-same");
  INFO(same.out << same.err);
  CHECK(same.status == 0);
  CHECK(same.out.find("identical: " + std::to_string(open_reader(a)->total_events()) + " events") != std::string::npos);
  CHECK(same.out.find("note:") == std::string::npos);

  const std::string longer =
      make_log("same-longer.ede", "examples/scenes/periodic.toml", options + " --set stop.time=0.5");
  const ToolRun ends = replay("diff " + a + " " + longer, "diff-ends");
  INFO(ends.out << ends.err);
  CHECK(ends.status == 1);
  CHECK(ends.out.find("the first " + std::to_string(open_reader(a)->total_events()) +
                      " events are identical; then A ends") != std::string::npos);

  const std::string fewer =
      make_log("same-fewer.ede", "examples/scenes/periodic.toml", " --set species.gas.count=200 --set stop.time=0.1");
  const ToolRun other = replay("diff " + a + " " + fewer, "diff-other");
  CHECK(other.status == 1);
  CHECK(other.err.find("cannot be compared") != std::string::npos);
  CHECK(other.err.find("300 disks") != std::string::npos);
}

TEST_CASE("ede-replay reads a log cut short as far as it goes", "[tool][ede-replay]") {
  const std::string log = make_log("cut.ede", "examples/scenes/periodic.toml", kPeriodic);
  const auto reader = open_reader(log);
  const std::string bytes = read_file(log);
  const std::string cut = test_file("cut-short.ede");

  SECTION("in the middle of a chunk: incomplete, and the state up to the last complete chunk is exact") {
    const ede::LogRecordRef& chunk = reader->chunks()[7];
    write_bytes(cut, bytes.substr(0, chunk.offset + 56 + chunk.payload_size / 2));
    const ToolRun info = replay("info " + cut, "cut-info");
    INFO(info.out << info.err);
    CHECK(info.status == 0);
    CHECK(info.out.find("incomplete: ") != std::string::npos);
    CHECK(number_after(info.out, "events           ") == chunk.first_event);
    // The cut log gives the full log's state at any time up to its last event.
    const ToolRun events = replay("events " + log + " --from-event " + std::to_string(chunk.first_event - 1) +
                                      " --to-event " + std::to_string(chunk.first_event - 1),
                                  "cut-last");
    const std::string t_last = csv_fields(lines(events.out).at(1))[1];
    for (const std::string& at : {std::string("0.01"), t_last}) {
      const ToolRun a = replay(cut + " --at " + at, "cut-at");
      REQUIRE(a.status == 0);
      CHECK(a.out == replay(log + " --at " + at, "cut-at-full").out);
    }
    CHECK(replay(cut + " --at end", "cut-end").out ==
          replay(log + " --event " + std::to_string(chunk.first_event), "cut-ev").out);
    const ToolRun beyond = replay(cut + " --at 0.2", "cut-beyond");
    CHECK(beyond.status == 1);
    CHECK(beyond.err.find("incomplete") != std::string::npos);
    const ToolRun verify = replay("verify -q " + cut, "cut-verify");
    CHECK(verify.status == 0);
    CHECK(verify.out.find("the log is incomplete") != std::string::npos);
  }
  SECTION("just before the trailer: every event is there, the log says it is incomplete") {
    write_bytes(cut, bytes.substr(0, bytes.size() - 32));
    const ToolRun info = replay("info " + cut, "cut-trailer");
    CHECK(info.status == 0);
    CHECK(info.out.find("incomplete: ") != std::string::npos);
    const std::string all = std::to_string(reader->total_events());
    CHECK(number_after(info.out, "events           ") == reader->total_events());
    CHECK(replay(cut + " --at end", "cut-trailer-end").out == replay(log + " --event " + all, "cut-trailer-ev").out);
    CHECK(replay("events " + cut, "cut-trailer-events").out == replay("events " + log, "cut-trailer-events-full").out);
  }
  SECTION("before the first state: unreadable, with a message naming the file") {
    const std::uint64_t header_end = reader->keyframes()[0].offset;
    const std::uint64_t cuts[] = {10, 16 + 30, header_end / 2, header_end + 100};
    for (const std::uint64_t at : cuts) {
      write_bytes(cut, bytes.substr(0, at));
      for (const std::string& args :
           {cut + " --at end", "info " + cut, "events " + cut, "verify -q " + cut, "diff " + log + " " + cut}) {
        const ToolRun r = replay(args, "cut-early");
        INFO("cut at " << at << ": " << args << ": " << r.err);
        CHECK(r.status == 1);
        CHECK(r.err.find("ede-replay: error: ") == 0);
        CHECK(r.err.find(cut) != std::string::npos);
      }
    }
  }
}

TEST_CASE("ede-replay rejects missing files, other files and bad command lines clearly", "[tool][ede-replay]") {
  const std::string missing = test_file("no-such-log.ede");
  const std::string toml = source_path("examples/gas.toml");
  for (const std::string& args :
       {missing + " --at 1", "info " + missing, "events " + missing, "verify " + missing,
        "diff " + missing + " " + missing, toml + " --at 1", "info " + toml, "verify " + toml}) {
    const ToolRun r = replay(args, "bad-file");
    INFO(args << ": " << r.err);
    CHECK(r.status == 1);
    CHECK(r.err.find(args.find(toml) != std::string::npos ? toml : missing) != std::string::npos);
  }
  CHECK(replay("info " + toml, "not-a-log").err.find("not an ede event log") != std::string::npos);

  const std::string log =
      make_log("cli.ede", "examples/scenes/periodic.toml", " --set species.gas.count=100 --set stop.time=0.1");
  for (const std::string& args :
       {std::string(""), log, log + " --at 0.1 --event 3", log + " --no-such-flag", std::string("--no-such-flag"),
        "info " + log + " --no-such-flag", "events " + log + " --from 0.2 --to 0.1",
        "events " + log + " --from 0.1 --from-event 3", "diff " + log}) {
    const ToolRun r = replay(args, "bad-cli");
    INFO(args << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(!r.err.empty());
  }
  CHECK(replay("--help", "help").status == 0);
  CHECK(replay("verify --help", "help-verify").status == 0);
  for (const std::string& args : {log + " --at -1", log + " --at 0.1x", log + " --at 5", log + " --event 100000000"}) {
    const ToolRun r = replay(args, "bad-value");
    INFO(args << ": " << r.err);
    CHECK(r.status == 1);
    CHECK(r.err.find("ede-replay: error: ") == 0);
  }
}

TEST_CASE("ede-replay convert writes version 1 and back, info names the version, diff finds them identical",
          "[tool][ede-replay][convert]") {
  const std::string v2 = make_log("convert-v2.ede", "examples/gas.toml",
                                  " --set species.gas.count=200 --set stop.time=0.3" + kSmallRecords);
  const std::string v1 = test_file("convert-v1.ede"), again = test_file("convert-again.ede");
  std::remove(v1.c_str());
  std::remove(again.c_str());
  const ToolRun to_v1 = replay("convert " + v2 + " -o " + v1 + " --format-version 1", "convert-to-v1");
  INFO(to_v1.out << to_v1.err);
  REQUIRE(to_v1.status == 0);
  CHECK(to_v1.out.find("format version 1") != std::string::npos);
  CHECK(replay("info " + v1, "convert-info-v1").out.find("(format version 1)") != std::string::npos);
  CHECK(replay("info " + v2, "convert-info-v2").out.find("(format version 2)") != std::string::npos);
  CHECK(replay("diff " + v1 + " " + v2, "convert-diff").status == 0);
  REQUIRE(replay("convert " + v1 + " -o " + again, "convert-to-v2").status == 0);
  CHECK(read_file(again) == read_file(v2));  // the same writer, the same bytes
  CHECK(replay("convert " + v2 + " -o " + v2, "convert-same").status == 2);
  CHECK(replay("convert " + v2 + " -o " + again + "x --format-version 4", "convert-bad").status == 2);
}
