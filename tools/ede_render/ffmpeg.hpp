// Encoding PNG frames into an MP4 or an animated GIF with ffmpeg, run as a child process through
// run_program (process.hpp).
//
// ffmpeg is found on PATH first (find_program; the README's set-up installs it), so the movie can fall back
// to keeping the frames with a clear warning and the command that would encode them, quoted so that it
// pastes into a shell as it is. The MP4 is H.264 in yuv420p, which needs even dimensions: a pad filter
// adds one white row or column when the frames are odd, so the frames themselves stay the box to scale.
// The GIF takes its 256 colours from the frames themselves (palettegen, then paletteuse without dithering:
// the disks' flat colours stay flat). Rejected: linking libavcodec (a large dependency for one call) and
// a GIF writer of our own (ffmpeg's palette is better than a fixed one and it is already needed for MP4).
#pragma once

#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::render {

// .mp4 and .gif: the movie files ffmpeg makes from the frames.
bool is_encoded_movie(const std::string& output);

// The ffmpeg command line that encodes frames_dir/frame_%05d.png at `fps` frames per second into `output`
// (overwritten), chosen by output's extension.
std::vector<std::string> ffmpeg_arguments(const std::string& ffmpeg, const std::string& frames_dir, double fps,
                                          const std::string& output);

// Runs it.
Status encode_movie(const std::string& ffmpeg, const std::string& frames_dir, double fps, const std::string& output);

// The arguments as one line a POSIX shell reads back to the same arguments (each quoted where needed).
std::string shell_command(const std::vector<std::string>& argv);

}  // namespace ede::render
