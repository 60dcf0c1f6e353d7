// Encoding PNG frames into an MP4 with ffmpeg, run as a child process without a shell.
//
// ffmpeg is optional: find_program looks it up on PATH first, so the caller can fall back to keeping the
// frames with a clear warning. The child gets its arguments through execv (file names with spaces or
// quotes are safe), stdin from /dev/null (ffmpeg would otherwise read keystrokes), and its stderr is
// captured for the error message. The video is H.264 in yuv420p, which needs even dimensions: a pad filter
// adds one white row or column when the frames are odd, so the frames themselves stay the box to scale.
// Rejected: linking libavcodec (a large dependency for an optional feature) and system() (a shell between
// us and the file names).
#pragma once

#include <optional>
#include <string>

#include "ede/error.hpp"

namespace ede::render {

// The full path of an executable `name` on PATH, if there is one.
std::optional<std::string> find_program(const std::string& name);

// Encodes frames_dir/frame_%05d.png at `fps` frames per second into `output` (overwritten).
Status encode_mp4(const std::string& ffmpeg, const std::string& frames_dir, double fps, const std::string& output);

}  // namespace ede::render
