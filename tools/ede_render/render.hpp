// What the parts of ede-render share: the options, the picture formats, messages, and the two entry
// points (a still picture, a movie).
//
// main.cpp parses the command line into Options; still.cpp and movie.cpp turn a log into files through
// frames (the state at a time as the library's DiskFrame, plain doubles), colouring (what colour each disk
// is, the legend) and draw / annotate (cairo). Exit status: 0 success, 1 an input problem (unreadable log, time beyond its
// end, unwritable output), 2 a command line that asks for something impossible, like ede-replay.
// Rejected: one file doing it all (the placeholder's successor would have been ~800 lines mixing cairo,
// replay and process handling).
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "report_error.hpp"

namespace ede::render {

enum class ColourBy { Species, Speed, Displacement, Psi6 };
enum class ImageFormat { Png, Svg };

struct Options {
  std::string log, output;
  std::string at;                        // a still: a time or "end"
  std::string from = "0", to = "end";    // a movie
  std::optional<int> frames;             // a movie of this many frames, evenly spaced
  std::optional<double> every;           // or a movie of frames from, from + every, ... up to to
  std::string species;                   // only the disks of this species ("": all)
  ColourBy colour = ColourBy::Species;
  int width = 800;                       // pixels (SVG: points)
  std::vector<std::string> mark_species; // empty: every species with exactly one disk
  bool legend = true;
  double fps = 25;
  std::optional<double> max_displacement;  // top of the displacement colour bar (default: the largest)
};

// An error about the input: message on stderr, exit status 1.
inline int fail(const std::string& message) {
  ede::tools::report_error("ede-render", message);
  return 1;
}

// A command line that parsed but asks for something impossible: exit status 2.
inline int usage_error(const std::string& message) {
  std::fprintf(stderr, "ede-render: %s (see ede-render --help)\n", message.c_str());
  return 2;
}

inline void warn(const std::string& message) { std::fprintf(stderr, "ede-render: warning: %s\n", message.c_str()); }

inline bool ends_with(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    const char a = s[s.size() - suffix.size() + i];
    const char lower = (a >= 'A' && a <= 'Z') ? char(a - 'A' + 'a') : a;
    if (lower != suffix[i]) return false;
  }
  return true;
}

// The picture format named by a file's extension (.png or .svg, any case), if it is one.
inline std::optional<ImageFormat> format_of(const std::string& path) {
  if (ends_with(path, ".png")) return ImageFormat::Png;
  if (ends_with(path, ".svg")) return ImageFormat::Svg;
  return std::nullopt;
}

int render_still(const Options& opt);
int render_movie(const Options& opt);

}  // namespace ede::render
