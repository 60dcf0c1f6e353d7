// pack_frame, frame_statistics and make_reference; see frame.hpp. The statistics use the library's gas
// analysis (GasSnapshot, temperature, speed classes, histograms), so the page shows what ede-stats would
// print; the columns are written straight into the response, one pass over the sent disks per column.
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

void append_u32(std::string& out, std::uint32_t v) {
  char b[4];
  std::memcpy(b, &v, 4);
  out.append(b, 4);
}

// A column of the sent disks (every stride-th of n): value(i) of T for disk i, padded to 8 bytes.
template <class T, class Value>
void append_column(std::string& out, std::size_t n, std::size_t stride, Value value) {
  const std::size_t sent = (n + stride - 1) / stride, at = out.size(), bytes = sent * sizeof(T);
  out.resize(at + (bytes + 7) / 8 * 8, '\0');
  char* p = out.data() + at;
  for (std::size_t i = 0; i < n; i += stride, p += sizeof(T)) {
    const T v = value(i);
    std::memcpy(p, &v, sizeof(T));
  }
}

// f(values) with the column's own array (a Column's operator[] dispatches on its type for every element).
template <class F>
void with_values(const Column& c, F f) {
  switch (c.scalar()) {
    case ScalarKind::Float: return f(c.values<float>());
    case ScalarKind::Double: return f(c.values<double>());
    default: return f(c.values<long double>());
  }
}

// v / scale as u16 fixed point, rounded, clamped to [0, 65535].
std::uint16_t fixed16(double v, double scale) {
  const double q = std::nearbyint(v / scale * 65535.0);
  return std::uint16_t(q > 0 ? (q < 65535 ? q : 65535) : 0);
}

}  // namespace

Reference make_reference(const State& initial, const std::vector<PairSteps>& steps) {
  Reference r;
  r.bonds = bond_radii(steps, initial.species_names);
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

Result<FrameRequest> frame_request(std::size_t max_disks, const std::string& exact, const std::string& colour) {
  FrameRequest r;
  r.max_disks = max_disks;
  if (exact == "1" || exact == "true")
    r.exact = true;
  else if (!(exact.empty() || exact == "0" || exact == "false"))
    return Error{"parameter 'exact' must be 1 or 0, not '" + exact.substr(0, 40) + "'"};
  if (colour == "species")
    r.colour = Colouring::Species;
  else if (colour == "displacement")
    r.colour = Colouring::Displacement;
  else if (colour == "clusters")
    r.colour = Colouring::Clusters;
  else if (!(colour.empty() || colour == "speed"))
    return Error{"parameter 'colour' must be speed, species, displacement or clusters, not '" + colour.substr(0, 40) +
                 "'"};
  return r;
}

std::string colouring_refused(const FrameRequest& request, const Reference& ref) {
  return request.colour == Colouring::Clusters ? clusters_unavailable(ref.bonds) : "";
}

FrameStatistics frame_statistics(const State& s, const Reference& ref) {
  const GasSnapshot g = snapshot(s);
  const std::vector<double> v = speeds(g), e = kinetic_energies(g), m = masses(g);
  const double kT = temperature(g), vmean = mean_speed(g);
  FrameStatistics out;
  out.time = double(s.time);
  out.reference_speed = ref.mean_speed0 > 0 ? ref.mean_speed0 : vmean;
  const double vref = out.reference_speed;
  const SpeedClasses classes = speed_classes(g, vref);
  const auto [mmin, mmax] = m.empty() ? std::pair(1.0, 1.0) : std::pair(*std::min_element(m.begin(), m.end()),
                                                                         *std::max_element(m.begin(), m.end()));
  const double vmax_hist = std::max(3.5 * vmean, 3.0 * vref);
  const nlohmann::json j = {{"statistics_time", out.time},
                            {"kT", kT},
                            {"kT0", ref.kT0},
                            {"mean_speed", vmean},
                            {"mean_speed0", ref.mean_speed0},
                            {"class_speeds", {0.5 * vref, 1.5 * vref}},
                            {"percent", {classes.slow_percent, classes.medium_percent, classes.fast_percent}},
                            {"mass", mmin == mmax ? nlohmann::json(mmin) : nlohmann::json(nullptr)},
                            {"speed_hist", histogram_json(v, vmax_hist, 40)},
                            {"energy_hist", histogram_json(e, 6 * kT, 40)}};
  const std::string text = j.dump();
  out.json_fields = text.substr(1, text.size() - 2);
  return out;
}

std::string pack_frame(const State& s, const Reference& ref, const FrameExtras& extras, const FrameRequest& request,
                       const FrameStatistics& statistics) {
  const std::size_t n = s.size(), max_disks = request.max_disks;
  const std::size_t stride = n > max_disks && max_disks > 0 ? (n + max_disks - 1) / max_disks : 1;
  const std::size_t sent = (n + stride - 1) / stride;

  // The sent disks' displacements (the colouring's, and its scale), the nearest image in a periodic box.
  std::vector<double> disp;
  double disp_max = 0;
  if (request.colour == Colouring::Displacement) {
    disp.assign(n, 0.0);
    for (std::size_t i = 0; i < n; i += stride) {
      double dx = i < ref.x0.size() ? s.x[i] - ref.x0[i] : 0, dy = i < ref.y0.size() ? s.y[i] - ref.y0[i] : 0;
      if (s.boundary == BoundaryKind::Periodic) {  // a wrapped disk has not moved a box
        dx -= s.lx * std::nearbyint(dx / s.lx);
        dy -= s.ly * std::nearbyint(dy / s.ly);
      }
      disp[i] = std::hypot(dx, dy);
      disp_max = std::max(disp_max, disp[i]);
    }
  }
  // Every disk's cluster (bonds to disks not sent count too).
  Clusters clusters;
  if (request.colour == Colouring::Clusters) clusters = find_clusters(s, ref.bonds);
  double rmin = 0, rmax = 0;
  with_values(s.radius, [&](const auto& r) {
    for (std::size_t i = 0; i < n; i += stride) {
      rmin = i ? std::min(rmin, double(r[i])) : double(r[i]);
      rmax = i ? std::max(rmax, double(r[i])) : double(r[i]);
    }
  });
  const bool radius_column = request.exact || rmin != rmax;
  const char* position_type = request.exact ? "f64" : "u16";
  nlohmann::json columns = nlohmann::json::array({{"x", position_type}, {"y", position_type}});
  if (radius_column) columns.push_back({"r", position_type});
  columns.push_back({"colour", "u8"});
  const char* colour_names[] = {"speed class", "species", "displacement", "clusters"};
  nlohmann::json j = {{"time", double(s.time)},
                      {"events", s.events},
                      {"disks", n},
                      {"lx", s.lx},
                      {"ly", s.ly},
                      {"periodic", s.boundary == BoundaryKind::Periodic},
                      {"species_names", s.species_names},
                      {"collisions_per_disk", n ? 2 * extras.collisions / double(n) : 0.0},
                      {"stride", stride},
                      {"sent", sent},
                      {"packing", request.exact ? "exact" : "compact"},
                      {"columns", columns},
                      {"colour", {{"by", colour_names[int(request.colour)]}, {"displacement_max", disp_max}}}};
  if (request.colour == Colouring::Clusters)
    j["colour"].update({{"clusters", clusters.count}, {"largest", clusters.largest}, {"alone", clusters.alone},
                        {"bond_radius", ref.bonds.largest}});
  if (!radius_column) j["radius"] = rmax;
  if (!request.exact) j["scale"] = {s.lx / 65535.0, s.ly / 65535.0, rmax / 65535.0};
  std::string json = j.dump();
  json.pop_back();
  json += "," + statistics.json_fields;
  if (!extras.json_fields.empty()) json += "," + extras.json_fields;
  json += "}";
  while (json.size() % 8) json.push_back(' ');  // the columns start 8-byte aligned (float64 in JavaScript)

  std::string out = "EDEF";
  out.reserve(16 + json.size() + (request.exact ? 25 : 7) * sent + 32);
  append_u32(out, std::uint32_t(json.size()));
  out += json;
  append_u32(out, std::uint32_t(sent));
  append_u32(out, 0);
  if (request.exact) {
    for (const Column* c : {&s.x, &s.y, &s.radius})
      with_values(*c, [&](const auto& v) { append_column<double>(out, n, stride, [&](std::size_t i) { return double(v[i]); }); });
  } else {
    const std::pair<const Column*, double> fixed[] = {{&s.x, s.lx}, {&s.y, s.ly}, {&s.radius, rmax}};
    for (std::size_t c = 0; c < (radius_column ? 3u : 2u); ++c) {
      const double scale = fixed[c].second;
      with_values(*fixed[c].first, [&](const auto& v) {
        append_column<std::uint16_t>(out, n, stride, [&](std::size_t i) { return fixed16(double(v[i]), scale); });
      });
    }
  }
  switch (request.colour) {
    case Colouring::Speed: {
      const double vref = statistics.reference_speed;
      with_values(s.vx, [&](const auto& vx) {  // both velocity columns have the run's one type
        with_values(s.vy, [&](const auto& vy) {
          append_column<std::uint8_t>(out, n, stride, [&](std::size_t i) {
            const double x = double(vx[i]), y = double(vy[i]);  // GasSnapshot::speed's formula
            return std::uint8_t(speed_class(std::sqrt(x * x + y * y), vref));
          });
        });
      });
      break;
    }
    case Colouring::Species:
      append_column<std::uint8_t>(out, n, stride, [&](std::size_t i) { return std::uint8_t(s.species[i] & 0xff); });
      break;
    case Colouring::Displacement:
      append_column<std::uint8_t>(out, n, stride, [&](std::size_t i) {
        return disp_max > 0 ? std::uint8_t(std::nearbyint(255 * disp[i] / disp_max)) : std::uint8_t(0);
      });
      break;
    case Colouring::Clusters:
      append_column<std::uint8_t>(out, n, stride, [&](std::size_t i) {
        const std::uint32_t r = clusters.rank[i];
        return r == 0 ? std::uint8_t(0) : std::uint8_t(1 + (r - 1) % 255);
      });
      break;
  }
  return out;
}

std::string pack_frame(const State& s, const Reference& ref, const FrameExtras& extras, const FrameRequest& request) {
  return pack_frame(s, ref, extras, request, frame_statistics(s, ref));
}

}  // namespace ede::view
