// The scan's bookkeeping on hand-made measurements: metric names and values in CSV order, mean and
// standard error by hand, runs grouped by value with their time sources and ranges, and the axis
// position of typed values.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "ede/crater.hpp"

using namespace ede;

namespace {

CraterMeasurement measurement(double depth, std::size_t displaced, CraterTimeSource source, double time) {
  CraterMeasurement m;
  m.report.metrics.depth = depth;
  m.report.metrics.width = 2 * depth;
  m.report.metrics.area = 0.5;
  m.report.metrics.depth_below_mean = depth + 1;
  m.report.metrics.deepest_x = 0.25;
  m.report.metrics.removed_area = 0.75;
  m.report.metrics.raised_area = 0.125;
  m.report.displaced.assign(displaced, 0);
  m.report.after.detached = 3;
  m.source = source;
  m.time = time;
  return m;
}

}  // namespace

TEST_CASE("crater metrics: names and values in the scan CSV's order", "[analysis][crater]") {
  CHECK(crater_metric_names() == std::vector<std::string>{"count", "depth", "width", "area", "depth_below_mean",
                                                          "deepest_x", "removed_area", "raised_area", "detached"});
  CHECK(crater_metric_values(measurement(0.5, 7, CraterTimeSource::LogEnd, 1)) ==
        std::vector<double>{7, 0.5, 1, 0.5, 1.5, 0.25, 0.75, 0.125, 3});
}

TEST_CASE("mean_and_error: the mean and s / sqrt(n), none below two values", "[analysis][crater]") {
  const MeanAndError m = mean_and_error({1, 2, 3, 4});
  CHECK(m.n == 4);
  CHECK(m.mean == 2.5);
  CHECK(m.error == std::sqrt(5.0 / 3) / 2);  // sum of squares 5, n - 1 = 3
  const MeanAndError one = mean_and_error({7});
  CHECK(one.mean == 7);
  CHECK(std::isnan(one.error));
  CHECK(mean_and_error({}).n == 0);
}

TEST_CASE("group_crater_scan: runs by value, in run order, with their times", "[analysis][crater]") {
  const std::vector<CraterMeasurement> runs = {
      measurement(1, 10, CraterTimeSource::EnergyFraction, 0.2), measurement(2, 20, CraterTimeSource::LogEnd, 0.4),
      measurement(3, 30, CraterTimeSource::EnergyFraction, 0.3), measurement(5, 50, CraterTimeSource::Requested, 0.5)};
  const std::vector<CraterScanGroup> g = group_crater_scan(runs, {0, 1, 0, 1}, 3);
  REQUIRE(g.size() == 3);
  CHECK(g[0].runs == 2);
  CHECK(g[0].metrics[0].mean == 20);  // count: (10 + 30) / 2
  CHECK(g[0].metrics[1].mean == 2);   // depth
  CHECK(g[0].metrics[1].error == 1);  // s = sqrt(2), / sqrt(2)
  CHECK(g[0].at_log_end == 0);
  CHECK(g[0].first_time == 0.2);
  CHECK(g[0].last_time == 0.3);
  CHECK(g[1].at_log_end == 1);
  CHECK(g[1].requested == 1);
  CHECK(g[1].metrics[1].mean == 3.5);
  CHECK(g[2].runs == 0);
  CHECK(g[2].metrics.size() == crater_metric_names().size());
}

TEST_CASE("group_crater_scan: the runs' numbers alone give the same groups", "[analysis][crater]") {
  const std::vector<CraterMeasurement> runs = {
      measurement(1, 10, CraterTimeSource::EnergyFraction, 0.2), measurement(2, 20, CraterTimeSource::LogEnd, 0.4),
      measurement(3, 30, CraterTimeSource::EnergyFraction, 0.3), measurement(5, 50, CraterTimeSource::Requested, 0.5)};
  std::vector<CraterScanRun> numbers;
  for (const CraterMeasurement& m : runs) numbers.push_back(crater_scan_run(m));
  CHECK(numbers[1].metrics == crater_metric_values(runs[1]));
  CHECK(numbers[1].source == CraterTimeSource::LogEnd);
  CHECK(numbers[1].time == 0.4);
  const std::vector<CraterScanGroup> a = group_crater_scan(runs, {0, 1, 0, 1}, 2);
  const std::vector<CraterScanGroup> b = group_crater_scan(numbers, {0, 1, 0, 1}, 2);
  REQUIRE(b.size() == 2);
  for (std::size_t v = 0; v < 2; ++v) {
    CHECK(b[v].runs == a[v].runs);
    CHECK(b[v].at_log_end == a[v].at_log_end);
    CHECK(b[v].requested == a[v].requested);
    CHECK(b[v].first_time == a[v].first_time);
    CHECK(b[v].last_time == a[v].last_time);
    REQUIRE(b[v].metrics.size() == a[v].metrics.size());
    for (std::size_t c = 0; c < a[v].metrics.size(); ++c) {
      CHECK(b[v].metrics[c].mean == a[v].metrics[c].mean);
      CHECK((b[v].metrics[c].error == a[v].metrics[c].error ||
             (std::isnan(b[v].metrics[c].error) && std::isnan(a[v].metrics[c].error))));
    }
  }
}

TEST_CASE("scan_axis_position: a number, a vector's length, else NaN", "[analysis][crater]") {
  CHECK(scan_axis_position("25") == 25);
  CHECK(scan_axis_position("1e-3") == 1e-3);
  CHECK(scan_axis_position("[3,4]") == 5);
  CHECK(scan_axis_position("[0, -4]") == 4);
  CHECK(std::isnan(scan_axis_position("\"float\"")));
  CHECK(std::isnan(scan_axis_position("[1,x]")));
  CHECK(std::isnan(scan_axis_position("")));
}
