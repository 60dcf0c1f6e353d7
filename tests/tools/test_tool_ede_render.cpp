// ede-render as a user runs it: pictures of tiny hand-made logs checked pixel by pixel, SVG paths counted,
// periodic images, movies (PNG frames, MP4 when ffmpeg is installed, a warning when it is not), and clear
// errors on bad input.
//
// Logs come from ede-sim on small scenes with explicit positions and velocities, so every disk's place at
// the drawn time is known. PNGs are read back with cairo itself, the library ede-render draws with.
#include <cairo.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "tool_runner.hpp"

using namespace ede::test;
namespace fs = std::filesystem;

namespace {

// A PNG read back with cairo.
class Png {
 public:
  explicit Png(const std::string& path) : surface_(cairo_image_surface_create_from_png(path.c_str())) {
    INFO(path);
    REQUIRE(cairo_surface_status(surface_) == CAIRO_STATUS_SUCCESS);
  }
  ~Png() { cairo_surface_destroy(surface_); }
  Png(const Png&) = delete;
  Png& operator=(const Png&) = delete;

  int width() const { return cairo_image_surface_get_width(surface_); }
  int height() const { return cairo_image_surface_get_height(surface_); }
  // 0xRRGGBB at pixel (px, py) (cairo's RGB24 and ARGB32 pixels are native-endian 32-bit words).
  unsigned rgb(int px, int py) const {
    REQUIRE(px >= 0);
    REQUIRE(py >= 0);
    REQUIRE(px < width());
    REQUIRE(py < height());
    const unsigned char* data = cairo_image_surface_get_data(surface_);
    const std::size_t stride = std::size_t(cairo_image_surface_get_stride(surface_));
    std::uint32_t v;
    std::memcpy(&v, data + std::size_t(py) * stride + std::size_t(px) * 4, 4);
    return v & 0xFFFFFF;
  }

 private:
  cairo_surface_t* surface_;
};

// The palette the docs name (docs/pictures.md).
constexpr unsigned kFirstSpecies = 0x0072B2, kSecondSpecies = 0xE69F00;
constexpr unsigned kSlow = 0x0072B2, kFast = 0xD55E00, kBackground = 0xFFFFFF;
constexpr unsigned kNotMoved = 0xFFFFCC, kMarked = 0x0072B2;

// A 2 x 1 box with walls: two "bed" disks (r = 0.1) at rest at (0.4, 0.3) and (0.8, 0.3), one "ball"
// (r = 0.15) from (1.5, 0.6) at velocity (-0.2, 0): at t = 1 it is at (1.3, 0.6). No collision.
const char* const kTinyScene = R"([box]
size = [2.0, 1.0]
[[species]]
name = "bed"
radius = 0.1
[species.placement]
kind = "explicit"
positions = [[0.4, 0.3], [0.8, 0.3]]
[[species]]
name = "ball"
radius = 0.15
[species.placement]
kind = "explicit"
positions = [[1.5, 0.6]]
[species.velocity]
kind = "list"
values = [[-0.2, 0.0]]
[stop]
time = 1.0
)";

// A periodic unit box: one disk (r = 0.1) at rest across the left edge at (0.02, 0.5), one at the centre.
const char* const kWrapScene = R"([box]
size = [1.0, 1.0]
boundary = "periodic"
[[species]]
name = "gas"
radius = 0.1
[species.placement]
kind = "explicit"
positions = [[0.02, 0.5], [0.5, 0.5]]
[stop]
time = 1.0
)";

// A hexagon: one disk (r = 0.1) at (0.5, 0.5) with six at distance 0.25 at angles 0, 60, ..., 300 degrees:
// the centre's |psi6| is 1 (to round-off), the outer ones' less.
const char* const kHexagonScene = R"([box]
size = [2.0, 1.0]
[[species]]
name = "hex"
radius = 0.1
[species.placement]
kind = "explicit"
positions = [[0.5, 0.5], [0.75, 0.5], [0.625, 0.7165063509461096], [0.37500000000000006, 0.7165063509461097], [0.25, 0.5], [0.3749999999999999, 0.2834936490538904], [0.625, 0.28349364905389035]]
[stop]
time = 1.0
)";

std::string make_log(const std::string& name, const char* scene_text) {
  const std::string scene = temp_path("render-" + name + ".toml");
  std::ofstream(scene) << scene_text;
  return sim_log(scene, "", temp_path("render-" + name + ".ede"), "render-sim-" + name);
}

ToolRun render(const std::string& args, const std::string& tag) { return run_tool("ede-render", args, "render-" + tag); }

// Pixel of a simulation point in an image of a box of height ly at `scale` pixels per unit.
std::pair<int, int> pixel(double x, double y, double scale, double ly) {
  return {int(std::floor(x * scale)), int(std::floor((ly - y) * scale))};
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// cairo's SVG spelling of an 8-bit colour, as in style="fill:rgb(0%,44.705882%,69.803922%)": percentages
// printed with six decimals, trailing zeros dropped.
std::string svg_fill(unsigned rgb) {
  const auto pct = [](unsigned c) {
    char b[32];
    std::snprintf(b, sizeof b, "%f", c * 100.0 / 255.0);
    std::string s = b;
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s + "%";
  };
  return "fill:rgb(" + pct(rgb >> 16) + "," + pct((rgb >> 8) & 255) + "," + pct(rgb & 255) + ")";
}

bool have_ffmpeg() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string dirs = path;
  for (std::size_t start = 0; start <= dirs.size();) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    if (::access((dirs.substr(start, end - start) + "/ffmpeg").c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

}  // namespace

TEST_CASE("ede-render draws each disk in its species' colour at its place, to scale", "[tool][ede-render]") {
  const std::string log = make_log("species", kTinyScene);
  const std::string png = temp_path("render-species.png");
  const ToolRun r = render(log + " --at 1 --width 400 --no-legend -o " + png, "species");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Png image(png);
  CHECK(image.width() == 400);
  CHECK(image.height() == 200);  // the 2 x 1 box at 200 pixels per unit
  const double scale = 200;
  const auto at = [&](double x, double y) {
    const auto [px, py] = pixel(x, y, scale, 1.0);
    return image.rgb(px, py);
  };
  CHECK(at(0.4, 0.3) == kFirstSpecies);
  CHECK(at(0.8, 0.3) == kFirstSpecies);
  CHECK(at(1.3, 0.6) == kSecondSpecies);  // the ball moved from x = 1.5 (and is marked: outline at its edge)
  CHECK(at(1.5, 0.6) == kBackground);     // where it started
  CHECK(at(1.0, 0.15) == kBackground);
  CHECK(at(0.4 + 0.085, 0.3) == kFirstSpecies);  // radius 0.1 = 20 pixels: inside at 17, outside at 22
  CHECK(at(0.4 + 0.11, 0.3) == kBackground);
}

TEST_CASE("ede-render --width sets the image size and the box sets its aspect", "[tool][ede-render]") {
  const std::string log = make_log("size", kTinyScene);
  for (int width : {100, 333, 1000}) {
    const std::string png = temp_path("render-size-" + std::to_string(width) + ".png");
    const ToolRun r = render(log + " --at end --width " + std::to_string(width) + " -o " + png, "size");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const Png image(png);
    CHECK(image.width() == width);
    CHECK(image.height() == int(std::lround(width / 2.0)));
  }
}

TEST_CASE("ede-render --color speed puts slow and fast disks in their classes' colours", "[tool][ede-render]") {
  // Initial mean speed (0 + 0 + 0.2) / 3 = 0.067: the ball (0.2 > 1.5 x 0.067) is fast, the bed at rest slow.
  const std::string log = make_log("speed", kTinyScene);
  const std::string png = temp_path("render-speed.png");
  const ToolRun r = render(log + " --at 1 --width 400 --color speed -o " + png, "speed");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Png image(png);
  CHECK(image.rgb(260, 80) == kFast);  // (1.3, 0.6)
  CHECK(image.rgb(80, 140) == kSlow);  // (0.4, 0.3)
  CHECK(image.rgb(160, 140) == kSlow);
}

TEST_CASE("ede-render --color displacement: resting disks at the map's bottom, the projectile apart",
          "[tool][ede-render]") {
  const std::string log = make_log("displacement", kTinyScene);
  const std::string png = temp_path("render-displacement.png");
  const ToolRun r = render(log + " --at 1 --width 400 --color displacement -o " + png, "displacement");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Png image(png);
  CHECK(image.rgb(80, 140) == kNotMoved);  // the bed at rest
  CHECK(image.rgb(160, 140) == kNotMoved);
  CHECK(image.rgb(260, 80) == kMarked);    // the ball, a one-disk species: marked, blue
}

TEST_CASE("ede-render --color psi6: a perfect hexagonal neighbourhood at the map's top, others below",
          "[tool][ede-render]") {
  const std::string log = make_log("psi6", kHexagonScene);
  const std::string png = temp_path("render-psi6.png");
  const ToolRun r = render(log + " --at 0 --width 400 --color psi6 -o " + png, "psi6");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Png image(png);
  CHECK(image.rgb(100, 100) == 0x800026);  // the centre, |psi6| = 1: the map's top (docs/pictures.md)
  const unsigned outer = image.rgb(150, 100);  // (0.75, 0.5)
  CHECK(outer != 0x800026);
  CHECK(outer != kBackground);
}

TEST_CASE("ede-render writes SVG with one path per disk", "[tool][ede-render]") {
  const std::string log = make_log("svg", kTinyScene);
  const std::string svg = temp_path("render.svg");
  const ToolRun r = render(log + " --at 1 --no-legend -o " + svg, "svg");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::string text = read_file(svg);
  REQUIRE(text.find("<svg") != std::string::npos);
  INFO(svg_fill(kFirstSpecies));
  CHECK(count(text, svg_fill(kFirstSpecies)) == 2);   // the two bed disks
  CHECK(count(text, svg_fill(kSecondSpecies)) == 1);  // the ball
}

TEST_CASE("ede-render draws a disk across a periodic edge on both sides", "[tool][ede-render]") {
  const std::string log = make_log("wrap", kWrapScene);
  const std::string png = temp_path("render-wrap.png");
  const ToolRun r = render(log + " --at end --width 200 --no-legend -o " + png, "wrap");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Png image(png);
  // Centre (0.02, 0.5) = pixel (4, 100), radius 20 pixels: the right edge shows x in [0.92, 1).
  CHECK(image.rgb(10, 100) == kFirstSpecies);
  CHECK(image.rgb(194, 100) == kFirstSpecies);
  CHECK(image.rgb(175, 100) == kBackground);
  CHECK(image.rgb(194, 60) == kBackground);
  CHECK(image.rgb(100, 100) == kFirstSpecies);
}

TEST_CASE("ede-render makes movies: PNG frames, MP4 and animated GIF with ffmpeg", "[tool][ede-render]") {
  const std::string log = make_log("movie", kTinyScene);
  const std::string dir = temp_path("render-frames");
  fs::remove_all(dir);
  const ToolRun r = render(log + " --from 0 --to 1 --frames 3 --width 200 --no-legend -o " + dir, "movie");
  INFO(r.err);
  REQUIRE(r.status == 0);
  for (const char* frame : {"frame_00000.png", "frame_00001.png", "frame_00002.png"}) {
    INFO(frame);
    CHECK(fs::file_size(fs::path(dir) / frame) > 0);
  }
  CHECK_FALSE(fs::exists(fs::path(dir) / "frame_00003.png"));
  {  // the ball at t = 0.5 is at x = 1.4: pixel (140, 40) at 100 pixels per unit
    const Png middle((fs::path(dir) / "frame_00001.png").string());
    CHECK(middle.rgb(140, 40) == kSecondSpecies);
  }
  fs::remove_all(dir);

  // The README's set-up installs ffmpeg (scripts/install-deps.sh): movies must work after it.
  if (!have_ffmpeg()) FAIL("ffmpeg is not on PATH: scripts/install-deps.sh installs it (apt-get install ffmpeg)");
  const std::string mp4 = temp_path("render-movie.mp4");
  const ToolRun v = render(log + " --frames 3 --fps 5 --width 101 -o " + mp4, "mp4");  // odd width: padded
  INFO(v.err);
  REQUIRE(v.status == 0);
  const std::string video = read_file(mp4);
  CHECK(video.size() > 100);
  CHECK(video.substr(4, 4) == "ftyp");  // an MP4 (ISO base media) file
  const std::string gif_path = temp_path("render-movie.gif");
  const ToolRun g = render(log + " --frames 3 --fps 5 --width 101 -o " + gif_path, "gif");
  INFO(g.err);
  REQUIRE(g.status == 0);
  const std::string gif = read_file(gif_path);
  REQUIRE(gif.size() > 13);
  CHECK(gif.substr(0, 6) == "GIF89a");
  CHECK((unsigned char)gif[6] + 256 * (unsigned char)gif[7] == 101);  // the frames' width: no padding in a GIF
  CHECK(gif.find("NETSCAPE2.0") != std::string::npos);                // an animation that loops
}

TEST_CASE("ede-render --every: frames at from, from + DT, ... up to --to, and --to end is the log's end",
          "[tool][ede-render]") {
  const std::string log = make_log("every", kTinyScene);
  const std::string dir = temp_path("render-every");
  fs::remove_all(dir);
  const ToolRun r = render(log + " --from 0.25 --to end --every 0.25 --width 200 --no-legend -o " + dir, "every");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("wrote 4 frames") != std::string::npos);  // t = 0.25, 0.5, 0.75, 1
  CHECK_FALSE(fs::exists(fs::path(dir) / "frame_00004.png"));
  {  // the last frame is t = 1: the ball at x = 1.3, pixel (130, 40) at 100 pixels per unit
    const Png last((fs::path(dir) / "frame_00003.png").string());
    CHECK(last.rgb(130, 40) == kSecondSpecies);
    CHECK(last.rgb(148, 40) == kBackground);
  }
  fs::remove_all(dir);
}

TEST_CASE("ede-render --species draws only the disks of that species", "[tool][ede-render]") {
  const std::string log = make_log("only", kTinyScene);
  const std::string png = temp_path("render-only.png");
  const ToolRun r = render(log + " --at 1 --width 400 --no-legend --species ball -o " + png, "only");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("1 disks") != std::string::npos);
  const Png image(png);
  CHECK(image.rgb(260, 80) == kSecondSpecies);  // the ball keeps its species colour
  CHECK(image.rgb(80, 140) == kBackground);     // the bed is not drawn
  CHECK(image.rgb(160, 140) == kBackground);
}

TEST_CASE("ede-render keeps the frames with a warning when ffmpeg is missing", "[tool][ede-render]") {
  const std::string log = make_log("noffmpeg", kTinyScene);
  const std::string mp4 = temp_path("render-noffmpeg.mp4"), frames = temp_path("render-noffmpeg_frames");
  fs::remove_all(frames);
  const std::string err = temp_path("render-noffmpeg.err");
  const std::string cmd = "PATH=/nonexistent " + tool_path("ede-render") + " " + log + " --frames 2 --width 100 -o " +
                          mp4 + " >/dev/null 2>" + err;
  const int raw = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 0);
  CHECK(read_file(err).find("ffmpeg is not installed") != std::string::npos);
  CHECK(fs::exists(fs::path(frames) / "frame_00001.png"));
  CHECK_FALSE(fs::exists(mp4));
  // The warning's command pastes into bash as it is (the ffmpeg filter's parentheses are quoted).
  const std::string text = read_file(err);
  const std::string marker = "and run:\n  ";
  const std::size_t at = text.find(marker);
  REQUIRE(at != std::string::npos);
  const std::size_t from = at + marker.size();
  const std::string suggested = text.substr(from, text.find('\n', from) - from);
  INFO(suggested);
  CHECK(suggested.starts_with("ffmpeg "));
  const std::string script = temp_path("render-noffmpeg.sh");
  { std::ofstream(script) << suggested << "\n"; }
  CHECK(std::system(("bash -n " + script).c_str()) == 0);
  if (have_ffmpeg()) {
    CHECK(std::system(("bash " + script + " >/dev/null 2>&1").c_str()) == 0);
    CHECK(fs::file_size(mp4) > 0);
    fs::remove(mp4);
  }
  fs::remove_all(frames);
}

TEST_CASE("ede-render rejects bad input with a clear message and a non-zero exit", "[tool][ede-render]") {
  const std::string log = make_log("bad", kTinyScene), png = temp_path("render-bad.png");
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {temp_path("no-such-log.ede") + " --at 0 -o " + png, "no-such-log.ede"},
      {log + " --at 2 -o " + png, "after the end of the log"},
      {log + " --at soon -o " + png, "--at 'soon' is not a time"},
      {log + " --at 1 --mark-species comet -o " + png, "--mark-species: the log has no species 'comet'"},
      {log + " --at 1 --species comet -o " + png, "--species: the log has no species 'comet'; its species are: bed, ball"},
      {log + " --frames 2 --to 7 -o " + temp_path("render-bad-late"), "--to 7 is after the end of the log (t = 1)"},
      {log + " --every 0 -o " + temp_path("render-bad-every"), "--every must be > 0"},
      {log + " --every 0.1 --frames 2 -o " + temp_path("render-bad-both"), "excludes"},
      {log + " --at 1 -o " + temp_path("render-bad.jpg"), ".png or .svg"},
      {log + " -o " + png, "give --at"},
      {log + " --at 1 --frames 3 -o " + temp_path("render-bad-dir"), "not both"},
      {log + " --frames 3 -o " + png, "directory of PNG frames or to an .mp4"},
      {log + " --at 1 --color rainbow -o " + png, "rainbow"},
      {log + " --at 1 -o " + temp_path("no-such-dir") + "/x.png", "cannot write"},
  };
  for (const Case& c : cases) {
    const ToolRun r = render(c.args, "bad");
    INFO(c.args << "\n" << r.err);
    CHECK(r.status != 0);
    CHECK(r.err.find(c.message) != std::string::npos);
  }
}

TEST_CASE("ede-render: a bad command line exits with status 2 and CLI11's message, --help with 0",
          "[tool][ede-render]") {
  const std::string log = temp_path("render-any.ede"), png = temp_path("render-any.png");
  const ToolRun flag = render(log + " --at 1 --no-such-flag -o " + png, "bad-flag");
  CHECK(flag.status == 2);
  CHECK(flag.err.find("--no-such-flag") != std::string::npos);
  CHECK(render(log + " --at 1 --width 3 -o " + png, "bad-width").status == 2);
  CHECK(render(log + " --at 1", "no-output").status == 2);
  CHECK(render("--help", "help").status == 0);
  const ToolRun version = render("--version", "version");
  CHECK(version.status == 0);
  CHECK(version.out.rfind("ede-render, ede ", 0) == 0);
}

TEST_CASE("ede-render draws the scene's wall segments", "[tool][ede-render][segment]") {
  // The tiny scene with a vertical segment at x = 1.1 from y = 0.1 to 0.5 (clear of every disk).
  const std::string text = std::string(kTinyScene) + "[[walls.segments]]\nfrom = [1.1, 0.1]\nto = [1.1, 0.5]\n";
  const std::string log = make_log("segments", text.c_str());
  const std::string png = temp_path("render-segments.png");
  const ToolRun r = render(log + " --at 1 --width 400 --no-legend -o " + png, "segments");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Png image(png);
  const auto at = [&](double x, double y) {
    const auto [px, py] = pixel(x, y, 200, 1.0);
    return image.rgb(px, py);
  };
  CHECK(at(1.1, 0.3) != kBackground);  // on the segment: a dark line
  CHECK(at(1.1, 0.7) == kBackground);  // beyond its end
  CHECK(at(1.2, 0.3) == kBackground);
}
