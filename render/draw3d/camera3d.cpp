#include "render/draw3d/camera3d.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace render::draw3d {

using sim::core::Vec2;
using sim::world3d::Vec3;
namespace {

// the depth range a ball needs, seen from `distance` away: a little more than the ball on each
// side; a camera inside the ball draws from a thousandth of its reach
std::pair<double, double> depthRange(double distance, double radius) {
  const double reach = distance + radius;
  return {std::max(0.9 * (distance - radius), 1e-3 * reach), 1.1 * reach};
}

}  // namespace

Ball Box3d::ball() const {
  if (empty()) return {Vec3::Zero(), 1.0};
  const double r = 0.5 * (max - min).norm();
  return {0.5 * (min + max), r > 0.0 ? r : 1.0};
}

Camera3d::Camera3d(const Vec3& eye, const Vec3& target, const Vec3& up, double fovDegrees, int widthPx, int heightPx,
                   const Vec2& principalPx, double nearDepth, double farDepth)
    : eye_(eye),
      focal_(0.5 * heightPx / std::tan(0.5 * fovDegrees * std::numbers::pi / 180.0)),
      widthPx_(widthPx),
      heightPx_(heightPx),
      principal_(principalPx),
      near_(nearDepth),
      far_(farDepth) {
  const Vec3 forward = (target - eye).normalized();
  const Vec3 right = forward.cross(up).normalized();
  basis_.row(0) = right.transpose();
  basis_.row(1) = right.cross(forward).transpose();
  basis_.row(2) = forward.transpose();
  targetDepth_ = (target - eye).norm();
}

Camera3d Camera3d::fit(const Box3d& content, const Vec3& direction, const Vec3& up, double fovDegrees, double margin, int widthPx,
                       int heightPx, int freeWidthPx, int freeHeightPx) {
  const Ball ball = content.ball();
  const Box3d box = content.empty() ? [&] { Box3d b; b.add(ball); return b; }() : content;
  // the view's axes, from the eye toward the content's center
  const Camera3d axes(ball.center + direction.normalized(), ball.center, up, fovDegrees, widthPx, heightPx, Vec2::Zero(), 1.0,
                      2.0);
  const double focal = axes.focal_;
  // the half-sizes of the free part the content may fill, px
  const double halfWidth = (1.0 - 2.0 * margin) * 0.5 * freeWidthPx, halfHeight = (1.0 - 2.0 * margin) * 0.5 * freeHeightPx;
  // a corner c (camera axes, from the center) seen from distance d lies within the free part when
  // f |c_x| / (d + c_z) ≤ halfWidth and f |c_y| / (d + c_z) ≤ halfHeight: the least such d for all
  // eight corners, and always in front of the nearest
  double distance = 0.0, nearest = 0.0;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1 ? box.max : box.min).x(), (k & 2 ? box.max : box.min).y(), (k & 4 ? box.max : box.min).z());
    const Vec3 c = axes.basis_ * (corner - ball.center);
    distance = std::max(distance, std::max(focal * std::abs(c.x()) / halfWidth, focal * std::abs(c.y()) / halfHeight) - c.z());
    nearest = std::max(nearest, -c.z());
  }
  distance = std::max(distance, 1.05 * nearest + 1e-9);
  const auto [nearDepth, farDepth] = depthRange(distance, ball.radius);
  return Camera3d(ball.center + distance * direction.normalized(), ball.center, up, fovDegrees, widthPx, heightPx,
                  Vec2(0.5 * freeWidthPx, 0.5 * freeHeightPx), nearDepth, farDepth);
}

Camera3d Camera3d::look(const Vec3& eye, const Vec3& target, const Vec3& up, double fovDegrees, int widthPx, int heightPx,
                        const Ball& content) {
  const auto [nearDepth, farDepth] = depthRange((content.center - eye).norm(), content.radius);
  return Camera3d(eye, target, up, fovDegrees, widthPx, heightPx, Vec2(0.5 * widthPx, 0.5 * heightPx), nearDepth, farDepth);
}

Vec4 Camera3d::clipOf(const Vec2& pixel, double depth) const {
  // normalized device coordinates from pixels (GL's y up), times w = depth
  const double x = 2.0 * pixel.x() / widthPx_ - 1.0, y = 1.0 - 2.0 * pixel.y() / heightPx_;
  const double a = (far_ + near_) / (far_ - near_), b = -2.0 * far_ * near_ / (far_ - near_);
  return {x * depth, y * depth, a * depth + b, depth};
}

Vec4 Camera3d::clip(const Vec3& world) const {
  // clipOf(pixelOf(c), depth) multiplied out: linear in c, so that it holds behind the eye too and GL
  // clips triangles that cross the near plane
  const Vec3 c = toCamera(world);
  const double a = (far_ + near_) / (far_ - near_), b = -2.0 * far_ * near_ / (far_ - near_);
  return {(2.0 * principal_.x() / widthPx_ - 1.0) * c.z() + 2.0 * focal_ * c.x() / widthPx_,
          (1.0 - 2.0 * principal_.y() / heightPx_) * c.z() + 2.0 * focal_ * c.y() / heightPx_, a * c.z() + b, c.z()};
}

Vec2 Camera3d::screenDirection(const Vec3& d) const {
  const Vec3 c = basis_ * d;
  const Vec2 s(c.x(), -c.y());
  return s.norm() > 0.0 ? Vec2(s.normalized()) : Vec2::Zero();
}

}  // namespace render::draw3d
