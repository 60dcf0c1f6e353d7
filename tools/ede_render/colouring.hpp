// Colouring: what colour each disk is, which disks are marked, and what the legend says. No cairo here.
//
// Three colourings, each with its own legend:
//   species       Okabe & Ito's colour-blind-safe palette in species order; legend: names and counts;
//   speed         the GasLab classes against v̄0, the initial mean speed: slow (v < 0.5 v̄0) blue, medium
//                 green, fast (v > 1.5 v̄0) vermilion (Okabe-Ito hues for GasLab's blue/green/red); if
//                 every disk starts at rest, against the frame's own mean speed instead;
//   displacement  distance from the initial position on a sequential map (pale yellow -> dark red,
//                 ColorBrewer YlOrRd, readable in grey and with colour-vision deficiencies); a colour bar.
//                 Its top is the 95th percentile of the unmarked disks' displacements: a few far-flung
//                 ejecta would otherwise leave the whole bed pale; larger values take the top colour;
//   psi6          the local bond order |psi6_j| (ede::psi6: nearest six neighbours) on the same map from 0
//                 to 1: ordered (hexatic, crystalline) patches dark, disordered liquid pale; a colour bar.
// Marked disks (a projectile) get an outline when drawn; they keep their species or speed colour, and in
// displacement colouring are blue, outside the map. Which disks are marked, their speed classes and the
// scale's top are the library's (ede/analysis.hpp, "Frames"), so the live view colours alike; the colours
// are plain data so tests and docs can name them. Rejected: a continuous speed map (the course's gas
// figure has three classes, which read at a glance), rainbow maps (not ordered in lightness) and a
// displacement scale up to the largest value.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ede/analysis.hpp"
#include "frames.hpp"
#include "render.hpp"

namespace ede::render {

struct Rgb {
  double r = 0, g = 0, b = 0;
  static Rgb hex(unsigned v) { return {((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0, (v & 255) / 255.0}; }
};

// The species palette (Okabe & Ito 2008), in species order; cycles after eight species.
Rgb species_colour(std::size_t species);
Rgb speed_colour(SpeedClass c);
// The displacement map at u in [0, 1] (clamped).
Rgb displacement_colour(double u);
// The fill of marked disks in displacement colouring.
Rgb marked_colour();

struct LegendEntry {
  enum class Swatch { Disk, Ring, None };  // Ring: the marked disks' outline; None: a line of text
  Rgb colour;
  std::string text;
  Swatch swatch = Swatch::Disk;
};

struct ColourBar {  // displacement and psi6: the map from 0 to max
  double max = 1;
  std::string title;
  bool open_top = true;  // the top label says "max+" (larger values take the top colour)
};

struct Colouring {
  std::vector<Rgb> fill;  // per disk
  std::vector<LegendEntry> legend;
  std::optional<ColourBar> bar;
};

Colouring colour_disks(const Frame& f, ColourBy by, const std::vector<bool>& marked, double max_displacement);

}  // namespace ede::render
