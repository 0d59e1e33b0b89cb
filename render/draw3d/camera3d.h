// The perspective camera of 3D frames: a pinhole at `eye` looking at `target`, `up` drawn upward,
// a vertical field of view, and a principal point (where the line of sight meets the frame) that
// may sit off the frame's center, so that the content is centered in the part of the frame that
// panels and captions leave free. Projection is ours, not GL's: points go to pixels (for overlays)
// and to clip coordinates (for GL, with identity matrices), by the same numbers.
#pragma once

#include <Eigen/Core>

#include "sim/core/math.h"
#include "sim/world3d/math.h"

namespace render::draw3d {
using Vec4 = Eigen::Vector4d;

// a ball in world coordinates, m
struct Ball {
  sim::world3d::Vec3 center = sim::world3d::Vec3::Zero();
  double radius = 0.0;
};

// an axis-aligned box in world coordinates; empty until something is added
struct Box3d {
  sim::world3d::Vec3 min = sim::world3d::Vec3::Constant(std::numeric_limits<double>::infinity());
  sim::world3d::Vec3 max = sim::world3d::Vec3::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return !(min.x() <= max.x()); }
  void add(const sim::world3d::Vec3& p) { min = min.cwiseMin(p), max = max.cwiseMax(p); }
  void add(const Ball& b) {
    add(b.center - sim::world3d::Vec3::Constant(b.radius)), add(b.center + sim::world3d::Vec3::Constant(b.radius));
  }
  void add(const Box3d& b) {
    if (!b.empty()) add(b.min), add(b.max);
  }
  // the ball through the box's corners (radius 1 m around a point or nothing, so that a view has a scale)
  Ball ball() const;
};

class Camera3d {
 public:
  // depth is the distance along the line of sight; only [nearDepth, farDepth] is drawn
  Camera3d(const sim::world3d::Vec3& eye, const sim::world3d::Vec3& target, const sim::world3d::Vec3& up, double fovDegrees,
           int widthPx, int heightPx, const sim::core::Vec2& principalPx, double nearDepth, double farDepth);

  // the nearest camera that shows all of `content` (its eight corners) looking at its center from
  // along `direction`, with `margin` (a fraction of the free part) on each side, the principal point
  // at the center of the frame's top-left freeWidth × freeHeight pixels
  static Camera3d fit(const Box3d& content, const sim::world3d::Vec3& direction, const sim::world3d::Vec3& up, double fovDegrees,
                      double margin, int widthPx, int heightPx, int freeWidthPx, int freeHeightPx);
  // the camera at `eye` looking at `target`, its depth range holding `content`
  static Camera3d look(const sim::world3d::Vec3& eye, const sim::world3d::Vec3& target, const sim::world3d::Vec3& up,
                       double fovDegrees, int widthPx, int heightPx, const Ball& content);

  // camera coordinates (right, up, depth) of a world point
  sim::world3d::Vec3 toCamera(const sim::world3d::Vec3& world) const { return basis_ * (world - eye_); }
  // the pixel (x right, y down from the top-left corner) of a point in camera coordinates (depth > 0)
  sim::core::Vec2 pixelOf(const sim::world3d::Vec3& camera) const {
    return {principal_.x() + focal_ * camera.x() / camera.z(), principal_.y() - focal_ * camera.y() / camera.z()};
  }
  sim::core::Vec2 toPixel(const sim::world3d::Vec3& world) const { return pixelOf(toCamera(world)); }
  // clip coordinates (x, y, z, w) for GL of the pixel at `depth`: w = depth, z mapping [near, far] to [−1, 1]
  Vec4 clipOf(const sim::core::Vec2& pixel, double depth) const;
  Vec4 clip(const sim::world3d::Vec3& world) const;
  // pixels per meter at `depth`
  double pixelsPerMeter(double depth) const { return focal_ / depth; }
  // the height of the world the frame shows at the target's depth, m: arrow scales refer to it
  double viewHeight() const { return heightPx_ * targetDepth_ / focal_; }
  // a direction in the world as a direction on the frame (pixels, y down), unit or zero
  sim::core::Vec2 screenDirection(const sim::world3d::Vec3& worldDirection) const;

  const sim::world3d::Vec3& eye() const { return eye_; }
  const sim::world3d::Mat3& basis() const { return basis_; }  // rows: right, up, forward (world)
  int widthPx() const { return widthPx_; }
  int heightPx() const { return heightPx_; }
  double nearDepth() const { return near_; }
  double farDepth() const { return far_; }
  double focalPx() const { return focal_; }

 private:
  sim::world3d::Vec3 eye_;
  sim::world3d::Mat3 basis_;
  double focal_;  // pixels: half the frame height over tan(fov/2)
  int widthPx_, heightPx_;
  sim::core::Vec2 principal_;
  double near_, far_, targetDepth_;
};

}  // namespace render::draw3d
