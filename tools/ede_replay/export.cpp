// ede-replay export: states of a log in the formats other programs read (docs/python.md, "Interchange").
//
//   ede-replay export LOG -o run.xyz [--at T|end | --from T0 --to T1 (--frames N | --every DT)]
//   ede-replay export LOG -o run.gsd ...
//
// Extended XYZ is written here, from the public API, with every number's exact digits (exact_text): one
// frame per time, z = 0, the box as Lattice with a third axis of length 1, pbc, Time, and the properties
// species (a chemical symbol per ede species, H, He, ..., because ASE accepts only element names there),
// pos, vel, radius, masses and ede_species (the species' own name): ASE and OVITO read it. The layout is
// the Python module's (python/ede/export.py); a test checks that the two files are identical.
// GSD is HOOMD-blue's binary format; its reference implementation is python3-gsd, so for GSD this
// command runs the Python module's export_gsd (Debian's python3 with python3-gsd and the installed or
// built `ede` module) rather than writing the binary layout a second time.
// Rejected: a C++ GSD writer of our own (a second implementation of a format with a maintained one).
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "replay_tool.hpp"
#include "spawn.hpp"

namespace ede::replay_tool {

namespace {

struct ExportOptions {
  std::string log, output, format, at, from, to;
  std::optional<unsigned> frames;
  std::optional<double> every;
};

constexpr std::size_t kMaxFrames = 1'000'000;
constexpr std::array<const char*, 54> kElements = {
    "H",  "He", "Li", "Be", "B",  "C",  "N",  "O",  "F",  "Ne", "Na", "Mg", "Al", "Si", "P",  "S",  "Cl", "Ar",
    "K",  "Ca", "Sc", "Ti", "V",  "Cr", "Mn", "Fe", "Co", "Ni", "Cu", "Zn", "Ga", "Ge", "As", "Se", "Br", "Kr",
    "Rb", "Sr", "Y",  "Zr", "Nb", "Mo", "Tc", "Ru", "Rh", "Pd", "Ag", "Cd", "In", "Sn", "Sb", "Te", "I",  "Xe"};

Result<std::vector<Time>> export_times(const Log& log, const ExportOptions& opt) {
  if (!opt.at.empty()) {
    auto t = tools::read_time(log, opt.at, "--at");
    if (!t) return t.error();
    return std::vector<Time>{t.value().t};
  }
  tools::TimeOption start{Time(log.info().start_time), false};
  auto from = opt.from.empty() ? Result<tools::TimeOption>(start) : tools::read_time(log, opt.from, "--from", false);
  if (!from) return from.error();
  auto to = tools::read_time(log, opt.to.empty() ? std::string("end") : opt.to, "--to");
  if (!to) return to.error();
  const ScalarKind scalar = log.info().scalar;
  std::vector<Time> times;
  if (opt.every) times = times_every(from.value().t, to.value().t, Time(*opt.every), scalar, kMaxFrames);
  else times = evenly_spaced_times(from.value().t, to.value().t, opt.frames.value_or(1), scalar);
  if (times.empty()) return Error{"no times to export between --from and --to (check --frames or --every)"};
  return times;
}

// One frame; numbers in their exact digits (long double logs: 21).
void write_xyz_frame(std::FILE* out, const State& s, ScalarKind scalar) {
  auto num = [&](long double v) { return exact_text(v, scalar); };
  std::fprintf(out, "%zu\n", s.size());
  std::fprintf(out,
               "Lattice=\"%s 0.0 0.0 0.0 %s 0.0 0.0 0.0 1.0\" Properties=species:S:1:pos:R:3:vel:R:3:radius:R:1:"
               "masses:R:1:ede_species:S:1 Time=%s pbc=\"%s\"\n",
               num(s.lx).c_str(), num(s.ly).c_str(), num(s.time).c_str(),
               s.boundary == BoundaryKind::Periodic ? "T T F" : "F F F");
  for (std::size_t k = 0; k < s.size(); ++k) {
    const auto sp = std::size_t(s.species[k]);
    std::fprintf(out, "%s %s %s 0 %s %s 0 %s %s %s\n", kElements[sp], num(s.x.exact(k)).c_str(),
                 num(s.y.exact(k)).c_str(), num(s.vx.exact(k)).c_str(), num(s.vy.exact(k)).c_str(),
                 num(s.radius.exact(k)).c_str(), num(s.mass.exact(k)).c_str(), s.species_names[sp].c_str());
  }
}

int export_xyz(const Log& log, const std::vector<Time>& times, const std::string& path) {
  if (log.info().species_names.size() > kElements.size())
    return fail(path + ": XYZ export names species by chemical element, and this log has more than " +
                std::to_string(kElements.size()) + " species");
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) return fail("cannot write '" + path + "': " + std::strerror(errno));
  for (const Time t : times) {
    auto s = log.state_at(t);
    if (!s) return std::fclose(out), fail(s.error().message);
    write_xyz_frame(out, s.value(), log.info().scalar);
  }
  const bool ok = std::fflush(out) == 0 && !std::ferror(out);
  if (std::fclose(out) != 0 || !ok) return fail("error while writing '" + path + "': " + std::strerror(errno));
  return 0;
}

// The `ede` Python package in the build tree (tools/../python) when this tool runs from there.
std::string build_tree_python_dir() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const auto dir = exe.parent_path().parent_path() / "python";
  return std::filesystem::exists(dir / "ede" / "__init__.py") ? dir.string() : std::string();
}

int export_gsd(const Log& log, const std::vector<Time>& times, const std::string& path) {
  const bool debian = ::access("/usr/bin/python3", X_OK) == 0;
  std::vector<std::string> argv = {debian ? "/usr/bin/python3" : "python3", "-c",
                                   "import sys\n"
                                   "if sys.argv[1]: sys.path.insert(0, sys.argv[1])\n"
                                   "import ede\n"
                                   "ede.export_gsd(ede.open(sys.argv[2]), sys.argv[3], sys.argv[4:])\n",
                                   build_tree_python_dir(), log.info().path, path};
  for (const Time t : times) argv.push_back(exact(log, t));
  auto run = tools::run_program({argv, !debian, ""});
  if (!run) return fail(run.error().message);
  if (run.value().exit_status != 0) {
    const std::string& err = run.value().err;
    if (err.find("No module named 'ede'") != std::string::npos)
      return fail("GSD export runs the Python module `ede`, which is not installed: build it (pybind11-dev) "
                  "and install it (scripts/build.sh does), or export XYZ (-o FILE.xyz)");
    if (err.find("python3-gsd") != std::string::npos || err.find("No module named 'gsd'") != std::string::npos)
      return fail("GSD export needs python3-gsd: apt-get install python3-gsd (or export XYZ: -o FILE.xyz)");
    return fail("GSD export of " + log.info().path + " failed:\n" + err);
  }
  return 0;
}

int run_export(const ExportOptions& opt) {
  std::string format = opt.format;
  if (format.empty()) format = std::filesystem::path(opt.output).extension() == ".gsd" ? "gsd" : "xyz";
  if (format != "xyz" && format != "gsd")
    return usage_error("export: --format is xyz or gsd, got '" + format + "'");
  if (!opt.at.empty() && (!opt.from.empty() || !opt.to.empty() || opt.frames || opt.every))
    return usage_error("export: --at exports one time; give it alone, or --from/--to with --frames or --every");
  auto log = open_log(opt.log);
  if (!log) return fail(log.error().message);
  auto times = export_times(log.value(), opt);
  if (!times) return fail(times.error().message);
  return format == "xyz" ? export_xyz(log.value(), times.value(), opt.output)
                         : export_gsd(log.value(), times.value(), opt.output);
}

}  // namespace

Command add_export_command(CLI::App& app) {
  auto opt = std::make_shared<ExportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "export", "states as extended XYZ (ASE, OVITO) or GSD (HOOMD-blue, OVITO): one frame per time");
  cmd->add_option("log", opt->log, "event log (any file name)")->required();
  cmd->add_option("-o,--output", opt->output, "the file to write: FILE.xyz or FILE.gsd")->required();
  cmd->add_option("--format", opt->format, "xyz or gsd (default: from the output's extension; else xyz)");
  auto* at = cmd->add_option("--at", opt->at, "one time T (exact in the log's type) or 'end' (the default)");
  auto* from = cmd->add_option("--from", opt->from, "first time T0 (default: the start)");
  auto* to = cmd->add_option("--to", opt->to, "last time T1 or 'end' (the default)");
  auto* frames = cmd->add_option("--frames", opt->frames, "N times evenly spaced from T0 to T1, both included")
                     ->check(CLI::PositiveNumber);
  auto* every = cmd->add_option("--every", opt->every, "times T0 + k DT up to T1")->check(CLI::PositiveNumber);
  frames->excludes(every);
  at->excludes(from)->excludes(to)->excludes(frames)->excludes(every);
  return [opt] {
    if (opt->at.empty() && opt->from.empty() && opt->to.empty() && !opt->frames && !opt->every) opt->at = "end";
    return run_export(*opt);
  };
}

}  // namespace ede::replay_tool
