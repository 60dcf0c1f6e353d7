// Colours, marks and legends; see colouring.hpp.
#include "colouring.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "ede/number_text.hpp"

namespace ede::render {

namespace {

std::string species_name(const Frame& f, int s) {
  return s >= 0 && std::size_t(s) < f.species_names.size() ? f.species_names[std::size_t(s)] : std::to_string(s);
}

std::vector<std::size_t> species_counts(const Frame& f) {
  std::vector<std::size_t> n(f.species_names.size(), 0);
  for (int s : f.species) {
    if (s < 0) continue;
    if (std::size_t(s) >= n.size()) n.resize(std::size_t(s) + 1, 0);
    ++n[std::size_t(s)];
  }
  return n;
}

// The legend line of the marked disks, "projectile (marked)", with a swatch of their fill.
void add_marked_entry(const Frame& f, const std::vector<bool>& marked, const Rgb& swatch, Colouring& c) {
  std::vector<int> shown;
  for (std::size_t i = 0; i < f.size(); ++i)
    if (marked[i] && std::find(shown.begin(), shown.end(), f.species[i]) == shown.end())
      shown.push_back(f.species[i]);
  if (shown.empty()) return;
  std::string names;
  for (int s : shown) names += (names.empty() ? "" : ", ") + species_name(f, s);
  c.legend.push_back({swatch, names + " (marked)", LegendEntry::Swatch::Ring});
}

// Species: one line per species, the marked ones with the outline in their swatch.
void by_species(const Frame& f, const std::vector<bool>& marked, Colouring& c) {
  for (int s : f.species) c.fill.push_back(species_colour(std::size_t(std::max(s, 0))));
  const std::vector<std::size_t> n = species_counts(f);
  std::vector<bool> species_marked(n.size(), false);
  for (std::size_t i = 0; i < f.size(); ++i)
    if (marked[i] && f.species[i] >= 0) species_marked[std::size_t(f.species[i])] = true;
  for (std::size_t s = 0; s < n.size(); ++s) {
    if (n[s] == 0) continue;
    const std::string count = std::to_string(n[s]) + (species_marked[s] ? ", marked" : "");
    c.legend.push_back({species_colour(s), species_name(f, int(s)) + " (" + count + ")",
                        species_marked[s] ? LegendEntry::Swatch::Ring : LegendEntry::Swatch::Disk});
  }
}

// Classes against the initial mean speed; when everything starts at rest (a bed and a projectile falling
// under gravity) there is none, and the frame's own mean speed is the reference instead, said so.
void by_speed(const Frame& f, Colouring& c) {
  double reference = f.initial_mean_speed;
  const bool from_start = reference > 0;
  if (!from_start) {
    double sum = 0;
    for (double v : f.speed) sum += v;
    reference = f.speed.empty() ? 0 : sum / double(f.speed.size());
  }
  std::array<std::size_t, 3> n{};
  for (double v : f.speed) {
    const SpeedClass k = speed_class(v, reference);
    c.fill.push_back(speed_colour(k));
    ++n[std::size_t(k)];
  }
  const std::string bar = from_start ? "v\u0304\u2080" : "v\u0304";
  const std::string names[] = {"slow  v < 0.5 " + bar, "medium", "fast  v > 1.5 " + bar};
  for (std::size_t k = 0; k < 3; ++k)
    c.legend.push_back({speed_colour(SpeedClass(k)), names[k] + "  (" + std::to_string(n[k]) + ")"});
  c.legend.push_back({Rgb{}, bar + " = " + brief(reference, 3) +
                                 (from_start ? " (initial mean speed)" : " (mean speed now: all at rest at t = 0)"),
                      LegendEntry::Swatch::None});
}

// Displacement: marked disks (a projectile, which moves farthest) get a colour outside the map.
void by_displacement(const Frame& f, const std::vector<bool>& marked, double max, Colouring& c) {
  for (std::size_t i = 0; i < f.size(); ++i)
    c.fill.push_back(marked[i] ? marked_colour() : displacement_colour(f.displacement[i] / max));
  c.bar = ColourBar{max, "displacement from t = 0 [L]"};
  add_marked_entry(f, marked, marked_colour(), c);
}

// psi6: |psi6_j| in [0, 1] on the sequential map; 1 is a perfect hexagonal neighbourhood.
void by_psi6(const Frame& f, Colouring& c) {
  for (std::size_t i = 0; i < f.size(); ++i) c.fill.push_back(displacement_colour(i < f.psi6.size() ? f.psi6[i] : 0));
  c.bar = ColourBar{1, "|psi6|, local bond order", false};
}

}  // namespace

Rgb species_colour(std::size_t species) {
  static const unsigned palette[] = {0x0072B2, 0xE69F00, 0x009E73, 0xCC79A7, 0x56B4E9, 0xD55E00, 0xF0E442, 0x000000};
  return Rgb::hex(palette[species % 8]);
}

Rgb marked_colour() { return Rgb::hex(0x0072B2); }

Rgb speed_colour(SpeedClass c) {
  switch (c) {
    case SpeedClass::Slow: return Rgb::hex(0x0072B2);
    case SpeedClass::Medium: return Rgb::hex(0x009E73);
    case SpeedClass::Fast: break;
  }
  return Rgb::hex(0xD55E00);
}

Rgb displacement_colour(double u) {
  static const unsigned stops[] = {0xFFFFCC, 0xFFEDA0, 0xFED976, 0xFEB24C, 0xFD8D3C,
                                   0xFC4E2A, 0xE31A1C, 0xBD0026, 0x800026};
  constexpr int last = int(sizeof stops / sizeof stops[0]) - 1;
  const double x = std::clamp(std::isfinite(u) ? u : 1.0, 0.0, 1.0) * last;
  const int k = std::min(int(x), last - 1);
  const double w = x - k;
  const Rgb a = Rgb::hex(stops[k]), b = Rgb::hex(stops[k + 1]);
  return {a.r + (b.r - a.r) * w, a.g + (b.g - a.g) * w, a.b + (b.b - a.b) * w};
}

Colouring colour_disks(const Frame& f, ColourBy by, const std::vector<bool>& marked, double max_displacement) {
  Colouring c;
  switch (by) {
    case ColourBy::Species: by_species(f, marked, c); break;
    case ColourBy::Speed:
      by_speed(f, c);
      add_marked_entry(f, marked, Rgb{0.85, 0.85, 0.85}, c);
      break;
    case ColourBy::Displacement: by_displacement(f, marked, max_displacement, c); break;
    case ColourBy::Psi6: by_psi6(f, c); break;
  }
  return c;
}

}  // namespace ede::render
