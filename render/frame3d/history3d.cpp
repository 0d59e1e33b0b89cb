#include "render/frame3d/history3d.h"

namespace render::frame3d {

using sim::world3d::Vec3;
History3d::History3d(const sim::world3d::World& world, Options options)
    : options_(std::move(options)),
      trails_(world.bodies.size()),
      points_(options_.points.size()),
      omegas_(options_.omegaTips.size()) {
  afterStep(world);
}

void History3d::keep(std::vector<Vec3>& path, const Vec3& p, double spacing) {
  // the last point is always the newest: replaced while it stays within the spacing of the one before
  if (path.size() >= 2 && (path[path.size() - 2] - p).norm() < spacing) path.back() = p;
  else path.push_back(p);
}

void History3d::respace(double spacing, double omegaSpacing) {
  options_.spacing = spacing, options_.omegaSpacing = omegaSpacing;
  const auto again = [](std::vector<Vec3>& path, double d) {
    std::vector<Vec3> every = std::move(path);
    path.clear();
    for (const Vec3& p : every) keep(path, p, d);
  };
  for (auto& trail : trails_) again(trail, spacing);
  for (auto& path : points_) again(path, spacing);
  for (auto& path : omegas_) again(path, omegaSpacing);
}

size_t History3d::pathBytes() const {
  size_t total = 0;
  for (const auto* paths : {&trails_, &points_, &omegas_})
    for (const auto& path : *paths) total += path.capacity() * sizeof(Vec3);
  return total;
}

void History3d::afterStep(const sim::world3d::World& world) {
  if (options_.trails)
    for (size_t i = 0; i < world.bodies.size(); ++i) keep(trails_[i], world.bodies[i].x, options_.spacing);
  for (size_t k = 0; k < options_.points.size(); ++k) {
    const auto& [body, point] = options_.points[k];
    keep(points_[k], world.bodies[body].toWorld(point), options_.spacing);
  }
  for (size_t k = 0; k < options_.omegaTips.size(); ++k)
    keep(omegas_[k], world.bodies[options_.omegaTips[k]].omega, options_.omegaSpacing);
}

}  // namespace render::frame3d
