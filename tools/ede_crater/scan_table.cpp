// The results of a scan: the per-run and per-value CSV files and the table on stdout (see scan.hpp).
//
// The numbers are the library's (crater_metric_values in each run's process, group_crater_scan,
// scan_axis_position); this file lays them out. The per-value table shows one metric, with when its runs
// were measured, so a scan that mixes the energy criterion with the log's end says so. Rejected: printing every metric in the table
// (nine columns of means and errors do not read; the CSV has them).
#include <cmath>

#include "scan.hpp"

namespace ede::crater_tool {

namespace {


std::string axis_cell(const std::string& value) { return exact_cell(scan_axis_position(value)); }

std::vector<std::size_t> value_of_runs(const ScanResults& r) {
  std::vector<std::size_t> v;
  for (const ScanRow& row : r.rows) v.push_back(row.value);
  return v;
}

std::vector<CraterScanGroup> groups_of(const ScanResults& r) {
  std::vector<CraterScanRun> runs;
  for (const ScanRow& row : r.rows) runs.push_back(row.crater);
  return group_crater_scan(runs, value_of_runs(r), r.values.size());
}

// "t = a" or "t = a-b": the times the runs of one value were measured at.
std::string time_range(double lo, double hi) { return "t = " + brief(lo) + (lo == hi ? "" : "-" + brief(hi)); }

// Runs of value v whose end makes their crater doubtful (run_suspect).
std::size_t suspect_runs(const ScanResults& r, std::size_t v) {
  std::size_t n = 0;
  for (const ScanRow& row : r.rows) n += row.value == v && run_suspect(row.run_status);
  return n;
}

}  // namespace

Status write_scan_csv(const ScanResults& r, const std::string& per_run, const std::string& aggregate) {
  const std::vector<std::string>& names = crater_metric_names();
  std::string s = "value,x,seed,log,run_status,suspect,time,time_source,energy_fraction";
  for (const std::string& m : names) s += "," + m;
  s += "\n";
  for (const ScanRow& row : r.rows) {
    s += csv_field(r.values[row.value]) + "," + axis_cell(r.values[row.value]) + "," + std::to_string(row.seed) + "," +
         csv_field(row.log) + "," + csv_field(row.run_status) + "," + (run_suspect(row.run_status) ? "1" : "0") + "," +
         exact_double(row.crater.time) + "," + to_string(row.crater.source) + "," + exact_double(row.energy_fraction);
    for (const double v : row.crater.metrics) s += "," + exact_double(v);
    s += "\n";
  }
  if (Status w = write_text_file(per_run, s); !w) return w;

  std::string a = "value,x,n,n_suspect";
  for (const std::string& m : names) a += "," + m + "_mean," + m + "_stderr";
  a += "\n";
  const std::vector<CraterScanGroup> groups = groups_of(r);
  for (std::size_t v = 0; v < r.values.size(); ++v) {
    a += csv_field(r.values[v]) + "," + axis_cell(r.values[v]) + "," + std::to_string(groups[v].runs) + "," +
         std::to_string(suspect_runs(r, v));
    for (const MeanAndError& m : groups[v].metrics) a += "," + exact_double(m.mean) + "," + exact_cell(m.error);
    a += "\n";
  }
  return write_text_file(aggregate, a);
}

void print_scan_table(const ScanResults& r, const std::string& param, std::size_t metric) {
  std::printf("%-24s %4s  %s (mean +- standard error)   measured at\n", param.c_str(), "n",
              crater_metric_names()[metric].c_str());
  const std::vector<CraterScanGroup> groups = groups_of(r);
  for (std::size_t v = 0; v < r.values.size(); ++v) {
    const CraterScanGroup& g = groups[v];
    const MeanAndError& m = g.metrics[metric];
    const std::string when = g.requested    ? "the time asked for"
                             : g.at_log_end == 0 ? "energy fraction reached"
                                                 : std::to_string(g.at_log_end) + " of " + std::to_string(g.runs) +
                                                       " at the log's end";
    const std::size_t suspect = suspect_runs(r, v);
    std::printf("%-24s %4zu  %-12s +- %-12s  %s, %s%s\n", r.values[v].c_str(), m.n, brief(m.mean).c_str(),
                std::isnan(m.error) ? "-" : brief(m.error).c_str(), when.c_str(),
                time_range(g.first_time, g.last_time).c_str(),
                suspect ? ("  !! " + std::to_string(suspect) + " run(s) suspect").c_str() : "");
  }
  std::size_t total = 0;
  for (std::size_t v = 0; v < r.values.size(); ++v) total += suspect_runs(r, v);
  if (total)
    std::printf("!! %zu run(s) ended in inelastic collapse, with a non-finite number or unfinished (scan.csv: suspect, "
                "run_status); their craters are not comparable. Fix: enable the TC model (--set physics.tc=1e-6) "
                "and scan again.\n",
                total);
}

}  // namespace ede::crater_tool
