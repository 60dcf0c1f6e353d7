// start_from_state; see run_start.hpp.
#include "run/run_start.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/xxh3.hpp"
#include "ede/log.hpp"
#include "ede/number_text.hpp"
#include "setup/setup.hpp"
#include "setup/setup_from_csv.hpp"

namespace ede {

namespace {

struct Source {
  InitialState initial;
  std::string digest;
  double at = 0;
  // A sheared (Lees-Edwards) source log: its images' offset at `at`, its rate and box (else 0).
  double shear_offset = 0, shear_rate = 0;
};

// Why a start from a sheared log's state may overlap where the source did not: a new run starts its
// images' offset at 0 (engine/lees_edwards.hpp), so at a time the source's images were shifted, disks
// touching across the top or bottom edge land on each other's plain images. The times at which the images
// are aligned (offset 0) continue the run exactly.
std::string shifted_images_hint(const Source& src, double lx, double ly) {
  if (src.shear_offset == 0 || !(src.shear_rate > 0)) return "";
  const double period = lx / (src.shear_rate * ly);
  return " The state is from a sheared (Lees-Edwards) log at t = " + exact_double(src.at) +
         ", where its images above and below were shifted by " + general_text(src.shear_offset, 6) +
         "; a new run starts with them aligned (the offset is not carried over yet), which can put disks that "
         "touch across the top or bottom edge onto each other. Fix: start from a time at which the images are "
         "aligned, a multiple of lx / (shear_rate ly) = " + general_text(period, 10) +
         " (start.at, ede-sim --at), which continues the run exactly; or continue an interrupted run with --resume.";
}

Result<Source> from_log(const StartSpec& start, const std::string& path, const std::string& scene_name) {
  auto log = Log::open(path);
  if (!log) return Error{scene_name + ": start.from: " + log.error().message, log.error().kind};
  const LogInfo& info = log.value().info();
  Source src;
  if (start.at) {
    if (!(Time(*start.at) >= Time(info.start_time) && Time(*start.at) <= info.end_time))
      return Error{scene_name + ": error: start.at = " + exact_double(*start.at) + " is outside the log " + path +
                   " (it runs from " + exact_double(info.start_time) + " to " + exact_double(double(info.end_time)) +
                   "). Fix: give a time within the log, or leave start.at out to start from its end."};
    auto s = log.value().state_at(Time(*start.at));
    if (!s) return s.error();
    src.initial = initial_state_of(s.value());
    src.at = *start.at;
    src.shear_offset = s.value().shear_offset;
  } else {
    auto s = log.value().state_at_end();
    if (!s) return s.error();
    src.initial = initial_state_of(s.value());
    src.at = double(s.value().time);
    src.shear_offset = s.value().shear_offset;
  }
  src.shear_rate = info.shear_rate;
  auto digest = log.value().content_digest();
  if (!digest) return digest.error();
  src.digest = digest.value();
  return src;
}

Result<Source> from_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return Error{path + ": error: cannot read the CSV state (start.csv). Fix: check the path (relative paths are "
                        "relative to the scene file's folder).",
                 ErrorKind::Io};
  std::ostringstream text;
  text << in.rdbuf();
  const std::string bytes = text.str();
  auto st = parse_state_csv(bytes, path);
  if (!st) return st.error();
  Xxh3Hash h;
  h.update(bytes.data(), bytes.size());
  return Source{std::move(st).value(), "xxh3-128:" + h.hex(), 0};
}

// v -> v - P/M (the centre-of-mass velocity), sums in long double; then v -> -v if asked.
void adjust_velocities(const StartSpec& start, InitialState& st) {
  if (start.zero_momentum) {
    long double px = 0, py = 0, m = 0;
    for (std::size_t i = 0; i < st.size(); ++i) {
      px += (long double)st.mass[i] * st.vx[i];
      py += (long double)st.mass[i] * st.vy[i];
      m += st.mass[i];
    }
    const double ux = double(px / m), uy = double(py / m);
    for (std::size_t i = 0; i < st.size(); ++i) st.vx[i] -= ux, st.vy[i] -= uy;
  }
  if (start.reverse_velocities) {
    for (std::size_t i = 0; i < st.size(); ++i) st.vx[i] = -st.vx[i], st.vy[i] = -st.vy[i];
    for (double& w : st.omega) w = -w;  // rough disks: the reversed motion spins the other way
  }
}

Status check_pair_names(const Scene& scene, const InitialState& st) {
  for (const PairRestitution& p : scene.physics.pairs)
    for (const std::string& name : {p.a, p.b}) {
      bool found = false;
      for (const std::string& s : st.species_names) found = found || s == name;
      if (found) continue;
      std::string known;
      for (const std::string& s : st.species_names) known += (known.empty() ? "" : ", ") + s;
      return Error{scene.source_name + ": error: physics.pairs: there is no species '" + name +
                   "' in the starting state. Fix: use the names of its species: " + known + "."};
    }
  return Ok{};
}

}  // namespace

InitialState initial_state_of(const State& s) {
  InitialState st;
  st.lx = s.lx, st.ly = s.ly;
  st.species_names = s.species_names;
  for (std::size_t i = 0; i < s.size(); ++i)
    st.add(s.x[i], s.y[i], s.vx[i], s.vy[i], s.radius[i], s.mass[i], s.species[i]);
  for (std::size_t i = 0; i < s.omega.size(); ++i) st.omega.push_back(s.omega[i]), st.inertia.push_back(s.inertia[i]);
  return st;
}

std::string resolve_start_path(const std::string& path, const std::string& scene_source_name) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || scene_source_name.empty() || scene_source_name.front() == '<') return path;
  const std::filesystem::path dir = std::filesystem::path(scene_source_name).parent_path();
  return dir.empty() ? path : (dir / p).string();
}

Result<StartedRun> start_from_state(const Scene& scene) {
  const StartSpec& start = *scene.start;
  const bool is_log = !start.from.empty();
  const std::string path = resolve_start_path(is_log ? start.from : start.csv, scene.source_name);
  auto src = is_log ? from_log(start, path, scene.source_name) : from_csv(path);
  if (!src) return src.error();
  if (!start.digest.empty() && start.digest != src.value().digest)
    return Error{scene.source_name + ": error: start.digest = " + start.digest + " but " + path + " has " +
                 src.value().digest + ": it is not the source this run started from (changed or replaced). Fix: "
                 "give the original file (--set start." + (is_log ? "from" : "csv") +
                 "=PATH), or remove start.digest to start from this one as a new run."};
  StartedRun run;
  run.initial = std::move(src.value().initial);
  run.initial.lx = scene.lx;
  run.initial.ly = scene.ly;
  adjust_velocities(start, run.initial);
  if (Status s = check_pair_names(scene, run.initial); !s) return s.error();
  if (Status s = check_initial_state(run.initial, scene.boundary, scene.source_name + " (start from " + path + ")"); !s) {
    if (const std::string hint = shifted_images_hint(src.value(), scene.lx, scene.ly); !hint.empty()) {
      const std::string& m = s.error().message;
      return Error{m + (!m.empty() && m.back() == '.' ? "" : ".") + hint, s.error().kind};
    }
    return s.error();
  }
  if (Status s = check_disks_clear_of_segments(run.initial, scene.physics.segments,
                                               scene.source_name + " (start from " + path + ")");
      !s)
    return s.error();
  std::vector<Override> record;
  if (start.digest.empty()) record.push_back({"start.digest=\"" + src.value().digest + "\""});
  if (is_log && !start.at) record.push_back({"start.at=" + exact_double(src.value().at)});
  if (record.empty()) {
    run.scene = scene;
    return run;
  }
  auto recorded = parse_scene_text(scene.source_text, scene.source_name, record);
  if (!recorded) return recorded.error();
  run.scene = std::move(recorded).value();
  return run;
}

}  // namespace ede
