// The box, the disks (with their periodic images) and the marks; surfaces and files. See draw.hpp.
#include "draw.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace ede::render {

namespace {

constexpr double kTau = 6.283185307179586;
constexpr int kMaxPixels = 16384;  // per side: cairo's image surfaces stop at 32767

struct Mapping {  // simulation coordinates -> pixels
  double scale = 1, ly = 1;
  double x(double v) const { return v * scale; }
  double y(double v) const { return (ly - v) * scale; }
};

// Every offset (in box lengths) at which an image of the disk reaches into the box.
std::vector<std::pair<double, double>> images(const Frame& f, std::size_t i) {
  if (!f.periodic) return {{0.0, 0.0}};
  std::vector<std::pair<double, double>> out;
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b) {
      const double x = f.x[i] + a * f.lx, y = f.y[i] + b * f.ly, r = f.r[i];
      if (x + r > 0 && x - r < f.lx && y + r > 0 && y - r < f.ly) out.emplace_back(a * f.lx, b * f.ly);
    }
  return out;
}

void draw_disk(cairo_t* cr, double cx, double cy, double r, const Rgb& fill) {
  const double edge = std::min(1.0, 0.12 * r);
  cairo_new_path(cr);
  cairo_arc(cr, cx, cy, std::max(r - edge / 2, 0.0), 0, kTau);
  cairo_set_source_rgb(cr, fill.r, fill.g, fill.b);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, fill.r * 0.55, fill.g * 0.55, fill.b * 0.55);
  cairo_set_line_width(cr, edge);
  cairo_stroke(cr);
}

void draw_box(cairo_t* cr, const Frame& f, const Mapping& m) {
  const double w = std::max(1.5, m.x(f.lx) / 400);
  cairo_new_path(cr);
  cairo_rectangle(cr, w / 2, w / 2, m.x(f.lx) - w, m.y(0) - w);
  cairo_set_line_width(cr, f.periodic ? w / 2 : w);
  if (f.periodic) {  // no walls: a light dashed edge
    const double dash[] = {4 * w, 3 * w};
    cairo_set_dash(cr, dash, 2, 0);
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
  } else {
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
}

// Wall segments: dark lines as thick as the box's walls, with round ends (the end points are walls too).
void draw_segments(cairo_t* cr, const Frame& f, const Mapping& m) {
  if (f.segments.empty()) return;
  const double w = std::max(1.5, m.x(f.lx) / 400);
  cairo_set_line_width(cr, w);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  for (const auto& s : f.segments) {
    cairo_move_to(cr, m.x(s[0]), m.y(s[1]));
    cairo_line_to(cr, m.x(s[2]), m.y(s[3]));
  }
  cairo_stroke(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
}

void draw_scene(cairo_t* cr, const Picture& p) {
  const Frame& f = p.frame;
  const Mapping m{p.size.width / f.lx, f.ly};
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_save(cr);
  cairo_rectangle(cr, 0, 0, m.x(f.lx), m.y(0));
  cairo_clip(cr);
  for (std::size_t i = 0; i < f.size(); ++i)
    for (const auto& [ox, oy] : images(f, i))
      draw_disk(cr, m.x(f.x[i] + ox), m.y(f.y[i] + oy), f.r[i] * m.scale, p.colouring.fill[i]);
  for (std::size_t i = 0; i < f.size(); ++i)  // after every disk, so neighbours never cover a mark
    if (p.marked[i])
      for (const auto& [ox, oy] : images(f, i)) draw_mark(cr, m.x(f.x[i] + ox), m.y(f.y[i] + oy), f.r[i] * m.scale);
  draw_segments(cr, f, m);
  cairo_restore(cr);
  draw_box(cr, f, m);
  draw_label(cr, f, p.size);
  if (p.legend) draw_legend(cr, p.colouring, p.size);
}

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

Status cairo_error(const std::string& path, cairo_status_t s) {
  return Error{"cannot write '" + path + "': " + cairo_status_to_string(s)};
}

}  // namespace

Result<ImageSize> image_size(const Frame& f, int width) {
  if (width < 16 || width > kMaxPixels)
    return Error{"--width " + std::to_string(width) + " is out of range (16 to " + std::to_string(kMaxPixels) + ")"};
  const double height = std::round(width * f.ly / f.lx);
  if (!(height >= 1 && height <= kMaxPixels))
    return Error{"the box (" + std::to_string(f.lx) + " x " + std::to_string(f.ly) + ") at --width " +
                 std::to_string(width) + " would be " + std::to_string(height) + " pixels high; choose another width"};
  return ImageSize{width, int(height)};
}

void draw_mark(cairo_t* cr, double cx, double cy, double r) {
  cairo_new_path(cr);
  if (r >= 4) {  // a black ring along the edge with a white one inside: visible on light and dark fills
    const double w = std::clamp(0.18 * r, 1.5, 4.0);
    cairo_arc(cr, cx, cy, r - w / 2, 0, kTau);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, w);
    cairo_stroke(cr);
    cairo_arc(cr, cx, cy, r - w - w / 4, 0, kTau);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_set_line_width(cr, w / 2);
    cairo_stroke(cr);
  } else {  // too small to outline inside: a black ring around it
    cairo_arc(cr, cx, cy, r + 2.5, 0, kTau);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);
  }
}

Status write_picture(const std::string& path, ImageFormat format, const Picture& p) {
  SurfacePtr surface(format == ImageFormat::Svg
                         ? cairo_svg_surface_create(path.c_str(), p.size.width, p.size.height)
                         : cairo_image_surface_create(CAIRO_FORMAT_RGB24, p.size.width, p.size.height),
                     &cairo_surface_destroy);
  if (cairo_status_t s = cairo_surface_status(surface.get()); s != CAIRO_STATUS_SUCCESS) return cairo_error(path, s);
  {
    ContextPtr cr(cairo_create(surface.get()), &cairo_destroy);
    draw_scene(cr.get(), p);
    if (cairo_status_t s = cairo_status(cr.get()); s != CAIRO_STATUS_SUCCESS) return cairo_error(path, s);
  }
  if (format == ImageFormat::Png)
    if (cairo_status_t s = cairo_surface_write_to_png(surface.get(), path.c_str()); s != CAIRO_STATUS_SUCCESS)
      return cairo_error(path, s);
  cairo_surface_finish(surface.get());
  if (cairo_status_t s = cairo_surface_status(surface.get()); s != CAIRO_STATUS_SUCCESS) return cairo_error(path, s);
  return Ok{};
}

Status write_frame(const std::string& path, ImageFormat format, const Frame& f, const Options& opt,
                   const std::vector<bool>& marked, double max_displacement) {
  auto size = image_size(f, opt.width);
  if (!size) return size.error();
  const Colouring colouring = colour_disks(f, opt.colour, marked, max_displacement);
  return write_picture(path, format, Picture{f, colouring, marked, size.value(), opt.legend});
}

}  // namespace ede::render
