// ede-stats hist, species, energy and collisions as a user runs them: on logs written by ede-sim from the
// example scenes (shortened with --set), they write CSVs with the documented headers and numbers that
// agree with the log, draw non-empty PNG and SVG figures, and fail clearly on a missing log, an unknown
// species and a time after the end. Scratch files carry the process id (ctest runs cases in parallel).
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "log/log_reader.hpp"
#include "log/log_stats.hpp"
#include "tool_runner.hpp"

using namespace ede::test;

namespace {

std::string scratch(const std::string& name) { return temp_path("stats-" + name); }

// gas.toml (2000 disks, walls) shortened to 10 collisions per disk; --set options appended.
std::string make_log(const std::string& name, const std::string& scene = "examples/gas.toml",
                     const std::string& options = " --set stop.collisions_per_particle=10") {
  return sim_log(source_path(scene), options, scratch(name), "stats-sim-" + name);
}

ToolRun stats(const std::string& args, const std::string& tag) { return run_tool("ede-stats", args, "stats-" + tag); }

// A figure file that exists and looks like its format.
void check_figure(const std::string& path, const std::string& format) {
  const std::string bytes = read_file(path);
  REQUIRE(bytes.size() > 1000);
  if (format == "png") CHECK(bytes.substr(1, 3) == "PNG");
  if (format == "svg") CHECK(bytes.find("<svg") != std::string::npos);
}

}  // namespace

TEST_CASE("ede-stats hist writes the documented CSV and reports kT and KS", "[tool][ede-stats]") {
  const std::string log = make_log("hist.ede");
  const std::string csv = scratch("hist.csv");
  const ToolRun r = stats("hist " + log + " --bins 25 -o " + csv, "hist");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("kT               0.5"));
  CHECK_THAT(r.out, Catch::Contains("KS vs MB         D = "));
  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 26);
  CHECK(rows[0] == "bin_left,bin_right,density,count,mb_density,initial_density,initial_count");
  double integral = 0, mb = 0, initial = 0;
  std::uint64_t count = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const std::vector<std::string> f = csv_fields(rows[k]);
    REQUIRE(f.size() == 7);
    const double width = std::stod(f[1]) - std::stod(f[0]);
    integral += std::stod(f[2]) * width;
    mb += std::stod(f[4]) * width;
    initial += std::stod(f[5]) * width;
    count += std::stoull(f[3]);
  }
  CHECK(count == 2000);
  CHECK(integral == Approx(1).epsilon(1e-12));
  CHECK(initial == Approx(1).epsilon(1e-12));
  CHECK(mb == Approx(1).margin(1e-3));  // the MB tail beyond the largest sampled speed is cut off
}

TEST_CASE("ede-stats hist pools times, warns when they are too close, selects a species", "[tool][ede-stats]") {
  const std::string log = make_log("mix.ede", "examples/scenes/mixture.toml", " --set stop.time=1");
  const ToolRun pooled = stats("hist " + log + " --species heavy --quantity energy --from 0.5 --every 0.1", "pool");
  INFO(pooled.err);
  REQUIRE(pooled.status == 0);
  CHECK_THAT(pooled.out, Catch::Contains("species heavy: 250"));
  CHECK_THAT(pooled.out, Catch::Contains("6 times pooled"));
  CHECK_THAT(pooled.out, Catch::Contains("p is approximate"));
  const ToolRun close = stats("hist " + log + " --from 0.5 --to 0.6 --every 0.001", "close");
  REQUIRE(close.status == 0);
  CHECK_THAT(close.err, Catch::Contains("shorter than 2 mean free times"));
  CHECK(stats("hist " + log + " --from 0.5", "nofrom").status == 2);
}

TEST_CASE("ede-stats hist: --to end is the end of the log, as is leaving --to out", "[tool][ede-stats]") {
  const std::string log = make_log("to-end.ede", "examples/scenes/mixture.toml", " --set stop.time=0.5");
  const std::string a = scratch("to-end-a.csv"), b = scratch("to-end-b.csv");
  const ToolRun with_end = stats("hist " + log + " --from 0.1 --to end --every 0.2 -o " + a, "to-end-a");
  INFO(with_end.err);
  REQUIRE(with_end.status == 0);
  CHECK_THAT(with_end.out, Catch::Contains("t = 0.1 to 0.5 every 0.2 (3 times pooled)"));
  REQUIRE(stats("hist " + log + " --from 0.1 --every 0.2 -o " + b, "to-end-b").status == 0);
  CHECK(read_file(a) == read_file(b));
  const ToolRun late = stats("hist " + log + " --from 0.1 --to 0.7 --every 0.2", "to-late");
  CHECK(late.status == 1);
  CHECK_THAT(late.err, Catch::Contains("--to 0.7 is after the end of the log (t = 0.5); --to end gives the last state"));
}

TEST_CASE("ede-stats hist --plot draws PNG and SVG", "[tool][ede-stats][slow]") {
  const std::string log = make_log("hist-plot.ede");
  for (const std::string format : {"png", "svg"}) {
    const std::string figure = scratch("hist." + format);
    const ToolRun r = stats("hist " + log + " --plot " + figure, "hist-plot-" + format);
    INFO(r.err);
    REQUIRE(r.status == 0);
    check_figure(figure, format);
  }
}

TEST_CASE("ede-stats species: table and CSV per species and for all, over time", "[tool][ede-stats]") {
  const std::string log = make_log("species.ede", "examples/scenes/mixture.toml", " --set stop.time=1");
  const std::string csv = scratch("species.csv");
  const ToolRun r = stats("species " + log + " --every 0.5 -o " + csv, "species");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("heavy"));
  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 1 + 3 * 3);  // t = 0, 0.5, 1; light, heavy, all
  CHECK(rows[0] ==
        "time,species,n,mass_min,mass_max,mean_speed,mean_kinetic_energy,kT,mean_speed_error,"
        "mean_kinetic_energy_error");
  CHECK(rows[1] == "0,light,1000,1,1,1,0.5,0.5,0,0");
  CHECK(csv_fields(rows[2])[6] == "2");  // heavy: m = 4, speed 1
  CHECK(csv_fields(rows[3])[1] == "all");
  CHECK(csv_fields(rows[7])[0] == "1");
  const std::string figure = scratch("species.svg");
  const ToolRun p = stats("species " + log + " --every 0.5 --plot " + figure, "species-plot");
  INFO(p.err);
  REQUIRE(p.status == 0);
  check_figure(figure, "svg");
}

TEST_CASE("ede-stats species --species keeps one species' rows", "[tool][ede-stats]") {
  const std::string log = make_log("species-one.ede", "examples/scenes/mixture.toml", " --set stop.time=0.5");
  const std::string csv = scratch("species-one.csv");
  const ToolRun r = stats("species " + log + " --every 0.25 --species heavy -o " + csv, "species-one");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 1 + 3);  // t = 0, 0.25, 0.5; heavy only
  for (std::size_t k = 1; k < rows.size(); ++k) CHECK(csv_fields(rows[k])[1] == "heavy");
  CHECK(rows[1] == "0,heavy,250,4,4,1,2,2,0,0");
  const ToolRun bad = stats("species " + log + " --species medium", "species-one-bad");
  CHECK(bad.status == 1);
  CHECK_THAT(bad.err, Catch::Contains("the log has no species 'medium'; its species are: light, heavy"));
}

TEST_CASE("ede-stats energy --from --to: the grid within the range, E(0) still at t = 0", "[tool][ede-stats]") {
  const std::string log = make_log("e-range.ede", "examples/gas.toml",
                                   " --set stop.time=0.1 --set physics.restitution=0.9");
  const std::string whole = scratch("e-range-whole.csv"), part = scratch("e-range-part.csv");
  REQUIRE(stats("energy " + log + " --every 0.01 -o " + whole, "e-range-whole").status == 0);
  const ToolRun r = stats("energy " + log + " --from 0.05 --to end --every 0.01 -o " + part, "e-range-part");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("t = 0.05 to 0.1"));
  const std::vector<std::string> all = lines(read_file(whole)), some = lines(read_file(part));
  REQUIRE(all.size() == 1 + 11);
  REQUIRE(some.size() == 1 + 6);
  // The ends of the range are grid times of both (0.05 = 5 x 0.01 and 0.1 = 10 x 0.01 in double): the
  // energy and E/E(0) there agree to the last digit (Haff's tau does not: its calibration point is the
  // first grid time after 2 collisions per disk, which differs between the grids).
  CHECK(csv_fields(some[1])[2] == "0.050000000000000003");
  CHECK(csv_fields(some[1])[2] == csv_fields(all[6])[2]);
  for (const std::size_t column : {std::size_t(3), std::size_t(4)}) {
    CHECK(csv_fields(some[1])[column] == csv_fields(all[6])[column]);
    CHECK(csv_fields(some.back())[column] == csv_fields(all.back())[column]);
  }
}

TEST_CASE("ede-stats energy: one curve per log labelled by restitution, conserved when elastic", "[tool][ede-stats]") {
  const std::string opts = " --set stop.collisions_per_particle=100 --set stop.time=0.1";
  const std::string elastic = make_log("e1.ede", "examples/gas.toml", opts);
  const std::string cooling = make_log("e09.ede", "examples/gas.toml", opts + " --set physics.restitution=0.9");
  const std::string csv = scratch("energy.csv");
  const std::string figure = scratch("energy.png");
  const ToolRun r = stats("energy " + elastic + " " + cooling + " --every 0.001 -o " + csv + " --plot " + figure, "energy");
  INFO(r.err);
  REQUIRE(r.status == 0);
  check_figure(figure, "png");
  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() == 1 + 2 * 101);
  CHECK(rows[0] == "label,restitution,time,kinetic_energy,energy_ratio,mean_kinetic_energy,haff_ratio,mean_kinetic_energy:gas");
  CHECK(csv_fields(rows[1])[0] == "ξ = 1");
  CHECK(csv_fields(rows[102])[0] == "ξ = 0.9");
  for (std::size_t k = 1; k <= 101; ++k) CHECK(std::abs(std::stod(csv_fields(rows[k])[4]) - 1) < 1e-12);
  CHECK(std::stod(csv_fields(rows.back())[4]) < 0.9);
  CHECK(csv_fields(rows.back())[2] == "0.10000000000000001");
  // The default grid: 1/20 of the mean free time.
  const ToolRun d = stats("energy " + elastic, "energy-default");
  REQUIRE(d.status == 0);
  CHECK_THAT(d.out, Catch::Contains("(1/20 of the mean free time"));
  CHECK_THAT(d.out, Catch::Contains("conservation"));
}

TEST_CASE("ede-stats collisions: counts equal the log's, speed classes sum to 100%", "[tool][ede-stats]") {
  const std::string log = make_log("coll.ede");
  const std::string csv = scratch("coll.csv");
  const std::string figure = scratch("coll.svg");
  const ToolRun r = stats("collisions " + log + " -o " + csv + " --plot " + figure, "coll");
  INFO(r.err);
  REQUIRE(r.status == 0);
  check_figure(figure, "svg");
  const std::vector<std::string> rows = lines(read_file(csv));
  REQUIRE(rows.size() >= 101);
  CHECK(rows[0] ==
        "time,pair_collisions,wall_collisions,collisions_per_particle,collision_rate,mean_free_time,"
        "slow_percent,medium_percent,fast_percent,enskog_rate");
  auto reader = ede::LogReader::open(log);
  REQUIRE(reader);
  auto kinds = ede::count_logged_kinds(*reader.value());
  REQUIRE(kinds);
  const std::vector<std::string> last = csv_fields(rows.back());
  CHECK(std::stoull(last[1]) == kinds.value().of(ede::EventKind::Pair));
  CHECK(std::stoull(last[2]) == kinds.value().of(ede::EventKind::Wall));
  CHECK(std::stod(last[3]) == Approx(10).margin(1e-3));
  CHECK(csv_fields(rows[1])[4].empty());  // no rate before the first interval
  CHECK(csv_fields(rows[1])[6] == "0");   // every disk starts at speed 1 = v_ref: all medium
  CHECK(csv_fields(rows[1])[7] == "100");
  for (std::size_t k = 2; k < rows.size(); ++k) {
    const std::vector<std::string> f = csv_fields(rows[k]);
    CHECK(std::stod(f[6]) + std::stod(f[7]) + std::stod(f[8]) == Approx(100).epsilon(1e-13));
    CHECK(std::stod(f[5]) == Approx(1 / std::stod(f[4])));
  }
  CHECK_THAT(r.out, Catch::Contains("mean free time"));
}

TEST_CASE("ede-stats fails clearly on a missing log, an unknown species, a time after the end", "[tool][ede-stats]") {
  const ToolRun missing = stats("hist " + scratch("no-such.ede"), "missing");
  CHECK(missing.status == 1);
  CHECK_THAT(missing.err, Catch::Contains("no-such.ede"));
  for (const std::string cmd : {"species", "energy", "collisions"})
    CHECK(stats(cmd + " " + scratch("no-such.ede"), "missing-" + cmd).status == 1);
  const std::string log = make_log("bad.ede", "examples/scenes/mixture.toml", " --set stop.time=0.2");
  const ToolRun species = stats("hist " + log + " --species medium", "species-bad");
  CHECK(species.status == 1);
  CHECK_THAT(species.err, Catch::Contains("no species 'medium'; its species are: light, heavy"));
  const ToolRun late = stats("hist " + log + " --at 5", "late");
  CHECK(late.status == 1);
  CHECK_THAT(late.err, Catch::Contains("--at 5 is after the end of the log (t = 0.20000000000000001)"));
  CHECK(stats("species " + log + " --at 0.3", "late-species").status == 1);
  CHECK(stats("hist " + log + " --at soon", "nan").status == 1);
  CHECK(stats("hist " + log + " --quantity mass", "quantity").status == 2);
}

TEST_CASE("ede-stats: a bad command line exits with status 2 and CLI11's message, --help with 0", "[tool][ede-stats]") {
  const ToolRun flag = stats("hist " + scratch("any.ede") + " --no-such-flag", "bad-flag");
  CHECK(flag.status == 2);
  CHECK_THAT(flag.err, Catch::Contains("--no-such-flag"));
  CHECK(stats("species", "no-log").status == 2);
  CHECK(stats("", "no-subcommand").status == 2);
  CHECK(stats("histogram " + scratch("any.ede"), "bad-subcommand").status == 2);
  CHECK(stats("--help", "help").status == 0);
  CHECK(stats("energy --help", "help-energy").status == 0);
  for (const std::string command : {"", "hist", "species", "energy", "collisions", "pressure"}) {
    const ToolRun v = stats(command + " --version", "version");
    INFO(command);
    CHECK(v.status == 0);
    CHECK(v.out.rfind("ede-stats" + (command.empty() ? "" : " " + command) + ", ede ", 0) == 0);
  }
  CHECK(stats("energy " + scratch("any.ede") + " --dt 0.1", "old-dt").status == 2);  // now --every
}
