// ede-stats psi6: the bond-orientational order psi6 (nearest six neighbours), its global value |<psi6>|,
// its mean local modulus, g6(r) beside g(r), and with --disks a CSV of psi6 per disk (id, x, y, psi6) at
// the last frame, for colouring pictures. Thin: bond_order and psi6 (ede/structure.hpp).
#include <cmath>
#include <memory>

#include "output_file.hpp"
#include "stats_tool.hpp"
#include "table_cli.hpp"

namespace ede::stats_tool {

namespace {

struct Psi6Options {
  std::string log, disks;
  double r_max = 0;
  std::size_t bins = 200;
  FrameCli frames;
  TableOutput out;
};

Status write_disks(const std::string& path, const State& s, const std::vector<std::complex<double>>& p) {
  std::string text = "id,x,y,psi6_re,psi6_im,psi6_abs\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    text += std::to_string(i) + "," + exact_double(s.x[i]) + "," + exact_double(s.y[i]) + "," + exact_double(p[i].real()) + "," +
            exact_double(p[i].imag()) + "," + exact_double(std::abs(p[i])) + "\n";
  tools::Output out(path);
  if (!out.file()) return Error{out.error()};
  out.write(text);
  return out.close();
}

int run_psi6(const Psi6Options& opt) {
  if (!opt.out.plot.empty() && !plot_name_ok(opt.out.plot))
    return usage_error("--plot wants a file name ending in .png or .svg", "psi6");
  auto opened = open_log_overview(opt.log);
  if (!opened) return fail(opened.error().message);
  const Log& log = opened.value().log;
  auto f = opt.frames.read(log);
  if (!f) return usage_error(f.error().message, "psi6");
  PairCorrelationOptions o;
  o.bins = opt.bins;
  o.r_max = opt.r_max > 0 ? opt.r_max : 0.25 * std::min(log.info().lx, log.info().ly);
  auto b = bond_order(log, o, f.value());
  if (!b) return fail(b.error().message);
  const BondOrder& r = b.value();
  if (!opt.disks.empty()) {
    auto times = frame_times(log, f.value());
    auto s = log.state_at(times.value().back());
    if (!s) return fail(s.error().message);
    if (Status w = write_disks(opt.disks, s.value(), r.psi6); !w) return fail(w.error().message);
  }
  Summary s;
  s.add("log", opt.log + " (" + std::to_string(log.info().disks) + " disks)");
  s.add("neighbours", "the nearest six of each disk");
  s.add("frames", std::to_string(r.g6.frames));
  s.add("|<psi6>|", brief(r.global) + " (global order, mean over frames)");
  s.add("<|psi6|>", brief(r.mean_local) + " (mean local order)");
  s.number("global", r.global), s.number("mean_local", r.mean_local), s.number("frames", double(r.g6.frames));
  Table t;
  std::vector<double> x(r.g6.g.size());
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = 0.5 * (r.g6.r_lo[k] + r.g6.r_hi[k]);
  t.add("r", x), t.add("g", r.g6.g), t.add("g6", r.g6.g6);
  return finish_table("psi6", opt.out, s, t, {.x = "r", .ys = "g6", .dashed = "", .title = "bond-orientational correlation g6(r)",
                                               .xlabel = "r [L]", .ylabel = "g6(r) = Re <psi6_i psi6_j*>", .scale = "linear"});
}

}  // namespace

Command add_psi6_command(CLI::App& app) {
  auto opt = std::make_shared<Psi6Options>();
  CLI::App* cmd = app.add_subcommand("psi6", "bond-orientational order psi6 (nearest six), global |<psi6>|, g6(r)");
  cmd->add_option("log", opt->log, "event log")->required();
  opt->frames.add(cmd, "psi6");
  cmd->add_option("--r-max", opt->r_max, "largest r for g6 (default: a quarter of the shorter box side)");
  cmd->add_option("--bins", opt->bins, "bins of g6 (default 200)")->check(CLI::Range(std::size_t(1), std::size_t(10000000)));
  cmd->add_option("--disks", opt->disks, "write CSV of psi6 per disk at the last frame: id,x,y,psi6_re,psi6_im,psi6_abs");
  opt->out.add(cmd, "write CSV: r,g,g6", "draw g6(r) into FILE.png or FILE.svg");
  return [opt] { return run_psi6(*opt); };
}

}  // namespace ede::stats_tool
