// Dots blended into a frame after GL has drawn it: the contact dots of a dense frame (hundreds to
// tens of thousands, each a few pixels across). llvmpipe sets up a fan of triangles for each at every
// sample position, which cost a 720p frame of a 210-box pile a quarter of its drawing and one of a
// 5,050-box pile two fifths (render/README.md); here a dot costs its few pixels, once.
//
// Coverage is taken at 16 positions a pixel (a 4×4 grid), of the true disc: smoother than the four
// samples of a polygon. A run of consecutive dots of one color covers each sample once, as GL's
// opaque fans do, so two dots on one corner are one dot's color where they overlap.
#pragma once

#include <vector>

#include "render/draw/color.h"
#include "render/draw/image.h"
#include "sim/core/math.h"

namespace render::draw {

class DotLayer {
 public:
  // a disc about `center` (output pixels, x to the right, y down from the top-left corner: pixel
  // (i, j) covers [i, i + 1) × [j, j + 1)), `radius` pixels, in `color` at its alpha
  void add(const sim::core::Vec2& center, double radius, const Color& color);
  bool empty() const { return dots_.empty(); }
  void clear() { dots_.clear(); }
  // the dots blended over `frame` (RGBA, opaque) in the order added; its alpha is left alone
  void drawInto(Image& frame) const;

 private:
  struct Dot {
    double x, y, radius;
    Color color;
  };
  std::vector<Dot> dots_;
  // the run dots_[first, last) (one color) drawn into `frame`, `mask` the scratch it reuses
  void drawRun(size_t first, size_t last, Image& frame, std::vector<uint16_t>& mask) const;
};

}  // namespace render::draw
