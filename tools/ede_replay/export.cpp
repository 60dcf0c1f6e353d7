// ede-replay export: states of a log in the formats other programs read (docs/python.md, "Interchange").
//
//   ede-replay export LOG -o run.xyz [--at T|end | --from T0 --to T1 (--frames N | --every DT)]
//   ede-replay export LOG -o run.gsd ...
//   ede-replay export LOG -o run.xyz --every-collisions-per-disk K   (XYZ: the states right after the pair
//                                     collisions that bring the count to ceil(k K N / 2), k = 0, 1, ...)
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

#include <algorithm>
#include <array>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include "replay_tool.hpp"
#include "process.hpp"

namespace ede::replay_tool {

namespace {

struct ExportOptions {
  std::string log, output, format, at, from, to;
  std::optional<unsigned> frames;
  std::optional<double> every;
  std::optional<double> every_collisions;
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

// A frame is a time, or a number of events (the state right after a collision count).
struct Frame {
  Time time = 0;
  std::optional<std::uint64_t> events;
};

// The frames every K collisions per disk, from 0 to the log's last pair collision.
Result<std::vector<Frame>> collision_frames(const Log& log, double every) {
  auto counts = log.count_events();
  if (!counts) return counts.error();
  const double pairs = double(counts.value().by_kind[int(EventKind::Pair)]);
  const double per_disk = 2 * pairs / double(std::max<std::uint64_t>(log.info().disks, 1));
  std::vector<double> marks;
  // k K N / 2 <= pairs, with k K computed afresh each time (no drift from repeated sums).
  for (std::size_t k = 0; double(k) * every <= per_disk && marks.size() < kMaxFrames; ++k) marks.push_back(double(k) * every);
  while (!marks.empty() && std::ceil(marks.back() * double(log.info().disks) / 2) > pairs) marks.pop_back();
  auto events = log.events_after_collisions(marks);
  if (!events) return events.error();
  std::vector<Frame> frames;
  for (const std::uint64_t n : events.value()) frames.push_back({0, n});
  return frames;
}

int export_xyz(const Log& log, const std::vector<Frame>& frames, const std::string& path) {
  if (log.info().species_names.size() > kElements.size())
    return fail(path + ": XYZ export names species by chemical element, and this log has more than " +
                std::to_string(kElements.size()) + " species");
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) return fail("cannot write '" + path + "': " + std::strerror(errno));
  for (const Frame& f : frames) {
    auto s = f.events ? log.state_at_event(*f.events) : log.state_at(f.time);
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
  tools::SpawnRequest request;
  request.argv = std::move(argv);
  request.search_path = !debian;
  auto run = tools::run_program(request);
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
  if (opt.every_collisions && (!opt.at.empty() || !opt.from.empty() || !opt.to.empty() || opt.frames || opt.every))
    return usage_error("export: --every-collisions-per-disk exports the whole log by collision count; give it alone");
  if (opt.every_collisions && format == "gsd")
    return usage_error("export: --every-collisions-per-disk writes XYZ only (GSD frames are exported by time); "
                       "use -o FILE.xyz");
  auto log = open_log(opt.log);
  if (!log) return fail(log.error().message);
  if (opt.every_collisions) {
    auto frames = collision_frames(log.value(), *opt.every_collisions);
    if (!frames) return fail(frames.error().message);
    return export_xyz(log.value(), frames.value(), opt.output);
  }
  auto times = export_times(log.value(), opt);
  if (!times) return fail(times.error().message);
  if (format == "gsd") return export_gsd(log.value(), times.value(), opt.output);
  std::vector<Frame> frames;
  for (const Time t : times.value()) frames.push_back({t, std::nullopt});
  return export_xyz(log.value(), frames, opt.output);
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
  cmd->add_option("--every-collisions-per-disk", opt->every_collisions,
                  "XYZ frames right after the pair collisions that bring the count to ceil(k K N / 2), k = 0, 1, ... "
                  "(the schedules' collisions per disk), to the log's last")
      ->check(CLI::PositiveNumber);
  frames->excludes(every);
  at->excludes(from)->excludes(to)->excludes(frames)->excludes(every);
  return [opt] {
    if (opt->at.empty() && opt->from.empty() && opt->to.empty() && !opt->frames && !opt->every && !opt->every_collisions)
      opt->at = "end";
    return run_export(*opt);
  };
}

}  // namespace ede::replay_tool
