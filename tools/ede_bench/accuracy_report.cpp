// The accuracy study's tables and figure; see accuracy_report.hpp. Every number printed comes from the
// rows; the CSV keeps 6 significant digits, the Markdown 2 or 3 (the errors span 30 orders of magnitude,
// their leading digits are what a reader compares). The figure is drawn by matplotlib from the CSV only,
// so it can be redrawn without rerunning the study. Rejected: drawing in C++ (the project's figures all
// come from tools/plot with one style).
#include "accuracy_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "output_file.hpp"
#include "plot_runner.hpp"
#include "study/measurement.hpp"

namespace ede::bench {

using namespace study;

namespace {

std::string csv_number(double v) { return fmt(v, 6); }

std::string name_of(Precision p) { return p == Precision::LongDouble ? "long_double" : precision_name(p); }
std::string contact_of(ContactRoot c) { return c == ContactRoot::Textbook ? "textbook" : "stable"; }

// ns/event of the double, stable-root row of the same scene.
double double_ns(const std::vector<EngineRow>& rows, const std::string& scene) {
  for (const EngineRow& r : rows)
    if (r.scene == scene && r.setting.precision == Precision::Double && r.setting.contact == ContactRoot::Stable)
      return r.ns_per_event;
  return 0;
}

std::string divergence_text(double collisions, const StudyPlan& plan) {
  return collisions < 0 ? "> " + fmt(plan.divergence_cap) : fmt(collisions);
}

std::string engine_csv(const StudyResults& res) {
  std::ostringstream o;
  o << "scene,precision,contact,disks,events,collisions,ns_per_event,ns_ratio_to_double,energy_drift,"
       "energy_drift_max,largest_overlap,largest_overlap_snapshot,timing_events,repeats_agree,log_bytes_per_event";
  for (const double c : res.plan.reversal_collisions) o << ",reversal_rms_c" << fmt(c);
  for (const double c : res.plan.reversal_collisions) o << ",reversal_returned_c" << fmt(c);
  o << ",free_path,divergence_path_collisions,divergence_diameter_collisions,divergence_cap,failure\n";
  for (const EngineRow& r : res.engine) {
    const double base = double_ns(res.engine, r.scene);
    o << r.scene << "," << name_of(r.setting.precision) << ","
      << contact_of(r.setting.contact) << "," << r.disks << "," << r.events << "," << r.collisions << ","
      << csv_number(r.ns_per_event) << "," << csv_number(base > 0 ? r.ns_per_event / base : 0) << ","
      << csv_number(r.drift) << "," << csv_number(r.drift_max) << "," << csv_number(r.overlap) << ","
      << csv_number(r.overlap_snapshot) << "," << r.timing_events << "," << (r.repeats_agree ? 1 : 0) << "," << (r.log_bytes_per_event < 0 ? "" : csv_number(r.log_bytes_per_event));
    for (std::size_t k = 0; k < res.plan.reversal_collisions.size(); ++k)
      o << "," << (k < r.reversal_rms.size() ? csv_number(r.reversal_rms[k]) : "");
    for (std::size_t k = 0; k < res.plan.reversal_collisions.size(); ++k)
      o << "," << (k < r.reversal_returned.size() ? csv_number(r.reversal_returned[k]) : "");
    o << "," << csv_number(r.free_path) << "," << csv_number(r.divergence_path) << ","
      << csv_number(r.divergence_diameter) << "," << csv_number(res.plan.divergence_cap) << ",\"" << r.failure
      << "\"\n";
  }
  return o.str();
}

std::string stepped_csv(const SteppedStudy& st) {
  std::ostringstream o;
  o << "method,dt_over_tau,dt,step_over_diameter,cpu_seconds,cpu_ratio,pair_collisions,rate_error,energy_drift,"
       "largest_overlap,cooling_cpu_seconds,cooling_cpu_ratio,cooling_error,tau,tau_cooling,diameter,v_rms,span,"
       "cooling_span,rate_stderr,failure\n";
  for (const SteppedRow& r : st.rows)
    o << r.method << "," << csv_number(r.dt_over_tau) << "," << csv_number(r.dt) << ","
      << csv_number(r.step_over_diameter) << "," << csv_number(r.cpu_seconds) << "," << csv_number(r.cpu_ratio)
      << "," << r.pair_collisions << "," << csv_number(r.rate_error) << "," << csv_number(r.energy_drift) << ","
      << csv_number(r.overlap) << "," << csv_number(r.cooling_cpu_seconds) << "," << csv_number(r.cooling_cpu_ratio)
      << "," << csv_number(r.cooling_error) << "," << csv_number(st.tau) << "," << csv_number(st.tau_cooling) << ","
      << csv_number(st.diameter) << "," << csv_number(st.v_rms) << "," << csv_number(st.span) << ","
      << csv_number(st.cooling_span) << "," << csv_number(st.rate_stderr) << ",\"" << r.failure << "\"\n";
  return o.str();
}

std::string log_csv(const std::vector<LogRow>& rows) {
  std::ostringstream o;
  o << "configuration,keyframe_interval,automatic_rebuilds,ns_per_event,ratio_to_off,bytes_per_event,"
       "keyframe_share,seek_median_seconds,seek_max_seconds,failure\n";
  for (const LogRow& r : rows)
    o << r.label << "," << r.interval << "," << (r.rebuilds ? 1 : 0) << "," << csv_number(r.ns_per_event)
      << "," << csv_number(r.ratio_to_off) << "," << csv_number(r.bytes_per_event) << ","
      << csv_number(r.keyframe_share) << "," << csv_number(r.seek_median) << "," << csv_number(r.seek_max) << ",\""
      << r.failure << "\"\n";
  return o.str();
}

std::string slash_list(const std::vector<double>& v, int digits) {
  std::string s;
  for (std::size_t k = 0; k < v.size(); ++k) s += (k ? " / " : "") + fmt(v[k], digits);
  return s;
}

void engine_tables(std::ostringstream& o, const StudyResults& res) {
  const StudyPlan& plan = res.plan;
  const std::string cs = slash_list(plan.reversal_collisions, 3);
  for (const std::string& scene : engine_scenes()) {
    o << "### " << scene << " (examples/accuracy/" << scene << ".toml)\n\n";
    o << "| setting | ns/event | × double | energy drift | largest overlap at a collision | reversal RMS / d, c = " << cs
      << " | back within d, c = " << cs << " | one ulp apart: collisions/disk to l / to d | log B/event |\n";
    o << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    const double base = double_ns(res.engine, scene);
    for (const EngineRow& r : res.engine) {
      if (r.scene != scene) continue;
      if (!r.failure.empty()) {
        o << "| " << r.setting.label() << " | failed: " << r.failure << " |\n";
        continue;
      }
      o << "| " << r.setting.label() << " | " << fmt(r.ns_per_event) << " | "
        << fmt(base > 0 ? r.ns_per_event / base : 0) << " | " << fmt(r.drift, 2) << (r.repeats_agree ? "" : " (!)")
        << " | " << fmt(r.overlap, 2) << " | " << slash_list(r.reversal_rms, 2) << " | "
        << slash_list(r.reversal_returned, 2) << " | " << divergence_text(r.divergence_path, plan) << " / "
        << divergence_text(r.divergence_diameter, plan) << " | "
        << (r.log_bytes_per_event < 0 ? "–" : fmt(r.log_bytes_per_event)) << " |\n";
    }
    o << "\n";
  }
  const EngineRow first = res.engine.empty() ? EngineRow{} : res.engine.front();
  o << "N = " << first.disks << " disks per scene. Errors after " << fmt(first.events)
    << " engine events (drift: at the end; overlap: the largest at any pair collision); "
    << "ns/event: median of " << plan.repeat << " runs of " << fmt(first.timing_events)
    << " events, interleaved over the settings (\"(!)\": a timed run's drift differed from the error run's). "
       "d: disk diameter; l: mean free path (v_rms tau).\n\n";
}

void stepped_table(std::ostringstream& o, const SteppedStudy& st) {
  o << "### Time-stepped against event-driven (gas: collision rate; cooling: E(t)/E0)\n\n";
  o << "| method | dt / tau | v dt / d | CPU s (gas) | × event-driven | rate error | energy drift | largest overlap "
       "| CPU s (cooling) | × event-driven | cooling error |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const SteppedRow& r : st.rows) {
    if (!r.failure.empty()) {
      o << "| " << r.method << " | " << fmt(r.dt_over_tau) << " | failed: " << r.failure << " |\n";
      continue;
    }
    const bool ts = r.method == "time-stepped", ref = r.method == "event-driven";
    o << "| " << r.method << " | " << (ts ? fmt(r.dt_over_tau) : "–") << " | "
      << (ts ? fmt(r.step_over_diameter, 2) : "–") << " | " << fmt(r.cpu_seconds) << " | " << fmt(r.cpu_ratio, 2)
      << " | " << (ref ? "(reference)" : fmt(r.rate_error, 2)) << " | " << fmt(r.energy_drift, 2) << " | "
      << fmt(r.overlap, 2) << " | " << fmt(r.cooling_cpu_seconds) << " | " << fmt(r.cooling_cpu_ratio, 2) << " | "
      << (ref ? "(reference)" : fmt(r.cooling_error, 2)) << " |\n";
  }
  o << "\ntau = " << fmt(st.tau) << " (mean free time of the gas), d = " << fmt(st.diameter) << ", v_rms = "
    << fmt(st.v_rms) << "; runs to " << fmt(st.span) << " (gas) and " << fmt(st.cooling_span)
    << " (cooling, where the event-driven E/E0 = " << fmt(st.energy_end)
    << "). \"Other seed\": the event-driven engine on another sample of the same gas, how much the rate and "
       "the cooling curve differ between samples. The event-driven rate's own standard error (10 blocks): "
    << fmt(st.rate_stderr, 2) << ". Largest overlap: time-stepped, every overlap found before resolution; "
       "event-driven, all near pairs at 10 samples.\n\n";
}

void log_table(std::ostringstream& o, const std::vector<LogRow>& rows) {
  o << "### The log (gas, double)\n\n| log | ns/event | × log off | B/logged event | keyframe share | "
       "seek median ms | seek max ms |\n|---|---:|---:|---:|---:|---:|---:|\n";
  for (const LogRow& r : rows) {
    if (!r.failure.empty()) {
      o << "| " << r.label << " | failed: " << r.failure << " |\n";
      continue;
    }
    const bool off = r.interval == 0 && !r.rebuilds;
    o << "| " << r.label << " | " << fmt(r.ns_per_event) << " | " << fmt(r.ratio_to_off) << " | "
      << (off ? "–" : fmt(r.bytes_per_event)) << " | " << (off ? "–" : fmt(100 * r.keyframe_share, 2) + " %")
      << " | " << (off ? "–" : fmt(1e3 * r.seek_median)) << " | " << (off ? "–" : fmt(1e3 * r.seek_max)) << " |\n";
  }
  o << "\n";
}

Status write_text(const std::string& path, const std::string& text) {
  tools::Output out(path);
  if (!out.error().empty()) return Error{out.error()};
  out.write(text);
  return out.close();
}

}  // namespace

Status write_report(const StudyResults& res, const std::string& out_dir, bool plot) {
  std::ostringstream md;
  engine_tables(md, res);
  stepped_table(md, res.stepped);
  log_table(md, res.log);
  std::fputs(md.str().c_str(), stdout);
  for (const auto& [name, text] : {std::pair<std::string, std::string>{"engine.csv", engine_csv(res)},
                                   {"time_stepped.csv", stepped_csv(res.stepped)},
                                   {"log.csv", log_csv(res.log)},
                                   {"tables.md", md.str()}})
    if (Status s = write_text(out_dir + "/" + name, text); !s) return s;
  if (!plot) return Ok{};
  return tools::run_plot_script("plot_accuracy.py", {out_dir, out_dir + "/accuracy.png"});
}

}  // namespace ede::bench
