// The orthographic camera: world units, y up, a frame of width × height pixels. Either fitted over
// everything a run covers (with a margin, keeping the frame's aspect) or a fixed center and height.
#pragma once

#include <algorithm>
#include <limits>

#include "sim/core/math.h"

namespace render::draw {

// an axis-aligned box in world coordinates; empty until something is added
struct Bounds {
  sim::core::Vec2 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  sim::core::Vec2 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  bool empty() const { return !(min.x() <= max.x() && min.y() <= max.y()); }
  void add(const sim::core::Vec2& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void add(const Bounds& b) {
    if (b.empty()) return;
    add(b.min);
    add(b.max);
  }
  sim::core::Vec2 size() const { return max - min; }
  sim::core::Vec2 center() const { return 0.5 * (min + max); }
};

class Camera {
 public:
  // the world point `center` at the middle of the frame, `worldHeight` meters from bottom to top
  Camera(const sim::core::Vec2& center, double worldHeight, int widthPx, int heightPx);
  // the smallest view of the frame's aspect that holds `bounds` with `margin` (a fraction of the view)
  // free on each side; an empty or point-like box gets a view 2 m high around it
  static Camera fit(const Bounds& bounds, double margin, int widthPx, int heightPx);

  const sim::core::Vec2& center() const { return center_; }
  double worldHeight() const { return worldHeight_; }
  double worldWidth() const { return worldHeight_ * widthPx_ / heightPx_; }
  int widthPx() const { return widthPx_; }
  int heightPx() const { return heightPx_; }
  // world length of one pixel
  double pixelSize() const { return worldHeight_ / heightPx_; }
  // the world rectangle the frame shows
  Bounds view() const;
  // pixel coordinates: x to the right, y down from the top-left corner of the frame
  sim::core::Vec2 toPixel(const sim::core::Vec2& world) const;
  sim::core::Vec2 toWorld(const sim::core::Vec2& pixel) const;

 private:
  sim::core::Vec2 center_;
  double worldHeight_;
  int widthPx_, heightPx_;
};

}  // namespace render::draw
