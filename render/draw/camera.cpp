#include "render/draw/camera.h"

namespace render::draw {

using sim::core::Vec2;
Camera::Camera(const Vec2& center, double worldHeight, int widthPx, int heightPx)
    : center_(center), worldHeight_(worldHeight), widthPx_(widthPx), heightPx_(heightPx) {}

Camera Camera::fit(const Bounds& bounds, double margin, int widthPx, int heightPx) {
  // a view of a single point (or of nothing) has no scale of its own: show 2 m around it
  constexpr double kDefaultHeight = 2.0;
  const double aspect = static_cast<double>(widthPx) / heightPx;
  if (bounds.empty()) return Camera(Vec2::Zero(), kDefaultHeight, widthPx, heightPx);
  const Vec2 size = bounds.size();
  // the content's height once widened to the frame's aspect, then grown so it fills 1 − 2·margin
  double height = std::max(size.y(), size.x() / aspect) / (1.0 - 2.0 * margin);
  if (!(height > 0.0)) height = kDefaultHeight;
  return Camera(bounds.center(), height, widthPx, heightPx);
}

Bounds Camera::view() const {
  const Vec2 half(0.5 * worldWidth(), 0.5 * worldHeight_);
  Bounds b;
  b.add(center_ - half);
  b.add(center_ + half);
  return b;
}

Vec2 Camera::toPixel(const Vec2& world) const {
  const double s = 1.0 / pixelSize();
  return {0.5 * widthPx_ + (world.x() - center_.x()) * s, 0.5 * heightPx_ - (world.y() - center_.y()) * s};
}

Vec2 Camera::toWorld(const Vec2& pixel) const {
  const double s = pixelSize();
  return {center_.x() + (pixel.x() - 0.5 * widthPx_) * s, center_.y() - (pixel.y() - 0.5 * heightPx_) * s};
}

}  // namespace render::draw
