#include "render/frame3d/occlusion.h"

#include <algorithm>
#include <cmath>

namespace render::frame3d {
using namespace sim::world3d;

namespace {

// whether the segment o + s d, s in [0, 1] (body frame), meets the box of half sides h (slabs,
// Ericson 5.3.3)
bool segmentMeetsBox(const Vec3& o, const Vec3& d, const Vec3& h) {
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(d[i]) < 1e-300) {
      if (std::abs(o[i]) > h[i]) return false;
      continue;
    }
    double s0 = (-h[i] - o[i]) / d[i], s1 = (h[i] - o[i]) / d[i];
    if (s0 > s1) std::swap(s0, s1);
    lo = std::max(lo, s0), hi = std::min(hi, s1);
    if (lo > hi) return false;
  }
  return true;
}

// whether the segment o + s d, s in [0, 1], meets the unit ball (Ericson 5.3.2)
bool segmentMeetsUnitBall(const Vec3& o, const Vec3& d) {
  const double a = d.squaredNorm(), b = o.dot(d), c = o.squaredNorm() - 1.0;
  if (c <= 0.0) return true;
  if (a == 0.0) return false;
  // the closest point of the line, clamped to the segment
  const double s = std::clamp(-b / a, 0.0, 1.0);
  return (o + s * d).squaredNorm() <= 1.0;
}

}  // namespace

bool hiddenByBodies(const Vec3& eye, const Vec3& point, const std::vector<Body>& bodies, double skinAtMost) {
  for (const Body& body : bodies) {
    double skin = skinAtMost;
    // the segment in the body's frame
    const sim::world3d::Mat3 r = body.rotation();
    const Vec3 o = r.transpose() * (eye - body.x), d = r.transpose() * (point - eye);
    // at most a quarter of the body's least half-size, so that a small body can still hide
    const double smallest = body.shape.kind == ShapeKind::Box      ? 0.5 * body.shape.sides.minCoeff()
                            : body.shape.kind == ShapeKind::Sphere ? body.shape.radius
                                                                   : body.shape.semiAxes.minCoeff();
    skin = std::min(skin, 0.25 * smallest);
    switch (body.shape.kind) {
      case ShapeKind::Box: {
        const Vec3 h = (0.5 * body.shape.sides.array() - skin).max(0.0).matrix();
        if (segmentMeetsBox(o, d, h)) return true;
        break;
      }
      case ShapeKind::Sphere: {
        const double radius = std::max(body.shape.radius - skin, 0.0);
        if (radius > 0.0 && segmentMeetsUnitBall(o / radius, d / radius)) return true;
        break;
      }
      case ShapeKind::Ellipsoid: {
        const Vec3 axes = (body.shape.semiAxes.array() - skin).max(0.0).matrix();
        if (axes.minCoeff() > 0.0 && segmentMeetsUnitBall(o.cwiseQuotient(axes), d.cwiseQuotient(axes))) return true;
        break;
      }
    }
  }
  return false;
}

}  // namespace render::frame3d
