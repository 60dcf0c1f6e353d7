// ede-crater measure (the default command): the crater of one log, printed with its definitions, the
// surface profiles and the energy curve as CSV, and a figure of both.
//
// The numbers come from the library (measure_crater); this file prints them and writes files. The energy
// curve goes next to the profile CSV as <name>-energy.csv, so `-o` stays one option. A figure without -o
// writes its CSV files to a temporary directory the plotting script reads and that is removed after.
// Rejected: printing only the numbers, which invites reading "width" as something it is not: every line
// says what it measures.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

#include "crater_tool.hpp"
#include "plot_runner.hpp"

namespace ede::crater_tool {

namespace {

struct Options {
  std::string log, output, plot;
  MeasureOptions measure;
};

std::string energy_csv_path(const std::string& profile_csv) {
  const std::filesystem::path p(profile_csv);
  return (p.parent_path() / (p.stem().string() + "-energy.csv")).string();
}

std::string percent(std::size_t part, std::size_t whole) {
  return brief(whole ? 100.0 * double(part) / double(whole) : 0.0) + "%";
}

void print_report(const Options& opt, const MeasuredLog& ml) {
  const CraterMeasurement& m = ml.crater;
  const CraterLengths& l = m.report.lengths;
  const CraterMetrics& c = m.report.metrics;
  const auto in_r = [&](double v) { return brief(v) + " (" + brief(v / l.bed_radius) + " r_bed)"; };
  std::printf("log               %s: %llu disks, %s; %s\n", opt.log.c_str(), static_cast<unsigned long long>(ml.disks),
              ml.scalar.c_str(), ml.run_status.c_str());
  std::printf("bed               %zu disks: %s\n", m.bed.disks, m.bed.reason.c_str());
  std::printf("measured at       t = %s, after %llu events: %s\n", exact_double(m.time).c_str(),
              static_cast<unsigned long long>(m.events), m.when.c_str());
  if (m.before_time > 0) std::printf("compared with     the bed at t = %s (--before)\n", exact_double(m.before_time).c_str());
  if (m.has_energy)
    std::printf("energy            E/E0 = %s there (E0 = %s); the fraction %s is %s\n", brief(m.energy_fraction).c_str(),
                brief(m.energy.initial_energy).c_str(), brief(m.energy.fraction).c_str(),
                m.energy.reached ? ("reached at t = " + exact_double(m.energy.time)).c_str() : "never reached in this log");
  else
    std::printf("energy            no fraction under gravity (the kinetic energy changes between collisions)\n");
  std::printf("lengths           r_bed = %s (mean bed radius); %zu bins of width %s; link gap %s\n",
              brief(l.bed_radius).c_str(), l.bins, in_r(l.bin_width).c_str(),
              l.exclude_detached ? in_r(l.link_gap).c_str() : "none (--keep-detached)");
  std::printf("displaced         %zu of %zu bed disks (%s) moved by more than %s\n", m.report.displaced.size(),
              m.report.bed_disks, percent(m.report.displaced.size(), m.report.bed_disks).c_str(),
              in_r(l.displacement_threshold).c_str());
  std::printf("depth             %s: the largest drop of the surface, max over x of h_before(x) - h_after(x), at "
              "x = %s\n",
              brief(c.depth).c_str(), brief(c.deepest_x).c_str());
  std::printf("depth below mean  %s: the initial mean surface level minus the lowest point of the final surface\n",
              brief(c.depth_below_mean).c_str());
  if (c.has_crater) {
    std::printf("width             %s: the extent of the bins around the deepest point where the surface fell by "
                "more than %s: x in [%s, %s)\n",
                brief(c.width).c_str(), in_r(l.drop_threshold).c_str(), brief(c.left).c_str(), brief(c.right).c_str());
    std::printf("area              %s: the area between the profiles over that region\n", brief(c.area).c_str());
  } else {
    std::printf("width, area       0: the surface fell by no more than %s anywhere: no crater\n",
                in_r(l.drop_threshold).c_str());
  }
  std::printf("removed / raised  %s / %s: the area where the surface fell / rose, over the whole box\n",
              brief(c.removed_area).c_str(), brief(c.raised_area).c_str());
  std::printf("detached          %zu bed disks before, %zu after: not linked to the bed's body (ejecta), left out "
              "of the surface\n",
              m.report.before.detached, m.report.after.detached);
}

int run_measure(const Options& opt) {
  if (auto s = settings_from(opt.measure); !s) return usage_error(s.error().message);
  auto measured = measure_log(opt.log, opt.measure);
  if (!measured) return fail(measured.error().message);
  const MeasuredLog& ml = measured.value();
  print_report(opt, ml);

  std::string profile = opt.output, energy = opt.output.empty() ? "" : energy_csv_path(opt.output);
  std::string temp_dir;
  if (profile.empty() && !opt.plot.empty()) {
    char tmpl[] = "/tmp/ede-crater-XXXXXX";
    if (!mkdtemp(tmpl)) return fail("cannot create a temporary directory for the figure's data");
    temp_dir = tmpl;
    profile = temp_dir + "/profile.csv";
    energy = temp_dir + "/energy.csv";
  }
  const auto cleanup = [&] {
    if (!temp_dir.empty()) std::filesystem::remove_all(temp_dir);
  };
  if (!profile.empty()) {
    if (Status s = write_profile_csv(profile, ml.crater); !s) return cleanup(), fail(s.error().message);
    if (!ml.crater.has_energy) energy = "-";  // no curve: the figure has the profiles only
    if (ml.crater.has_energy)
      if (Status s = write_energy_csv(energy, ml.crater); !s) return cleanup(), fail(s.error().message);
    if (temp_dir.empty())
      std::printf("wrote             %s (profiles)%s\n", profile.c_str(),
                  ml.crater.has_energy ? (", " + energy + " (energy curve)").c_str() : "");
  }
  if (!opt.plot.empty()) {
    const CraterMeasurement& m = ml.crater;
    const Status s = tools::run_plot_script_to(
        "plot_crater.py", {"measure", profile, energy, opt.plot, "--time", exact_double(m.time), "--fraction",
                           exact_double(m.energy.fraction), "--drop-threshold", exact_double(m.report.lengths.drop_threshold),
                           "--title", std::filesystem::path(opt.log).filename().string()},
        opt.plot);
    cleanup();
    if (!s) return fail(s.error().message);
    std::printf("wrote             %s (figure)\n", opt.plot.c_str());
  }
  return 0;
}

}  // namespace

Command add_measure_command(CLI::App& app) {
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "measure", "the crater of one log (the default command: `ede-crater LOG` works too)");
  cmd->add_option("log", opt->log, "event log written by ede-sim -o")->required();
  add_measure_options(*cmd, opt->measure);
  cmd->add_option("-o,--output", opt->output,
                  "write the surface profiles to this CSV, and the energy curve to <name>-energy.csv beside it");
  cmd->add_option("--plot", opt->plot, "draw the profiles and the energy curve (.png or .svg)");
  return [opt] { return run_measure(*opt); };
}

}  // namespace ede::crater_tool
