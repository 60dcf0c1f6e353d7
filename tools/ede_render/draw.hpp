// Drawing one picture with cairo: the box and the disks to scale, marks, then the annotations.
//
// The image is the box: `width` pixels for lx, the same scale for ly (height = round(width * ly / lx)),
// y pointing up as in the simulation. A disk is one path, a circle of radius r - w/2 filled and stroked
// with a darker edge of width w, so the painted disk has radius r exactly and touching disks stay apart
// to the eye; cairo anti-aliases it. Periodic boxes draw every image of a disk that reaches into the box
// (a disk across an edge shows on both sides), clipped to the box. PNG comes from an image surface, SVG
// from an SVG surface of the same size in points: one drawing function for both.
// Rejected: a margin around the box for the legend (the picture would no longer be the box to scale;
// the legend and label sit in corners on translucent panels instead) and drawing disks as fixed-size
// markers (wrong sizes in polydisperse scenes and craters).
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "colouring.hpp"
#include "ede/error.hpp"
#include "frames.hpp"
#include "render.hpp"

namespace ede::render {

struct ImageSize {
  int width = 0, height = 0;
};

// The image size for a frame at `width` pixels; an error if the box's aspect makes it unreasonable.
Result<ImageSize> image_size(const Frame& f, int width);

struct Picture {
  const Frame& frame;
  const Colouring& colouring;
  const std::vector<bool>& marked;
  ImageSize size;
  bool legend = true;
};

Status write_picture(const std::string& path, ImageFormat format, const Picture& p);

// A frame coloured and drawn as the options say: what a still and every movie frame do.
Status write_frame(const std::string& path, ImageFormat format, const Frame& f, const Options& opt,
                   const std::vector<bool>& marked, double max_displacement);

// The outline of a marked disk of radius r (pixels) at (cx, cy): also used for its legend swatch.
void draw_mark(cairo_t* cr, double cx, double cy, double r);

// The annotations (annotate.cpp): time and N in the top-left corner, the legend or colour bar top right.
void draw_label(cairo_t* cr, const Frame& f, ImageSize size);
void draw_legend(cairo_t* cr, const Colouring& c, ImageSize size);

}  // namespace ede::render
