// ede-crater as a user runs it: a small crater log measured and written as CSV and a figure, the choice of
// time, scans that are deterministic and independent of --jobs, and clear errors on bad input.
//
// Logs come from ede-sim on examples/crater.toml shrunk with --set: 200-400 bed disks of radius ~0.014
// and a projectile of radius 0.07 (5 bed radii), which run in well under a second.
#include <catch2/catch.hpp>

#include "text_support.hpp"
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tool_runner.hpp"

using namespace ede::test;

namespace {

const std::string kScene = source_path("examples/crater.toml");
const std::string kSmall = " --set species.projectile.radius=0.07";
// The tables of `ede-crater scan` before it became a sweep (tests/tools/fixtures/crater-scan/README.md).
const std::string kFixtures = source_path("tests/tools/fixtures/crater-scan");

// A scan's stdout without its last line ("wrote DIR/scan.csv ...", which names the output folder).
std::string without_wrote_line(const std::string& out) {
  const std::size_t last = out.rfind("wrote ");
  return last == std::string::npos ? out : out.substr(0, last);
}

std::string make_crater_log(const std::string& name, const std::string& options) {
  return sim_log(kScene, kSmall + options, temp_path(name), "crater-sim-" + name);
}

ToolRun crater(const std::string& args, const std::string& tag) { return run_tool("ede-crater", args, "crater-" + tag); }


}  // namespace

TEST_CASE("ede-crater: measures a small crater log, writes the profiles, the energy curve and a figure",
          "[tool][ede-crater]") {
  const std::string log = make_crater_log("crater-small.ede", " --set species.bed.count=400");
  const std::string csv = temp_path("crater-small.csv"), png = temp_path("crater-small.png");
  const ToolRun r = crater(log + " -o " + csv + " --plot " + png, "small");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  for (const char* line : {"bed               400 disks: the species named 'bed'", "the first event after which at most 0.1",
                           "depth             ", "width             ", "area              ", "displaced         "})
    CHECK(contains(r.out, line));

  const std::vector<std::string> profile = lines(read_file(csv));
  REQUIRE(profile.size() == 36);  // header + 35 bins: 1 / (2 x 0.0141) = 35.4
  CHECK(profile[0] == "x_left,x_right,x,h_before,h_after,drop,in_crater,disks_before,disks_after");
  std::size_t in_crater = 0;
  for (std::size_t k = 1; k < profile.size(); ++k) in_crater += contains(profile[k], ",1,") ? 1 : 0;
  CHECK(in_crater > 0);
  const std::string energy = temp_path("crater-small-energy.csv");
  const std::vector<std::string> curve = lines(read_file(energy));
  REQUIRE(curve.size() == 502);
  CHECK(curve[0] == "t,energy_fraction");
  CHECK(curve[1] == "0,1");
  CHECK(read_file(png).substr(1, 3) == "PNG");
}

TEST_CASE("ede-crater: the time of the measurement: energy fraction, --at, --at end, never reached",
          "[tool][ede-crater]") {
  const std::string log = make_crater_log("crater-times.ede", " --set species.bed.count=200");
  const ToolRun at = crater(log + " --at 0.1", "at");
  REQUIRE(at.status == 0);
  CHECK(contains(at.out, "measured at       t = 0.10000000000000001, after"));
  CHECK(contains(at.out, "the time asked for"));
  const ToolRun end = crater(log + " --at end", "end");
  REQUIRE(end.status == 0);
  CHECK(contains(end.out, "the log's end, as asked"));
  const ToolRun never = crater(log + " --energy-fraction 0.01", "never");
  REQUIRE(never.status == 0);
  CHECK(contains(never.out, "the log's end: the kinetic energy never fell to 0.01"));
  CHECK(contains(never.out, "never reached in this log"));
  const ToolRun half = crater(log + " --energy-fraction 0.5 --threshold 0.001 --drop-threshold 2r", "half");
  REQUIRE(half.status == 0);
  CHECK(contains(half.out, "at most 0.5 of the initial kinetic energy"));
  CHECK(contains(half.out, "moved by more than 0.001 ("));
}

TEST_CASE("ede-crater: a crater under gravity is measured at a time asked for, against a settled bed (--before)",
          "[tool][ede-crater]") {
  // examples/crater-gravity.toml with a thin bed (200 disks) and a short run: the bed settles, the
  // projectile dropped from y = 1.8 reaches it at t ~ 0.55.
  const std::string log =
      sim_log(source_path("examples/crater-gravity.toml"), " --set species.bed.count=200 --set stop.time=0.7",
              temp_path("crater-gravity.ede"), "crater-sim-gravity");
  const ToolRun no_time = crater(log, "gravity-no-time");
  CHECK(no_time.status == 1);
  CHECK(contains(no_time.err, "the run is under gravity"));
  CHECK(contains(no_time.err, "measure at a time with --at T (or --at end)"));

  const std::string csv = temp_path("crater-gravity.csv"), png = temp_path("crater-gravity.png");
  std::filesystem::remove(temp_path("crater-gravity-energy.csv"));
  const ToolRun r = crater(log + " --before 0.5 --at end -o " + csv + " --plot " + png, "gravity");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(contains(r.out, "measured at       t = 0.69999999999999996, after"));
  CHECK(contains(r.out, "compared with     the bed at t = 0.5 (--before)"));
  CHECK(contains(r.out, "no fraction under gravity"));
  CHECK(lines(read_file(csv)).size() > 10);
  CHECK_FALSE(std::filesystem::exists(temp_path("crater-gravity-energy.csv")));  // no curve to write
  CHECK(read_file(png).substr(1, 3) == "PNG");

  // Against the loose initial bed, the settling alone reads as a "crater" across the whole box.
  const ToolRun loose = crater(log + " --at end", "gravity-loose");
  REQUIRE(loose.status == 0);
  CHECK_FALSE(contains(loose.out, "compared with"));

  const ToolRun reversed = crater(log + " --before 0.6 --at 0.55", "gravity-reversed");
  CHECK(reversed.status == 1);
  CHECK(contains(reversed.err, "before the reference state (--before 0.6): measure later"));
  const ToolRun word = crater(log + " --before soon --at end", "gravity-word");
  CHECK(word.status == 1);
  CHECK(contains(word.err, "--before 'soon' is not a time"));
}

TEST_CASE("ede-crater scan: deterministic CSV, the same for --jobs 1 and 2", "[tool][ede-crater]") {
  const std::string common = "scan " + kScene + " --param species.projectile.mass --values 5,25 --seeds 2 -q" +
                             kSmall + " --set species.bed.count=200 --out-dir ";
  const std::string a = temp_path("crater-scan-a"), b = temp_path("crater-scan-b"), c = temp_path("crater-scan-c");
  const ToolRun ra = crater(common + a + " --jobs 2", "scan-a");
  INFO(ra.out << ra.err);
  REQUIRE(ra.status == 0);
  REQUIRE(crater(common + b + " --jobs 2", "scan-b").status == 0);
  REQUIRE(crater(common + c + " -j 1", "scan-c").status == 0);

  const std::string runs = read_file(a + "/scan.csv"), aggregate = read_file(a + "/scan-aggregate.csv");
  // The tables and the printed table are those of the scan before it became a sweep (its own threads).
  CHECK(runs == read_file(kFixtures + "/mass/scan.csv"));
  CHECK(aggregate == read_file(kFixtures + "/mass/scan-aggregate.csv"));
  CHECK(without_wrote_line(ra.out) == without_wrote_line(read_file(kFixtures + "/mass/stdout.txt")));
  CHECK(runs == read_file(b + "/scan.csv"));
  CHECK(runs == read_file(c + "/scan.csv"));
  CHECK(aggregate == read_file(b + "/scan-aggregate.csv"));
  CHECK(aggregate == read_file(c + "/scan-aggregate.csv"));

  const std::vector<std::string> rows = lines(runs);
  REQUIRE(rows.size() == 5);
  CHECK(rows[0].rfind("value,x,seed,log,run_status,suspect,time,time_source,energy_fraction,count,depth,width,area", 0) == 0);
  CHECK(rows[1].rfind("5,5,1,v0-s1.ede,reached stop.energy_fraction,0,", 0) == 0);
  CHECK(rows[2].rfind("5,5,2,v0-s2.ede,", 0) == 0);
  CHECK(rows[3].rfind("25,25,1,v1-s1.ede,", 0) == 0);
  CHECK(rows[4].rfind("25,25,2,v1-s2.ede,", 0) == 0);
  const std::vector<std::string> agg = lines(aggregate);
  REQUIRE(agg.size() == 3);
  CHECK(agg[1].rfind("5,5,2,0,", 0) == 0);  // n = 2 runs, none suspect

  // Each run's numbers are exactly what measuring its log alone gives.
  const ToolRun one = crater(a + "/v1-s2.ede", "scan-one");
  REQUIRE(one.status == 0);
  std::vector<std::string> f;
  std::istringstream row(rows[4]);
  for (std::string field; std::getline(row, field, ',');) f.push_back(field);
  REQUIRE(f.size() > 9);
  CHECK(contains(one.out, "measured at       t = " + f[6] + ", after"));
  CHECK(contains(one.out, "displaced         " + f[9] + " of 200 bed disks"));
  CHECK(std::filesystem::exists(a + "/v1-s2.txt"));

  // The same scan again reuses every run; other measuring options measure the kept logs again, run none.
  const std::string log_before = read_file(a + "/v0-s1.ede");
  const ToolRun again = crater(common + a + " --jobs 2", "scan-again");  // -q is in common: no progress lines
  REQUIRE(again.status == 0);
  CHECK(read_file(a + "/scan.csv") == runs);
  const ToolRun loud = crater("scan " + kScene + " --param species.projectile.mass --values 5,25 --seeds 2" + kSmall +
                                  " --set species.bed.count=200 --out-dir " + a,
                              "scan-loud");
  REQUIRE(loud.status == 0);
  CHECK(contains(loud.err, "ede-crater: 4/4 "));
  CHECK(contains(loud.err, " ok (reused)"));
  CHECK_FALSE(contains(loud.err, " s)"));  // no run's process ran
  const ToolRun other = crater(common + a + " --threshold 1r", "scan-threshold");
  REQUIRE(other.status == 0);
  CHECK(read_file(a + "/scan.csv") != runs);  // counted with another threshold
  CHECK(read_file(a + "/v0-s1.ede") == log_before);
}

TEST_CASE("ede-crater scan: each run's log is the one ede-sim writes for the same overrides", "[tool][ede-crater]") {
  const std::string dir = temp_path("crater-scan-same");
  const ToolRun r = crater("scan " + kScene + " --param physics.restitution --values 0.5 --first-seed 3 -q" + kSmall +
                               " --set species.bed.count=150 --set stop.time=0.05 --out-dir " + dir,
                           "scan-same");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const std::string alone = sim_log(kScene,
                                    kSmall + " --set species.bed.count=150 --set stop.time=0.05 --set "
                                             "physics.restitution=0.5 --set seed=3",
                                    temp_path("crater-scan-same-alone.ede"), "crater-sim-same");
  const std::string in_scan = read_file(dir + "/v0-s3.ede");
  REQUIRE(in_scan.size() > 1000);
  CHECK(in_scan == read_file(alone));
  CHECK(read_file(dir + "/v0-s3.txt").find("ended            ") != std::string::npos);  // the run's summary
}

TEST_CASE("ede-crater scan: vector values, and runs that end before the energy fraction", "[tool][ede-crater]") {
  const std::string dir = temp_path("crater-scan-xi");
  const ToolRun r = crater("scan " + kScene + " --param species.projectile.velocity.vector --values '[0,-3],[0, -4]'" +
                               kSmall + " --set species.bed.count=200 --set stop.time=0.1 -q --jobs 2 --out-dir " + dir,
                           "scan-vector");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(contains(r.out, "1 of 1 at the log's end, t = 0.1"));
  const std::vector<std::string> rows = lines(read_file(dir + "/scan.csv"));
  REQUIRE(rows.size() == 3);
  CHECK(rows[1].rfind("\"[0,-3]\",3,1,v0-s1.ede,reached stop.time,0,0.10000000000000001,log_end,", 0) == 0);
  CHECK(rows[2].rfind("\"[0, -4]\",4,1,", 0) == 0);  // the value as typed
}

TEST_CASE("ede-crater scan --no-logs keeps the results and no log, and collapse is marked", "[tool][ede-crater][slow]") {
  const std::string dir = temp_path("crater-scan-nologs");
  const ToolRun r = crater("scan " + kScene + " --param physics.tc --values 0,1e-6 --no-logs -q" + kSmall +
                               " --set species.bed.count=300 --set species.projectile.mass=125 --out-dir " + dir,
                           "scan-nologs");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(!std::filesystem::exists(dir + "/v0-s1.ede"));
  CHECK(!std::filesystem::exists(dir + "/v1-s1.ede"));
  CHECK(std::filesystem::exists(dir + "/v0-s1.txt"));
  CHECK(read_file(dir + "/scan.csv") == read_file(kFixtures + "/tc/scan.csv"));
  CHECK(read_file(dir + "/scan-aggregate.csv") == read_file(kFixtures + "/tc/scan-aggregate.csv"));
  CHECK(without_wrote_line(r.out) == without_wrote_line(read_file(kFixtures + "/tc/stdout.txt")));
  const std::vector<std::string> rows = lines(read_file(dir + "/scan.csv"));
  REQUIRE(rows.size() == 3);
  // Whether tc = 0 collapses in so small a bed is the physics' business; the mark must follow the status.
  for (const std::string& row : {rows[1], rows[2]}) {
    const bool collapsed = row.find("collapse") != std::string::npos || row.find("stalled") != std::string::npos;
    CHECK(row.find(collapsed ? ",1," : ",0,") != std::string::npos);
    if (collapsed) CHECK(contains(r.out, "!! "));
  }
}

TEST_CASE("ede-crater: bad input gives one clear message", "[tool][ede-crater]") {
  const ToolRun missing = crater(temp_path("no-such-log.ede"), "missing");
  CHECK(missing.status == 1);
  CHECK(contains(missing.err, "ede-crater: error: cannot open"));

  const std::string log = make_crater_log("crater-bad.ede", " --set species.bed.count=200");
  const ToolRun species = crater(log + " --species sand", "species");
  CHECK(species.status == 1);
  CHECK(contains(species.err, "there is no species 'sand' in the log; it has 'bed' (200 disks), 'projectile' (1 disk)"));

  const ToolRun threshold = crater(log + " --threshold 5q", "threshold");
  CHECK(threshold.status == 2);
  CHECK(contains(threshold.err, "--threshold '5q' is not a length"));
  const ToolRun late = crater(log + " --at 100", "late");
  CHECK(late.status == 1);
  CHECK(contains(late.err, "after the end of the log"));

  const ToolRun key = crater("scan " + kScene + " --param species.projectile.mas --values 1,2 --out-dir " +
                                 temp_path("crater-scan-bad"),
                             "key");
  CHECK(key.status == 1);
  CHECK(contains(key.err, "species[1].mas (species 'projectile'): unknown key; did you mean 'mass'?"));
  CHECK_FALSE(std::filesystem::exists(temp_path("crater-scan-bad")));  // nothing ran
  const ToolRun value = crater("scan " + kScene + " --param physics.restitution --values 0.5,2 --out-dir " +
                                   temp_path("crater-scan-bad"),
                               "value");
  CHECK(value.status == 1);
  CHECK(contains(value.err, "physics.restitution: must be in [0, 1], got 2"));
  const ToolRun empty = crater("scan " + kScene + " --param physics.restitution --values 0.5,,0.7", "empty");
  CHECK(empty.status == 2);
  CHECK(contains(empty.err, "empty value"));
  const ToolRun metric = crater("scan " + kScene + " --param physics.restitution --values 0.5 --metric depht", "metric");
  CHECK(metric.status == 2);
}

TEST_CASE("ede-crater: a bad command line exits with status 2 and CLI11's message, --help with 0",
          "[tool][ede-crater]") {
  const std::string log = temp_path("crater-any.ede");
  const ToolRun flag = crater(log + " --no-such-flag", "bad-flag");
  CHECK(flag.status == 2);
  CHECK(contains(flag.err, "--no-such-flag"));
  CHECK(crater("scan " + kScene + " --no-such-flag", "bad-scan-flag").status == 2);
  CHECK(crater(log + " --energy-fraction 2", "bad-fraction").status == 2);
  CHECK(crater("", "nothing").status == 2);
  CHECK(crater("--help", "help").status == 0);
  CHECK(crater("scan --help", "help-scan").status == 0);
  for (const std::string command : {"--version", "measure --version", "scan --version"}) {
    const ToolRun v = crater(command, "version");
    CHECK(v.status == 0);
    CHECK(v.out.rfind("ede-crater", 0) == 0);
  }
}
