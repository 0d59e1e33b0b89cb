#include "render/analysis/pyramid_rows.h"

#include <cmath>

namespace render::analysis {
using namespace sim::core;
using namespace sim::collision;

using sim::core::Vec2;
using sim::scene::BodyDef;

namespace {

// a listed box is where the pattern puts it when within this fraction of the spacing (the scenes'
// coordinates are written to a few decimals)
constexpr double kPlaceTolerance = 1e-6;

// the same box but for its name and place: shape, mass properties, material and motion
bool likeFirst(const BodyDef& b, const BodyDef& first) {
  const sim::core::Shape &s = b.shape, &f = first.shape;
  return s.kind == f.kind && s.radius == f.radius && s.vertices == f.vertices && s.planeNormal == f.planeNormal &&
         b.density == first.density && b.mass == first.mass && b.inertia == first.inertia && b.velocity == first.velocity &&
         b.angularVelocity == first.angularVelocity && b.restitution == first.restitution && b.friction == first.friction;
}

std::string place(int row, int k) { return "row " + std::to_string(row) + ", place " + std::to_string(k); }

}  // namespace

PyramidReading readPyramid(const std::vector<BodyDef>& bodies) {
  std::vector<std::size_t> dynamic;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].isStatic) dynamic.push_back(i);
  PyramidReading out;
  if (dynamic.size() < 3) {
    out.problem = "a pyramid needs at least two rows (3 dynamic bodies); the scene has " + std::to_string(dynamic.size());
    return out;
  }
  // the bottom row: the leading bodies at the first one's height
  const Vec2 origin = bodies[dynamic[0]].position;
  const Vec2 along = bodies[dynamic[1]].position - origin;
  const double spacing = along.norm();
  int base = 1;
  while (base < static_cast<int>(dynamic.size()) &&
         std::abs(bodies[dynamic[base]].position.y() - origin.y()) <= kPlaceTolerance * spacing)
    ++base;
  if (spacing == 0.0 || base < 2 || base == static_cast<int>(dynamic.size())) {
    out.problem = "the first two dynamic bodies must start the bottom row, and a second row must follow it";
    return out;
  }
  const std::size_t expected = static_cast<std::size_t>(base) * (base + 1) / 2;
  if (dynamic.size() != expected) {
    out.problem = "a bottom row of " + std::to_string(base) + " makes a pyramid of " + std::to_string(expected) +
                  " boxes; the scene has " + std::to_string(dynamic.size()) + " dynamic bodies";
    return out;
  }
  const Vec2 up = bodies[dynamic[base]].position - origin;
  std::size_t i = 0;
  for (int row = 0; row < base; ++row)
    for (int k = 0; k < base - row; ++k, ++i) {
      const BodyDef& b = bodies[dynamic[i]];
      const Vec2 want = origin + row * up + k * along;
      if (!likeFirst(b, bodies[dynamic[0]])) {
        out.problem = "body '" + b.name + "' differs from the first box in shape, mass, material or motion; a grown " +
                      "pyramid is made of copies of the first";
        return out;
      }
      if ((b.position - want).norm() > kPlaceTolerance * spacing || b.angle != 0.0) {
        out.problem = "body '" + b.name + "' is not where " + place(row + 1, k + 1) + " of the pyramid would be (" +
                      std::to_string(want.x()) + ", " + std::to_string(want.y()) + ", unrotated)";
        return out;
      }
    }
  out.rows = PyramidRows{base, origin, along, up, dynamic[0]};
  return out;
}

std::vector<BodyDef> pyramidOfBase(const std::vector<BodyDef>& bodies, const PyramidRows& rows, int base) {
  std::vector<BodyDef> out;
  for (const BodyDef& b : bodies)
    if (b.isStatic) out.push_back(b);
  // the bottom row's centre stays where the scene put it
  const Vec2 start = rows.origin + 0.5 * (rows.base - base) * rows.along;
  const BodyDef& box = bodies[rows.first];
  for (int row = 0; row < base; ++row)
    for (int k = 0; k < base - row; ++k) {
      BodyDef b = box;
      // appended piece by piece into a new string: g++ 12 warns of overlapping copies in
      // "b" + std::to_string(...) and in assigning "b" (GCC bug 105329, a false positive)
      std::string name(1, 'b');
      name += std::to_string(row + 1);
      name += '_';
      name += std::to_string(k + 1);
      b.name = std::move(name);
      b.position = start + row * rows.up + k * rows.along;
      out.push_back(b);
    }
  return out;
}

}  // namespace render::analysis
