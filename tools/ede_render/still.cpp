// A still picture: the state at --at T (or end) of a log, to one PNG or SVG file.
//
// Reads the log through LogFrames (replay from the nearest keyframe), resolves the marked species, sets
// the displacement scale from this very state unless --max-displacement fixes it, and draws. Rejected:
// drawing from ede-replay's CSV (an extra file and a second program for every picture).
#include <cstdio>

#include "colouring.hpp"
#include "draw.hpp"
#include "file_checks.hpp"
#include "frames.hpp"
#include "output_file.hpp"
#include "render.hpp"

namespace ede::render {

int render_still(const Options& opt) {
  const auto format = format_of(opt.output);
  auto frames = LogFrames::open(opt.log, opt.species);
  if (!frames) return fail(frames.error().message);
  auto at = frames.value().read_time(opt.at, "--at");
  if (!at) return fail(at.error().message);
  auto frame = frames.value().at(at.value(), opt.colour == ColourBy::Psi6);
  if (!frame) return fail(frame.error().message);
  const Frame& f = frame.value();
  auto marked = marked_disks(f, opt.mark_species);
  if (!marked) return fail(opt.log + ": --mark-species: " + marked.error().message);
  const double scale = opt.max_displacement.value_or(displacement_scale(f, marked.value()));
  // Drawn to a temporary beside the target (same extension: cairo picks the format from the name) and
  // renamed into place when complete; never over the log it was drawn from.
  if (Status s = tools::check_not_an_input(opt.output); !s) return fail(s.error().message);
  const std::string temp = tools::temporary_name(opt.output);
  if (Status s = write_frame(temp, *format, f, opt, marked.value(), scale); !s) {
    std::remove(temp.c_str());
    return fail("cannot write '" + opt.output + "' (drawn to " + temp + " first): " + s.error().message);
  }
  if (Status s = tools::commit_temporary(temp, opt.output); !s) return fail(s.error().message);
  std::printf("wrote %s (t = %s, %zu disks)\n", opt.output.c_str(), frames.value().time_text(f.time).c_str(), f.size());
  return 0;
}

}  // namespace ede::render
