// ede-render: pictures and movies of a logged run, drawn with cairo from the states replay gives.
//
//   ede-render LOG --at T|end -o FILE.png|FILE.svg [options]                      one picture of the state at T
//   ede-render LOG [--from T0] [--to T1|end] --frames K|--every DT -o DIR|FILE.mp4|FILE.gif [options]  a movie
//   options: --color species|speed|displacement|psi6, --width PIXELS, --species NAME, --mark-species NAME
//            (repeatable), --no-legend, --fps F (movies), --max-displacement D (displacement colour scale)
//
// Thin: parse and check the command line here, then render_still (still.cpp) or render_movie (movie.cpp).
// Every picture comes from a log, never from rerunning the physics. Exit status: 0 success (also a movie
// kept as PNG frames because ffmpeg is missing, with a warning), 1 an input problem, 2 a bad command line.
// Rejected: subcommands (`ede-render still`, `ede-render movie`): --frames or --every already says which
// one is meant.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "tool_main.hpp"
#include "command_line.hpp"
#include "ffmpeg.hpp"
#include "render.hpp"

namespace {

using namespace ede::render;

// A movie target is a directory (any name without an extension), an .mp4 or a .gif file.
bool movie_target_ok(const std::string& path) {
  if (is_encoded_movie(path)) return true;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return true;
  return !std::filesystem::path(path).has_extension();
}

int check_and_run(const Options& opt, const CLI::App& app) {
  if (opt.frames || opt.every) {
    if (!opt.at.empty()) return usage_error("give --at for a picture, or --frames or --every for a movie, not both");
    if (opt.frames && *opt.frames < 1) return usage_error("--frames must be at least 1");
    if (opt.every && !(*opt.every > 0)) return usage_error("--every must be > 0");
    if (!movie_target_ok(opt.output))
      return usage_error("a movie is written to a directory of PNG frames or to an .mp4 or .gif file, not '" + opt.output +
                         "'");
    return render_movie(opt);
  }
  for (const char* name : {"--from", "--to", "--fps"})
    if (app.count(name) > 0) return usage_error(std::string(name) + " is for movies: give --frames K or --every DT too");
  if (opt.at.empty()) return usage_error("give --at T (or --at end) for a picture, or --frames K for a movie");
  if (!format_of(opt.output))
    return usage_error("cannot write '" + opt.output +
                       "': the picture format comes from the extension, .png or .svg (a movie: --frames K)");
  return render_still(opt);
}

}  // namespace

static int run_main(int argc, char** argv) {
  CLI::App app{"ede-render: draw the state of a logged run (PNG or SVG), or a movie of it (PNG frames or MP4)"};
  Options opt;
  app.add_option("log", opt.log, "event log written by ede-sim -o")->required();
  app.add_option("-o,--output", opt.output, "FILE.png or FILE.svg; movies: a directory for the frames, FILE.mp4 or FILE.gif")
      ->required();
  app.add_option("--at", opt.at, "picture: the time T (read exactly in the log's scalar type), or 'end'");
  app.add_option("--from", opt.from, "movie: the first frame's time (default 0)");
  app.add_option("--to", opt.to, "movie: the last frame's time, or 'end' (the default)");
  auto* frames = app.add_option("--frames", opt.frames, "movie: the number of frames, at evenly spaced times");
  auto* every = app.add_option("--every", opt.every, "movie: a frame at --from, --from + DT, ... up to --to");
  frames->excludes(every);
  std::string colour = "species";
  app.add_option("--color,--colour", colour,
                 "species (default), speed (slow < 0.5, fast > 1.5 times the initial mean speed), or "
                 "displacement from t = 0, or psi6 (the local bond order |psi6|, nearest six neighbours)")
      ->check(CLI::IsMember({"species", "speed", "displacement", "psi6"}));
  app.add_option("--width", opt.width, "image width in pixels (SVG: points); the height follows the box")
      ->check(CLI::Range(16, 16384));
  app.add_option("--species", opt.species, "draw only the disks of this species (default: all)");
  app.add_option("--mark-species", opt.mark_species,
                 "outline the disks of this species (repeatable; default: every species with one disk)")
      ->allow_extra_args(false);
  app.add_flag("!--no-legend", opt.legend, "no legend or colour bar (the time label stays)");
  app.add_option("--fps", opt.fps, "movie: frames per second of the MP4 (default 25)")->check(CLI::PositiveNumber);
  app.add_option("--max-displacement", opt.max_displacement,
                 "--color displacement: the displacement at the top of the colour scale (default: the 95th "
                 "percentile of the unmarked disks'; movies: at the last frame)")
      ->check(CLI::PositiveNumber);
  ede::tools::add_version_flags(app, "ede-render");
  if (const auto stop = ede::tools::parse_command_line(app, argc, argv)) return *stop;
  opt.colour = colour == "speed"          ? ColourBy::Speed
               : colour == "displacement" ? ColourBy::Displacement
               : colour == "psi6"         ? ColourBy::Psi6
                                          : ColourBy::Species;
  return check_and_run(opt, app);
}

// Out of memory, a stray exception and a failed stdout become one message and a documented status.
int main(int argc, char** argv) { return ede::tools::run_tool("ede-render", run_main, argc, argv); }
