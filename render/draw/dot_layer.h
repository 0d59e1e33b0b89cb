// Dots blended into a frame after GL has drawn it: the contact dots of a dense frame (hundreds to
// tens of thousands, each a few pixels across). llvmpipe sets up a fan of triangles for each at every
// sample position, which cost a 720p frame of a 210-box pile a quarter of its drawing and one of a
// 5,050-box pile two fifths (render/README.md); here a dot costs its few pixels, once.
//
// Each dot is the polygon GL would draw (GlCanvas: a regular polygon, a corner at angle 0), its
// coverage taken at the sample positions the frame is drawn at, so that a dot looks the same
// whichever draws it (GlCanvas draws them with GL when GL draws over them): its corners on GL's
// 1/256 px grid, a sample on an edge given by GL's top-left rule. Consecutive opaque dots of one
// color cover each sample once, as GL's opaque fans do; a translucent dot blends over whatever
// lies under it, as each of GL's does.
#pragma once

#include <array>
#include <vector>

#include "render/draw/color.h"
#include "render/draw/image.h"
#include "sim/core/math.h"

namespace render::draw {

// a sample position within a pixel, from its top-left corner, y down (0 to 1 each)
using SamplePosition = std::array<double, 2>;

// the sample positions of a frame drawn at `samples` (1, 2 or 4) a pixel, `supersample` times wider
// and higher, as the output pixel sees them (GlContext)
std::vector<SamplePosition> samplePositions(int samples, int supersample);

class DotLayer {
 public:
  // a regular polygon of `corners` corners (one at angle 0 from `center`), `radius` from its
  // center to each; `center` in output pixels, x to the right, y down from the top-left corner
  // (pixel (i, j) covers [i, i + 1) × [j, j + 1)); in `color` at its alpha
  void add(const sim::core::Vec2& center, double radius, int corners, const Color& color);
  // the dots blended over `frame` (RGBA, opaque) in the order added, each pixel covered in the
  // share of `positions` (at most 16) inside; its alpha is left alone
  void drawInto(Image& frame, const std::vector<SamplePosition>& positions) const;

 private:
  struct Dot {
    double x, y, radius;
    int corners;
    Color color;
  };
  std::vector<Dot> dots_;
  // what drawing the runs of a frame shares and reuses (dot_layer.cpp)
  struct Scratch;
  // the run dots_[first, last) (opaque dots of one color, or one translucent dot) drawn into `frame`
  void drawRun(size_t first, size_t last, Image& frame, Scratch& scratch) const;
};

}  // namespace render::draw
