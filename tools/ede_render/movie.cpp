// A movie: K frames at evenly spaced times from --from to --to (or one every DT), as PNG files, an MP4 or a GIF.
//
// One LogFrames walks forward through the log (each frame continues from the previous one), so K frames
// cost one pass over the events between them; the frame times are the library's (evenly_spaced_times,
// times_every: exact in the log's type, computed from their index). Frames are frame_00000.png, frame_00001.png, ... in the
// output directory; for an .mp4 or .gif they go to a fresh temporary directory, ffmpeg encodes them, and the
// directory is removed. Without ffmpeg on PATH the frames are kept in <name>_frames/ beside the requested
// movie file, with a warning saying so and how to encode them later; the exit status is still 0. The colour
// scale of --color displacement is fixed for the whole movie (the scale of the last frame, read before the
// others; going back to the first then costs one keyframe) so colours mean the same in every frame.
// Rejected: a per-frame scale (colours would flicker as the crater grows) and seeking each frame from
// its nearest keyframe (K times the decoding).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "colouring.hpp"
#include "draw.hpp"
#include "ffmpeg.hpp"
#include "frames.hpp"
#include "ede/number_text.hpp"
#include "render.hpp"
#include "process.hpp"

namespace ede::render {

namespace fs = std::filesystem;

namespace {

std::string frame_name(int k) {
  const std::string n = std::to_string(k);
  return "frame_" + std::string(n.size() < 5 ? 5 - n.size() : 0, '0') + n + ".png";
}

constexpr std::size_t kMaxFrames = 1'000'000;

// The frames' times: --frames K evenly spaced, or every DT; the last one is `end` if --to is and it lands there.
Result<std::vector<tools::TimeOption>> frame_times(const Options& opt, const LogFrames& frames,
                                                  const tools::TimeOption& from, const tools::TimeOption& to) {
  const std::vector<Time> times = opt.frames ? evenly_spaced_times(from.t, to.t, std::size_t(*opt.frames), frames.scalar())
                                             : times_every(from.t, to.t, *opt.every, frames.scalar(), kMaxFrames);
  if (times.empty())
    return Error{opt.every ? "--every " + brief(*opt.every) + " gives more than " + std::to_string(kMaxFrames) +
                                 " frames"
                           : std::string("no frames")};
  std::vector<tools::TimeOption> out;
  for (const Time t : times) out.push_back({t, to.end && t == to.t});
  return out;
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
                 "or an .mp4 or .gif file)"};
  fs::create_directories(dir, ec);
  if (ec) return Error{"cannot create the directory '" + dir + "': " + ec.message()};
  return Ok{};
}

struct Target {
  std::string frames_dir;
  bool encode = false;     // .mp4 or .gif, and ffmpeg found
  bool temporary = false;  // frames_dir is ours to remove
  std::string ffmpeg;
};

Result<Target> choose_target(const Options& opt) {
  Target t;
  if (!is_encoded_movie(opt.output)) {
    t.frames_dir = opt.output;
    if (Status s = make_directory(t.frames_dir); !s) return s.error();
    return t;
  }
  if (auto ffmpeg = tools::find_program("ffmpeg")) {
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
  if (!is_encoded_movie(opt.output)) {
    std::printf("wrote %s to %s/\n", count.c_str(), target.frames_dir.c_str());
    return 0;
  }
  if (!target.encode) {
    std::vector<std::string> argv = ffmpeg_arguments("ffmpeg", target.frames_dir, opt.fps, opt.output);
    argv.erase(argv.begin() + 1, argv.begin() + 6);  // -nostdin ... -y: for the child process, not for people
    warn("ffmpeg is not installed (not found on PATH), so no " + opt.output + " was made; the " + count +
         " are in " + target.frames_dir + "/. Install ffmpeg (apt-get install ffmpeg, or scripts/install-deps.sh) "
         "and run:\n  " + shell_command(argv));
    return 0;
  }
  if (Status s = encode_movie(target.ffmpeg, target.frames_dir, opt.fps, opt.output); !s)
    return fail(s.error().message + "\nthe frames are kept in " + target.frames_dir + "/");
  std::error_code ec;
  fs::remove_all(target.frames_dir, ec);
  std::printf("wrote %s (%s at %s frames/s)\n", opt.output.c_str(), count.c_str(), brief(opt.fps).c_str());
  return 0;
}

}  // namespace

int render_movie(const Options& opt) {
  auto opened = LogFrames::open(opt.log, opt.species);
  if (!opened) return fail(opened.error().message);
  LogFrames& frames = opened.value();
  auto from = frames.read_time(opt.from, "--from");
  if (!from) return fail(from.error().message);
  auto to = frames.read_time(opt.to, "--to");
  if (!to) return fail(to.error().message);
  if (from.value().t > to.value().t) return usage_error("--from " + opt.from + " is after --to " + opt.to);
  auto times = frame_times(opt, frames, from.value(), to.value());
  if (!times) return usage_error(times.error().message);

  auto first = frames.at(times.value().front());
  if (!first) return fail(first.error().message);
  auto marked = marked_disks(first.value(), opt.mark_species);
  if (!marked) return fail(opt.log + ": --mark-species: " + marked.error().message);
  double scale = opt.max_displacement.value_or(0);
  if (opt.colour == ColourBy::Displacement && !opt.max_displacement) {
    auto last = frames.at(times.value().back());
    if (!last) return fail(last.error().message);
    scale = displacement_scale(last.value(), marked.value());
  }

  auto target = choose_target(opt);
  if (!target) return fail(target.error().message);
  const auto give_up = [&](const Error& e) {
    std::error_code ec;
    if (target.value().temporary) fs::remove_all(target.value().frames_dir, ec);
    return fail(e.message);
  };
  const int count = int(times.value().size());
  for (int k = 0; k < count; ++k) {
    auto frame = frames.at(times.value()[std::size_t(k)], opt.colour == ColourBy::Psi6);
    if (!frame) return give_up(frame.error());
    const std::string path = (fs::path(target.value().frames_dir) / frame_name(k)).string();
    if (Status s = write_frame(path, ImageFormat::Png, frame.value(), opt, marked.value(), scale); !s)
      return give_up(s.error());
  }
  if (!target.value().temporary) warn_stale_frames(target.value().frames_dir, count);
  return finish(opt, target.value(), count);
}

}  // namespace ede::render
