// One frame of the view: a State packed for the page as one binary response, a small JSON header with
// the monitors and histograms, then the columns the page draws, in one of two packings:
//
//   "EDEF" | u32 json_bytes | JSON (spaces to a multiple of 8 bytes from the start) | u32 n | u32 0 |
//   the columns JSON "columns" lists, in its order, each padded to 8 bytes  (little-endian, as every
//   machine ede-view runs on)
//
// - compact (the default; 5 bytes a disk, 7 with mixed radii): x and y as u16 fixed point over the box
//   (q = round(65535 x / lx): 1/65535 of the box, a hundredth of a pixel on the page), the radius as u16
//   of the largest radius only when the disks' radii differ (else one number in the JSON), and one u8 per
//   disk for the colouring the page asked for (?colour=): the speed class (0 slow, 1 medium, 2 fast), the
//   species index (mod 256), the displacement in 255ths of the largest one sent, or the bonded cluster
//   (0 alone, else 1 + (rank - 1) mod 255, rank 1 the largest: clusters.hpp), with the cluster count, the
//   largest cluster's size and the disks alone in the JSON.
// - exact (?exact=1): x, y and radius as float64, exactly the State's numbers (float and double runs;
//   long double runs rounded to double), and the same colour byte: what the tests compare with
//   `ede-replay --at`.
// Above `max_disks` only every k-th disk is sent (k = ceil(N / max_disks), said in the JSON as "stride"),
// while the monitors and histograms are computed over every disk. Rejected: float32 columns of x, y, r,
// speed, species and displacement for every colouring (24 bytes a disk: the server's packing and copying
// of 2.4 MB frames bounded 10^5 disks at ~10 frames/s), JSON per disk (10^5 disks would be ~6 MB of text
// per frame), and WebSockets (cpp-httplib has none; a fetch per frame paced by the page is as fast on
// localhost and lets any number of tabs watch without the server tracking them).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "clusters.hpp"
#include "ede/state.hpp"

namespace ede::view {

// What a frame compares against: the state its displacement is measured from and the initial averages
// GasLab's monitors show (speed classes are against the initial mean speed); and what bonds disks into
// clusters, from the scene's steps.
struct Reference {
  std::vector<double> x0, y0;
  double mean_speed0 = 0, kT0 = 0;
  BondRadii bonds;
};
Reference make_reference(const State& initial, const std::vector<PairSteps>& steps);

// Extra monitors the caller knows (a live run's events per second, a log's path); added to the JSON as is.
struct FrameExtras {
  std::string json_fields;  // "\"key\":value,..." without braces, or ""
  double collisions = 0;    // pair collisions up to this state (for collisions per disk)
};

enum class Colouring : std::uint8_t { Speed, Species, Displacement, Clusters };

// What the page asks for (?max=, ?exact=, ?colour=).
struct FrameRequest {
  std::size_t max_disks = 200000;
  bool exact = false;
  Colouring colour = Colouring::Speed;
  bool operator==(const FrameRequest&) const = default;
};
// The request's packing from its query values ("speed", "species", "displacement", "clusters"; "0"/"1"),
// or the message naming the bad value.
Result<FrameRequest> frame_request(std::size_t max_disks, const std::string& exact, const std::string& colour);
// Why frames of this reference cannot be packed as asked ("" when they can): clusters without a well.
std::string colouring_refused(const FrameRequest& request, const Reference& ref);

// The monitors and histograms over every disk (the frame's costly part: several passes and copies of
// every velocity), as JSON fields, with the speed the classes are measured against.
struct FrameStatistics {
  std::string json_fields;     // "\"kT\":...,\"speed_hist\":{...},..." without braces
  double time = 0;             // of the state they were computed from ("statistics_time" in the JSON)
  double reference_speed = 0;  // the initial mean speed (the current one when that is 0)
};
FrameStatistics frame_statistics(const State& s, const Reference& ref);

// A frame of `s` with statistics computed from it, or given (a live run reuses those of a state a few
// milliseconds older at large N: ede/live_run.hpp).
std::string pack_frame(const State& s, const Reference& ref, const FrameExtras& extras, const FrameRequest& request);
std::string pack_frame(const State& s, const Reference& ref, const FrameExtras& extras, const FrameRequest& request,
                       const FrameStatistics& statistics);

// ,"segments":[[ax,ay,bx,by],...] for FrameExtras::json_fields: the scene's wall segments, which the page
// draws over the disks ("" when the scene has none, so other frames keep their bytes).
std::string segments_field(const Scene& scene);

}  // namespace ede::view
