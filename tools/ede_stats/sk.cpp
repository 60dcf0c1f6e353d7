// ede-stats sk: the static structure factor S(k) on the box's wave vectors, averaged over shells of |k|
// (and over frames). Thin: structure_factor (ede/structure.hpp).
#include <cmath>
#include <memory>

#include "stats_tool.hpp"
#include "table_cli.hpp"

namespace ede::stats_tool {

namespace {

struct SkOptions {
  std::string log, species;
  double k_max = 0;
  std::size_t shells = 100;
  FrameCli frames;
  TableOutput out;
};

int run_sk(const SkOptions& opt) {
  if (!opt.out.plot.empty() && !plot_name_ok(opt.out.plot))
    return usage_error("--plot wants a file name ending in .png or .svg", "sk");
  if (!(opt.k_max > 0)) return usage_error("--k-max must be > 0", "sk");
  auto opened = open_log_overview(opt.log);
  if (!opened) return fail(opened.error().message);
  const Log& log = opened.value().log;
  auto f = opt.frames.read(log);
  if (!f) return usage_error(f.error().message, "sk");
  auto sp = read_species(log, opt.species);
  if (!sp) return fail(sp.error().message);
  StructureFactorOptions o;
  o.k_max = opt.k_max, o.shells = opt.shells, o.species = sp.value();
  auto r = structure_factor(log, o, f.value());
  if (!r) return fail(r.error().message);
  const StructureFactor& sf = r.value();
  Summary s;
  s.add("log", opt.log + " (" + std::to_string(sf.n) + " disks counted)");
  s.add("wave vectors", std::to_string(sf.s.size()) + " with 0 < |k| <= " + brief(opt.k_max) + " (one of each +-k)");
  s.add("frames", std::to_string(sf.frames));
  std::size_t peak = 0;
  for (std::size_t b = 0; b < sf.s_shell.size(); ++b)
    if (sf.s_shell[b] == sf.s_shell[b] && !(sf.s_shell[b] <= sf.s_shell[peak])) peak = b;
  s.add("peak", "S = " + brief(sf.s_shell[peak]) + " at k = " + brief(0.5 * (sf.k_lo[peak] + sf.k_hi[peak])));
  s.number("vectors", double(sf.s.size())), s.number("frames", double(sf.frames));
  s.number("peak_k", 0.5 * (sf.k_lo[peak] + sf.k_hi[peak])), s.number("peak_s", sf.s_shell[peak]);
  Table t;
  std::vector<double> k(sf.s_shell.size()), count(sf.s_shell.size());
  for (std::size_t b = 0; b < k.size(); ++b) k[b] = 0.5 * (sf.k_lo[b] + sf.k_hi[b]), count[b] = double(sf.shell_vectors[b]);
  t.add("k", k), t.add("k_lo", sf.k_lo), t.add("k_hi", sf.k_hi), t.add("s", sf.s_shell), t.add("vectors", count);
  return finish_table("sk", opt.out, s, t, {.x = "k", .ys = "s", .title = "static structure factor S(k)",
                                             .xlabel = "k [1/L]", .ylabel = "S(k)"});
}

}  // namespace

Command add_sk_command(CLI::App& app) {
  auto opt = std::make_shared<SkOptions>();
  CLI::App* cmd = app.add_subcommand("sk", "static structure factor S(k) on the box's wave vectors, shell averaged");
  cmd->add_option("log", opt->log, "event log")->required();
  opt->frames.add(cmd, "S(k)");
  cmd->add_option("--k-max", opt->k_max, "largest |k| (e.g. 20 / diameter)")->required();
  cmd->add_option("--shells", opt->shells, "shells of |k| (default 100)")->check(CLI::Range(std::size_t(1), std::size_t(1000000)));
  cmd->add_option("--species", opt->species, "only this species (default: every disk)");
  opt->out.add(cmd, "write CSV: k,k_lo,k_hi,s,vectors", "draw S(k) into FILE.png or FILE.svg");
  return [opt] { return run_sk(*opt); };
}

}  // namespace ede::stats_tool
