// pack_frame and make_reference; see frame.hpp. The statistics use the library's gas analysis
// (GasSnapshot, temperature, speed classes, histograms), so the page shows what ede-stats would print.
#include "frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "ede/analysis.hpp"

namespace ede::view {
namespace {

GasSnapshot snapshot(const State& s) {
  GasSnapshot g;
  g.time = double(s.time);
  g.vx = s.vx.to_doubles();
  g.vy = s.vy.to_doubles();
  g.mass = s.mass.to_doubles();
  g.species = s.species;
  g.species_names = s.species_names;
  return g;
}

nlohmann::json histogram_json(const std::vector<double>& samples, double hi, std::size_t bins) {
  if (!(hi > 0) || !std::isfinite(hi)) hi = 1;
  const Histogram h = make_histogram(samples, uniform_edges(0, hi, bins));
  return {{"lo", 0.0}, {"hi", hi}, {"counts", h.count}, {"outside", h.outside}};
}

void append_floats(std::string& out, const std::vector<float>& v) {
  const std::size_t at = out.size();
  out.resize(at + v.size() * sizeof(float));
  if (!v.empty()) std::memcpy(out.data() + at, v.data(), v.size() * sizeof(float));
}

void append_u32(std::string& out, std::uint32_t v) {
  char b[4];
  std::memcpy(b, &v, 4);
  out.append(b, 4);
}

}  // namespace

Reference make_reference(const State& initial) {
  Reference r;
  r.x0 = initial.x.to_doubles();
  r.y0 = initial.y.to_doubles();
  const GasSnapshot g = snapshot(initial);
  r.mean_speed0 = mean_speed(g);
  r.kT0 = temperature(g);
  return r;
}

std::string segments_field(const Scene& scene) {
  if (scene.physics.segments.empty()) return "";
  nlohmann::json list = nlohmann::json::array();
  for (const SegmentSpec& g : scene.physics.segments) list.push_back({g.from[0], g.from[1], g.to[0], g.to[1]});
  return ",\"segments\":" + list.dump();
}

std::string pack_frame(const State& s, const Reference& ref, const FrameExtras& extras, std::size_t max_disks) {
  const std::size_t n = s.size();
  const GasSnapshot g = snapshot(s);
  const std::vector<double> v = speeds(g), e = kinetic_energies(g), m = masses(g);
  const double kT = temperature(g), vmean = mean_speed(g);
  const double vref = ref.mean_speed0 > 0 ? ref.mean_speed0 : vmean;
  const SpeedClasses classes = speed_classes(g, vref);
  const auto [mmin, mmax] = m.empty() ? std::pair(1.0, 1.0) : std::pair(*std::min_element(m.begin(), m.end()),
                                                                         *std::max_element(m.begin(), m.end()));
  const double vmax_hist = std::max(3.5 * vmean, 3.0 * vref);
  nlohmann::json j = {{"time", double(s.time)},
                      {"events", s.events},
                      {"disks", n},
                      {"lx", s.lx},
                      {"ly", s.ly},
                      {"periodic", s.boundary == BoundaryKind::Periodic},
                      {"species_names", s.species_names},
                      {"kT", kT},
                      {"kT0", ref.kT0},
                      {"mean_speed", vmean},
                      {"mean_speed0", ref.mean_speed0},
                      {"class_speeds", {0.5 * vref, 1.5 * vref}},
                      {"percent", {classes.slow_percent, classes.medium_percent, classes.fast_percent}},
                      {"collisions_per_disk", n ? 2 * extras.collisions / double(n) : 0.0},
                      {"mass", mmin == mmax ? nlohmann::json(mmin) : nlohmann::json(nullptr)},
                      {"speed_hist", histogram_json(v, vmax_hist, 40)},
                      {"energy_hist", histogram_json(e, 6 * kT, 40)}};
  const std::size_t stride = n > max_disks && max_disks > 0 ? (n + max_disks - 1) / max_disks : 1;
  const std::size_t sent = (n + stride - 1) / stride;
  j["stride"] = stride;
  j["sent"] = sent;
  std::string json = j.dump();
  if (!extras.json_fields.empty()) json = json.substr(0, json.size() - 1) + "," + extras.json_fields + "}";
  while (json.size() % 4) json.push_back(' ');

  std::vector<float> x(sent), y(sent), r(sent), sp(sent), species(sent), disp(sent);
  const std::vector<double> xs = s.x.to_doubles(), ys = s.y.to_doubles(), rs = s.radius.to_doubles();
  for (std::size_t k = 0, i = 0; i < n; i += stride, ++k) {
    x[k] = float(xs[i]);
    y[k] = float(ys[i]);
    r[k] = float(rs[i]);
    sp[k] = float(v[i]);
    species[k] = float(s.species[i]);
    double dx = i < ref.x0.size() ? xs[i] - ref.x0[i] : 0, dy = i < ref.y0.size() ? ys[i] - ref.y0[i] : 0;
    if (s.boundary == BoundaryKind::Periodic) {  // the nearest image: a wrapped disk has not moved a box
      dx -= s.lx * std::nearbyint(dx / s.lx);
      dy -= s.ly * std::nearbyint(dy / s.ly);
    }
    disp[k] = float(std::hypot(dx, dy));
  }
  std::string out = "EDEF";
  out.reserve(8 + json.size() + 4 + 24 * sent);
  append_u32(out, std::uint32_t(json.size()));
  out += json;
  append_u32(out, std::uint32_t(sent));
  for (const auto* col : {&x, &y, &r, &sp, &species, &disp}) append_floats(out, *col);
  return out;
}

}  // namespace ede::view
