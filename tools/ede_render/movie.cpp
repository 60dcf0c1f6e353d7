// A movie: K frames at evenly spaced times from --from to --to, as PNG files or an MP4.
//
// One LogStates walks forward through the log (each seek continues from the previous frame), so K frames
// cost one pass over the events between them. Frames are frame_00000.png, frame_00001.png, ... in the
// output directory; for an .mp4 they go to a fresh temporary directory, ffmpeg encodes them, and the
// directory is removed. Without ffmpeg on PATH the frames are kept in <name>_frames/ beside the requested
// .mp4, with a warning saying so and how to encode them later; the exit status is still 0. The colour
// scale of --color displacement is fixed for the whole movie (the largest displacement at the last frame,
// found by a second LogStates that seeks there once) so colours mean the same in every frame.
// Rejected: a per-frame scale (colours would flicker as the crater grows) and seeking each frame from
// its nearest keyframe (K times the decoding).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "colouring.hpp"
#include "draw.hpp"
#include "ffmpeg.hpp"
#include "log_states.hpp"
#include "render.hpp"

namespace ede::render {

namespace fs = std::filesystem;

namespace {

std::string frame_name(int k) {
  char b[32];
  std::snprintf(b, sizeof b, "frame_%05d.png", k);
  return b;
}

// The displacement scale of the whole movie: as at its last frame.
Result<double> movie_displacement_scale(const Options& opt, const TimePoint& last, const std::vector<bool>& marked) {
  auto other = LogStates::open(opt.log);
  if (!other) return other.error();
  if (Status s = other.value()->seek(last); !s) return s.error();
  return displacement_scale(other.value()->frame(), marked);
}

Result<std::string> make_temporary_directory() {
  std::string pattern = (fs::temp_directory_path() / "ede-render-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) return Error{"cannot create a temporary directory for the frames"};
  return pattern;
}

Status make_directory(const std::string& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    return Error{"'" + dir + "' exists and is not a directory (movies are written as a directory of PNG frames, "
                 "or an .mp4 file)"};
  fs::create_directories(dir, ec);
  if (ec) return Error{"cannot create the directory '" + dir + "': " + ec.message()};
  return Ok{};
}

struct Target {
  std::string frames_dir;
  bool encode = false;     // .mp4 and ffmpeg found
  bool temporary = false;  // frames_dir is ours to remove
  std::string ffmpeg;
};

Result<Target> choose_target(const Options& opt) {
  Target t;
  if (!ends_with(opt.output, ".mp4")) {
    t.frames_dir = opt.output;
    if (Status s = make_directory(t.frames_dir); !s) return s.error();
    return t;
  }
  if (auto ffmpeg = find_program("ffmpeg")) {
    auto dir = make_temporary_directory();
    if (!dir) return dir.error();
    return Target{dir.value(), true, true, *ffmpeg};
  }
  t.frames_dir = opt.output.substr(0, opt.output.size() - 4) + "_frames";
  if (Status s = make_directory(t.frames_dir); !s) return s.error();
  return t;
}

void warn_stale_frames(const std::string& dir, int frames) {
  if (fs::exists(fs::path(dir) / frame_name(frames)))
    warn("'" + dir + "' also holds frames beyond " + frame_name(frames - 1) + " from an earlier run");
}

int finish(const Options& opt, const Target& target, int frames) {
  const std::string count = std::to_string(frames) + " frame" + (frames == 1 ? "" : "s");
  if (!ends_with(opt.output, ".mp4")) {
    std::printf("wrote %s to %s/\n", count.c_str(), target.frames_dir.c_str());
    return 0;
  }
  if (!target.encode) {
    char rate[32];
    std::snprintf(rate, sizeof rate, "%g", opt.fps);
    warn("ffmpeg is not installed (not found on PATH), so no " + opt.output + " was made; the " + count +
         " are in " + target.frames_dir + "/. Install ffmpeg and run: ffmpeg -framerate " + rate + " -i " +
         target.frames_dir + "/frame_%05d.png -c:v libx264 -pix_fmt yuv420p -vf pad=ceil(iw/2)*2:ceil(ih/2)*2 " +
         opt.output);
    return 0;
  }
  if (Status s = encode_mp4(target.ffmpeg, target.frames_dir, opt.fps, opt.output); !s)
    return fail(s.error().message + "\nthe frames are kept in " + target.frames_dir + "/");
  std::error_code ec;
  fs::remove_all(target.frames_dir, ec);
  std::printf("wrote %s (%s at %g frames/s)\n", opt.output.c_str(), count.c_str(), opt.fps);
  return 0;
}

}  // namespace

int render_movie(const Options& opt) {
  const int frames = *opt.frames;
  auto opened = LogStates::open(opt.log);
  if (!opened) return fail(opened.error().message);
  LogStates& states = *opened.value();
  auto from = states.parse_time(opt.from, "--from");
  if (!from) return fail(from.error().message);
  auto to = states.parse_time(opt.to, "--to");
  if (!to) return fail(to.error().message);
  if (from.value().t > to.value().t) return usage_error("--from " + opt.from + " is after --to " + opt.to);

  if (Status s = states.seek(from.value()); !s) return fail(s.error().message);
  auto marked = marked_disks(states.frame(), opt.mark_species);
  if (!marked) return fail(marked.error().message);
  double scale = opt.max_displacement.value_or(0);
  if (opt.colour == ColourBy::Displacement && !opt.max_displacement) {
    auto found = movie_displacement_scale(opt, to.value(), marked.value());
    if (!found) return fail(found.error().message);
    scale = found.value();
  }

  auto target = choose_target(opt);
  if (!target) return fail(target.error().message);
  const auto give_up = [&](const Error& e) {
    std::error_code ec;
    if (target.value().temporary) fs::remove_all(target.value().frames_dir, ec);
    return fail(e.message);
  };
  for (int k = 0; k < frames; ++k) {
    const long double fraction = frames == 1 ? 0.0L : static_cast<long double>(k) / (frames - 1);
    if (Status s = states.seek(states.between(from.value(), to.value(), fraction)); !s) return give_up(s.error());
    const std::string path = (fs::path(target.value().frames_dir) / frame_name(k)).string();
    if (Status s = write_frame(path, ImageFormat::Png, states.frame(), opt, marked.value(), scale); !s)
      return give_up(s.error());
  }
  if (!target.value().temporary) warn_stale_frames(target.value().frames_dir, frames);
  return finish(opt, target.value(), frames);
}

}  // namespace ede::render
