// Annotations: the time and N label (top left), the legend or displacement colour bar (top right).
//
// Both sit on translucent white panels over the box, sized from the text cairo measures, with a font size
// proportional to the image width so a thumbnail and a poster read alike. Text uses cairo's toy API with a
// sans-serif face (fontconfig picks DejaVu Sans on Debian); the picture needs a few short lines, not
// shaping. Rejected: pango (a second dependency for a handful of labels).
#include <algorithm>
#include <cmath>

#include "draw.hpp"
#include "ede/number_text.hpp"

namespace ede::render {

namespace {

struct Style {
  double font = 12, pad = 6, row = 17;
  explicit Style(ImageSize s) {
    font = std::clamp(s.width * 0.02, 9.0, 36.0);
    pad = 0.5 * font;
    row = 1.45 * font;
  }
};

double text_width(cairo_t* cr, const std::string& s) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  return e.x_advance;
}

// Text whose vertical middle is at y.
void text_at(cairo_t* cr, double x, double y, const std::string& s) {
  cairo_font_extents_t fe;
  cairo_font_extents(cr, &fe);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_move_to(cr, x, y + (fe.ascent - fe.descent) / 2);
  cairo_show_text(cr, s.c_str());
}

void panel(cairo_t* cr, double x, double y, double w, double h, double radius) {
  cairo_new_path(cr);
  cairo_arc(cr, x + w - radius, y + radius, radius, -M_PI / 2, 0);
  cairo_arc(cr, x + w - radius, y + h - radius, radius, 0, M_PI / 2);
  cairo_arc(cr, x + radius, y + h - radius, radius, M_PI / 2, M_PI);
  cairo_arc(cr, x + radius, y + radius, radius, M_PI, 3 * M_PI / 2);
  cairo_close_path(cr);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.88);
  cairo_fill_preserve(cr);
  cairo_set_source_rgba(cr, 0.3, 0.3, 0.3, 0.6);
  cairo_set_line_width(cr, 1);
  cairo_stroke(cr);
}

void set_font(cairo_t* cr, const Style& st) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, st.font);
}

void swatch(cairo_t* cr, const LegendEntry& e, double cx, double cy, double r) {
  if (e.swatch == LegendEntry::Swatch::None) return;
  cairo_new_path(cr);
  cairo_arc(cr, cx, cy, r, 0, 2 * M_PI);
  cairo_set_source_rgb(cr, e.colour.r, e.colour.g, e.colour.b);
  cairo_fill(cr);
  if (e.swatch == LegendEntry::Swatch::Ring) draw_mark(cr, cx, cy, r);
}

struct BarLayout {
  double width = 0, height = 0;
};

BarLayout bar_layout(cairo_t* cr, const ColourBar& bar, const Style& st) {
  const double w = std::max(text_width(cr, bar.title), 9 * st.font);
  return {w, st.row + 0.8 * st.font + st.row};  // title, gradient, tick labels
}

void draw_bar(cairo_t* cr, const ColourBar& bar, const Style& st, double x, double y, double w) {
  text_at(cr, x, y + st.row / 2, bar.title);
  const double gy = y + st.row, gh = 0.8 * st.font;
  cairo_pattern_t* g = cairo_pattern_create_linear(x, 0, x + w, 0);
  for (int k = 0; k <= 16; ++k) {
    const Rgb c = displacement_colour(k / 16.0);
    cairo_pattern_add_color_stop_rgb(g, k / 16.0, c.r, c.g, c.b);
  }
  cairo_new_path(cr);
  cairo_rectangle(cr, x, gy, w, gh);
  cairo_set_source(cr, g);
  cairo_fill_preserve(cr);
  cairo_pattern_destroy(g);
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  cairo_set_line_width(cr, 1);
  cairo_stroke(cr);
  for (int k = 0; k <= 2; ++k) {
    const std::string t = k == 0 ? "0" : brief(bar.max * k / 2, 3) + (k == 2 && bar.open_top ? "+" : "");
    const double tx = x + w * k / 2, tw = text_width(cr, t);
    cairo_new_path(cr);
    cairo_move_to(cr, tx, gy + gh);
    cairo_line_to(cr, tx, gy + gh + 0.25 * st.font);
    cairo_stroke(cr);
    text_at(cr, std::clamp(tx - tw / 2, x, x + w - tw), gy + gh + st.row / 2 + 0.2 * st.font, t);
  }
}

}  // namespace

void draw_label(cairo_t* cr, const Frame& f, ImageSize size) {
  const Style st(size);
  set_font(cr, st);
  const std::string text = "t = " + brief(double(f.time), 4) + "    N = " + std::to_string(f.size());
  const double w = text_width(cr, text) + 2 * st.pad, h = st.row + st.pad;
  panel(cr, st.pad, st.pad, w, h, st.pad / 2);
  text_at(cr, 2 * st.pad, st.pad + h / 2, text);
}

void draw_legend(cairo_t* cr, const Colouring& c, ImageSize size) {
  const Style st(size);
  set_font(cr, st);
  const double sw = 1.3 * st.font;  // swatch column
  double w = 0;
  for (const LegendEntry& e : c.legend)
    w = std::max(w, (e.swatch == LegendEntry::Swatch::None ? 0 : sw) + text_width(cr, e.text));
  BarLayout bar;
  if (c.bar) bar = bar_layout(cr, *c.bar, st);
  w = std::max(w, bar.width);
  if (w == 0) return;
  const double h = c.legend.size() * st.row + bar.height + st.pad * (c.bar && !c.legend.empty() ? 3 : 2);
  const double x = size.width - w - 3 * st.pad, y = st.pad;
  panel(cr, x, y, w + 2 * st.pad, h, st.pad / 2);
  double row_y = y + st.pad;
  if (c.bar) {
    draw_bar(cr, *c.bar, st, x + st.pad, row_y, w);
    row_y += bar.height + st.pad;
  }
  for (const LegendEntry& e : c.legend) {
    const double mid = row_y + st.row / 2;
    swatch(cr, e, x + st.pad + 0.45 * st.font, mid, 0.42 * st.font);
    text_at(cr, x + st.pad + (e.swatch == LegendEntry::Swatch::None ? 0 : sw), mid, e.text);
    row_y += st.row;
  }
}

}  // namespace ede::render
