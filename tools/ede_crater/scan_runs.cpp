// The runs of a scan, as a sweep (see scan.hpp): tools/sweep does them, each in its own process, and this
// file says what a scan's run is and how it is measured.
//
// The run's process loads the scene with the --set overrides, KEY=VALUE and seed=S (in that order, so
// its log is byte-identical to `ede-sim SCENE --set ... -o LOG`), runs it, writes <name>.txt (the run's
// summary) and measures its log with measure_log, exactly as `ede-crater LOG` does; the row carries the
// numbers (time, E/E0, the metrics) and the text (the log's status, the time's source) to the table. With
// --no-logs the log is deleted once measured, so a scan's disk use is a few logs, not all. The measuring
// options are the row's `measured_with`: a rerun with other options measures the kept logs again and
// reruns nothing. Rejected: in-process threads (the previous design; a crash of one run ended the scan)
// and ede-sim children (a second process per run to measure, and the ede-sim binary beside this one).
#include <cstdio>

#include "local_pool.hpp"
#include "scan.hpp"

namespace ede::crater_tool {

namespace {

// The sweep's `collect`: the numbers of a scan's row, in its CSV's order.
std::vector<std::string> scan_columns() {
  std::vector<std::string> c = {"time", "energy_fraction"};
  for (const std::string& m : crater_metric_names()) c.push_back(m);
  return c;
}

// Every measuring option, so that rows measured otherwise are measured again, not reused.
std::string measured_with(const MeasureOptions& o) {
  return "ede-crater scan: at=" + o.at + " before=" + o.before + " energy_fraction=" + exact_double(o.energy_fraction) +
         " species=" + o.species + " threshold=" + o.threshold + " bin_width=" + o.bin_width +
         " drop_threshold=" + o.drop_threshold + " link_gap=" + o.link_gap +
         " keep_detached=" + (o.keep_detached ? "1" : "0") + " points=" + std::to_string(o.points);
}

Result<sweep::Measured> measure_run(const sweep::RunToMeasure& run, const MeasureOptions& options) {
  const std::string stem = run.log_path.substr(0, run.log_path.size() - 4);  // without ".ede"
  if (run.fresh)
    if (Status s = write_text_file(stem + ".txt", to_text(run.summary)); !s) return s.error();
  auto m = measure_log(run.log_path, options);
  if (!m) return m.error();
  const CraterMeasurement& c = m.value().crater;
  sweep::Measured out{{c.time, c.energy_fraction}, {m.value().run_status, to_string(c.source)}};
  for (const double v : crater_metric_values(c)) out.values.push_back(v);
  return out;
}

std::string label(const sweep::Sweep& s, const sweep::PlannedRun& r) {
  return s.spec.parameters.front().keys.front() + "=" + r.columns.front() + ", seed " + std::to_string(*r.seed);
}

CraterTimeSource source_of(const std::string& text) {
  for (const CraterTimeSource t : {CraterTimeSource::EnergyFraction, CraterTimeSource::LogEnd, CraterTimeSource::Requested})
    if (text == to_string(t)) return t;
  return CraterTimeSource::LogEnd;
}

}  // namespace

bool run_suspect(const std::string& status) {
  for (const char* word : {"collapse", "stalled", "non-finite", "incomplete"})
    if (status.find(word) != std::string::npos) return true;
  return false;
}

sweep::Sweep scan_sweep(const ScanOptions& opt, const std::vector<std::string>& values) {
  sweep::Sweep s;
  s.spec.path = s.spec.scene_path = opt.scene;
  s.spec.results = s.results = opt.out_dir;
  s.spec.base_overrides = opt.sets;
  sweep::Parameter p{{opt.param}, {}};
  for (const std::string& v : values) p.values.push_back({v});
  s.spec.parameters.push_back(p);
  for (std::uint64_t seed = opt.first_seed; seed < opt.first_seed + opt.seeds; ++seed) s.spec.seeds.push_back(seed);
  s.spec.collect = scan_columns();
  s.runs = sweep::expand_runs(s.spec);
  for (sweep::PlannedRun& r : s.runs) r.name = "v" + std::to_string(r.point) + "-s" + std::to_string(*r.seed);
  s.runs_folder = "";
  s.child_argv = sweep::own_command_line();
  s.tool = "ede-crater";
  s.progress = !opt.quiet;
  s.keep_logs = !opt.no_logs;
  s.measured_with = measured_with(opt.measure);
  s.measure = [options = opt.measure](const sweep::RunToMeasure& run) { return measure_run(run, options); };
  return s;
}

Status check_scan_scenes(const sweep::Sweep& s, const std::string& param) {
  for (const sweep::PlannedRun& r : s.runs) {
    std::vector<Override> overrides;
    for (const std::string& o : r.overrides) overrides.push_back({o});
    if (auto scene = load_scene_file(s.spec.scene_path, overrides); !scene)
      return Error{"with " + param + "=" + r.columns.front() + ": " + scene.error().message};
  }
  return Ok{};
}

Result<std::vector<ScanRow>> run_scan_runs(const sweep::Sweep& s, std::size_t jobs) {
  const std::vector<sweep::RunRow> rows = sweep::run_local(s, jobs);
  std::vector<ScanRow> out;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const sweep::RunRow& row = rows[k];
    const sweep::PlannedRun& r = s.runs[k];
    if (!sweep::final_status(row.status) || row.notes.size() != 2 || row.values.size() != s.spec.collect.size())
      return Error{"the run " + label(s, r) + " failed: " + (row.error.empty() ? row.status : row.error) +
                   (s.keep_logs ? " (the same command again reuses the runs that have a result)" : "")};
    ScanRow sr;
    sr.value = r.point;
    sr.seed = *r.seed;
    sr.log = r.name + ".ede";
    sr.run_status = row.notes[0];
    sr.crater.source = source_of(row.notes[1]);
    sr.crater.time = row.values[0];
    sr.energy_fraction = row.values[1];
    sr.crater.metrics.assign(row.values.begin() + 2, row.values.end());
    out.push_back(std::move(sr));
  }
  return out;
}

}  // namespace ede::crater_tool
