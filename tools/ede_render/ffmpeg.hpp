// Encoding PNG frames into an MP4 with ffmpeg, run as a child process through run_program (spawn.hpp).
//
// ffmpeg is optional: the movie looks it up on PATH first (find_program), so it can fall back to keeping
// the frames with a clear warning. The video is H.264 in yuv420p, which needs even dimensions: a pad
// filter adds one white row or column when the frames are odd, so the frames themselves stay the box to
// scale. Rejected: linking libavcodec (a large dependency for an optional feature).
#pragma once

#include <string>

#include "ede/error.hpp"

namespace ede::render {

// Encodes frames_dir/frame_%05d.png at `fps` frames per second into `output` (overwritten).
Status encode_mp4(const std::string& ffmpeg, const std::string& frames_dir, double fps, const std::string& output);

}  // namespace ede::render
