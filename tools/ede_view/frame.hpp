// One frame of the view: a State packed for the page as one binary response, a small JSON header with
// the monitors and histograms, then float32 columns the page hands straight to its canvas drawing.
//
//   "EDEF" | u32 json_bytes | JSON (padded with spaces to 4 bytes) | u32 n | f32 x[n] y[n] r[n] speed[n]
//   species[n] displacement[n]        (little-endian, as every machine ede-view runs on)
//
// Above `max_disks` only every k-th disk is sent (k = ceil(N / max_disks), said in the JSON as "stride"),
// while the monitors and histograms are computed over every disk. Rejected: JSON per disk (10^5 disks
// would be ~6 MB of text per frame and the browser's parse alone would take longer than a frame), and
// WebSockets (cpp-httplib has none; a fetch per frame paced by the page is as fast on localhost and lets
// any number of tabs watch without the server tracking them).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ede/state.hpp"

namespace ede::view {

// What a frame compares against: the state its displacement is measured from and the initial averages
// GasLab's monitors show (speed classes are against the initial mean speed).
struct Reference {
  std::vector<double> x0, y0;
  double mean_speed0 = 0, kT0 = 0;
};
Reference make_reference(const State& initial);

// Extra monitors the caller knows (a live run's events per second, a log's path); added to the JSON as is.
struct FrameExtras {
  std::string json_fields;  // "\"key\":value,..." without braces, or ""
  double collisions = 0;    // pair collisions up to this state (for collisions per disk)
};

std::string pack_frame(const State& s, const Reference& ref, const FrameExtras& extras, std::size_t max_disks);

// ,"segments":[[ax,ay,bx,by],...] for FrameExtras::json_fields: the scene's wall segments, which the page
// draws over the disks ("" when the scene has none, so other frames keep their bytes).
std::string segments_field(const Scene& scene);

}  // namespace ede::view
