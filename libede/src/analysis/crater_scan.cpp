// The scan's bookkeeping (ede/crater.hpp): metrics as columns, means and standard errors per value, and
// where a value sits on a plot's axis.
//
// Sums are plain doubles in run order, so a table depends on the runs and their order alone (a scan stores
// runs by index, never by finishing order). Rejected: block_stats for the error (it wants two values at
// least and adds a correlation a scan of independent seeds does not need).
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "ede/crater.hpp"

namespace ede {

const std::vector<std::string>& crater_metric_names() {
  static const std::vector<std::string> names = {"count",     "depth",        "width",       "area",    "depth_below_mean",
                                                 "deepest_x", "removed_area", "raised_area", "detached"};
  return names;
}

std::vector<double> crater_metric_values(const CraterMeasurement& m) {
  const CraterMetrics& c = m.report.metrics;
  return {double(m.report.displaced.size()), c.depth,          c.width,       c.area,
          c.depth_below_mean,                c.deepest_x,      c.removed_area, c.raised_area,
          double(m.report.after.detached)};
}

MeanAndError mean_and_error(const std::vector<double>& values) {
  MeanAndError s;
  s.n = values.size();
  if (s.n == 0) return s;
  for (const double x : values) s.mean += x;
  s.mean /= double(s.n);
  if (s.n < 2) return s;
  double ss = 0;
  for (const double x : values) ss += (x - s.mean) * (x - s.mean);
  s.error = std::sqrt(ss / double(s.n - 1)) / std::sqrt(double(s.n));
  return s;
}

CraterScanRun crater_scan_run(const CraterMeasurement& m) { return {crater_metric_values(m), m.source, m.time}; }

std::vector<CraterScanGroup> group_crater_scan(const std::vector<CraterScanRun>& runs,
                                               const std::vector<std::size_t>& value_of_run, std::size_t values) {
  std::vector<CraterScanGroup> groups(values);
  std::vector<std::vector<std::vector<double>>> columns(values,
                                                        std::vector<std::vector<double>>(crater_metric_names().size()));
  for (std::size_t k = 0; k < runs.size() && k < value_of_run.size(); ++k) {
    const std::size_t v = value_of_run[k];
    if (v >= values) continue;
    CraterScanGroup& g = groups[v];
    const CraterScanRun& m = runs[k];
    for (std::size_t c = 0; c < m.metrics.size() && c < columns[v].size(); ++c) columns[v][c].push_back(m.metrics[c]);
    ++g.runs;
    g.at_log_end += m.source == CraterTimeSource::LogEnd ? 1 : 0;
    g.requested += m.source == CraterTimeSource::Requested ? 1 : 0;
    g.first_time = std::min(g.first_time, m.time);
    g.last_time = std::max(g.last_time, m.time);
  }
  for (std::size_t v = 0; v < values; ++v)
    for (const std::vector<double>& column : columns[v]) groups[v].metrics.push_back(mean_and_error(column));
  return groups;
}

std::vector<CraterScanGroup> group_crater_scan(const std::vector<CraterMeasurement>& runs,
                                               const std::vector<std::size_t>& value_of_run, std::size_t values) {
  std::vector<CraterScanRun> numbers;
  for (const CraterMeasurement& m : runs) numbers.push_back(crater_scan_run(m));
  return group_crater_scan(numbers, value_of_run, values);
}

double scan_axis_position(const std::string& value) {
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (!value.empty() && end == value.c_str() + value.size() && std::isfinite(v)) return v;
  if (value.size() < 2 || value.front() != '[' || value.back() != ']') return none;
  double sum = 0;
  const std::string inner = value.substr(1, value.size() - 2);
  const char* p = inner.c_str();
  while (*p) {
    const double c = std::strtod(p, &end);
    if (end == p || !std::isfinite(c)) return none;
    sum += c * c;
    p = end;
    while (*p == ' ') ++p;
    if (*p == ',') ++p;
  }
  return std::sqrt(sum);
}

}  // namespace ede
