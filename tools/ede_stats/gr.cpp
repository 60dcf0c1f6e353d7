// ede-stats gr: the pair correlation g(r) of a log at one time or averaged over frames, for every disk or
// one species pair, and with --contact the contact value g(sigma) three ways (fit of g(r), collision rate,
// virial pressure). Thin: pair_correlation and contact_values (ede/structure.hpp) do the work.
#include <cmath>
#include <memory>

#include "stats_tool.hpp"
#include "table_cli.hpp"

namespace ede::stats_tool {

namespace {

struct GrOptions {
  std::string log, species, with;
  double r_max = 0, r_min = 0;
  std::size_t bins = 200;
  bool contact = false;
  FrameCli frames;
  TableOutput out;
};

std::string pm(const ContactValue& c) { return brief(c.value) + " ± " + brief(c.error, 2); }

int run_gr(const GrOptions& opt) {
  if (!opt.out.plot.empty() && !plot_name_ok(opt.out.plot))
    return usage_error("--plot wants a file name ending in .png or .svg", "gr");
  auto opened = open_log_overview(opt.log);
  if (!opened) return fail(opened.error().message);
  const Log& log = opened.value().log;
  auto f = opt.frames.read(log);
  if (!f) return usage_error(f.error().message, "gr");
  PairCorrelationOptions o;
  o.bins = opt.bins, o.r_min = opt.r_min;
  o.r_max = opt.r_max > 0 ? opt.r_max : 0.25 * std::min(log.info().lx, log.info().ly);
  auto a = read_species(log, opt.species), b = read_species(log, opt.with.empty() ? opt.species : opt.with);
  if (!a) return fail(a.error().message);
  if (!b) return fail(b.error().message);
  o.species_a = a.value(), o.species_b = b.value();
  auto g = pair_correlation(log, o, f.value());
  if (!g) return fail(g.error().message);
  const PairCorrelation& p = g.value();
  Summary s;
  s.add("log", opt.log + " (" + std::to_string(log.info().disks) + " disks, " + to_string(log.info().boundary) + ")");
  s.add("pairs", std::string(opt.species.empty() ? "every disk" : opt.species) + " with " +
                     (opt.with.empty() ? (opt.species.empty() ? "every disk" : opt.species) : opt.with) + ": " +
                     std::to_string(p.n_a) + " x " + std::to_string(p.n_b) + " disks");
  s.add("frames", std::to_string(p.frames));
  s.add("area", brief(p.area) + (log.info().boundary == BoundaryKind::Walls ? " (the centres' rectangle)" : ""));
  s.number("frames", double(p.frames)), s.number("area", p.area), s.number("density_b", p.density_b);
  if (opt.contact) {
    auto c = contact_values(log, f.value());
    if (!c) return fail(c.error().message);
    s.add("sigma", brief(c.value().sigma));
    s.add("g(sigma) fit", pm(c.value().from_gr));
    s.add("g(sigma) rate", pm(c.value().from_collisions) + " (Enskog collision frequency)");
    s.add("g(sigma) virial", pm(c.value().from_pressure) + " (Z = 1 + (pi/2) n sigma^2 g)");
    // The equations of state at phi = (pi/4) n sigma^2 (equal disks), g = (Z - 1) / (2 phi).
    const double phi = 0.25 * 3.14159265358979323846 * c.value().density * c.value().sigma * c.value().sigma;
    const double g_kr = kolafa_rottner_contact_value(phi);
    s.add("g(sigma) EOS", "Henderson " + brief(henderson_contact_value(phi)) + ", Kolafa-Rottner " +
                              (std::isnan(g_kr) ? std::string("n/a (phi above its fit range 0.707)") : brief(g_kr)) +
                              " at phi = " + brief(phi, 4));
    s.number("g_sigma_henderson", henderson_contact_value(phi));
    s.number("g_sigma_kolafa_rottner", g_kr);
    s.number("g_sigma_fit", c.value().from_gr.value), s.number("g_sigma_fit_error", c.value().from_gr.error);
    s.number("g_sigma_collisions", c.value().from_collisions.value);
    s.number("g_sigma_collisions_error", c.value().from_collisions.error);
    s.number("g_sigma_pressure", c.value().from_pressure.value);
    s.number("g_sigma_pressure_error", c.value().from_pressure.error);
  }
  Table t;
  std::vector<double> r(p.g.size());
  for (std::size_t k = 0; k < r.size(); ++k) r[k] = 0.5 * (p.r_lo[k] + p.r_hi[k]);
  t.add("r", r), t.add("r_lo", p.r_lo), t.add("r_hi", p.r_hi), t.add("g", p.g), t.add("count", p.count),
      t.add("ideal", p.ideal);
  return finish_table("gr", opt.out, s, t, {.x = "r", .ys = "g", .title = "pair correlation g(r)", .xlabel = "r [L]",
                                             .ylabel = "g(r)"});
}

}  // namespace

Command add_gr_command(CLI::App& app) {
  auto opt = std::make_shared<GrOptions>();
  CLI::App* cmd = app.add_subcommand("gr", "pair correlation g(r), per species pair, and the contact value g(sigma)");
  cmd->add_option("log", opt->log, "event log")->required();
  opt->frames.add(cmd, "g(r)");
  cmd->add_option("--r-max", opt->r_max, "largest r (default: a quarter of the shorter box side)");
  cmd->add_option("--r-min", opt->r_min, "smallest r (default 0)");
  cmd->add_option("--bins", opt->bins, "bins (default 200)")->check(CLI::Range(std::size_t(1), std::size_t(10000000)));
  cmd->add_option("--species", opt->species, "first disk of each pair: this species (default: every disk)");
  cmd->add_option("--with", opt->with, "second disk of each pair: this species (default: as --species)");
  cmd->add_flag("--contact", opt->contact,
                "also g(sigma) from a fit of g(r), the collision rate and the pressure (one radius, periodic, "
                "--from/--to/--frames)");
  opt->out.add(cmd, "write CSV: r,r_lo,r_hi,g,count,ideal", "draw g(r) into FILE.png or FILE.svg");
  return [opt] { return run_gr(*opt); };
}

}  // namespace ede::stats_tool
