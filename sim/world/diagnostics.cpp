#include "sim/world/diagnostics.h"

#include <cstring>

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

KineticEnergy kineticEnergy(const Body& b) {
  if (b.isStatic) return {};
  return {0.5 * b.mass * b.v.squaredNorm(), 0.5 * b.inertia * b.omega * b.omega};
}

Energy energy(const World& world) {
  Energy e;
  for (const Body& b : world.bodies) e.kinetic += kineticEnergy(b).total();
  e.potential = world.forces.potentialEnergy(world.bodies);
  return e;
}

Vec2 linearMomentum(const World& world) {
  Vec2 p = Vec2::Zero();
  for (const Body& b : world.bodies)
    if (!b.isStatic) p += b.mass * b.v;
  return p;
}

double angularMomentum(const World& world) {
  double l = 0.0;
  for (const Body& b : world.bodies)
    if (!b.isStatic) l += cross(b.x, b.mass * b.v) + b.inertia * b.omega;
  return l;
}

unsigned long long stateHash(const World& world) {
  // FNV-1a over the raw bits
  unsigned long long h = 1469598103934665603ull;
  auto mix = [&h](double value) {
    unsigned long long bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int k = 0; k < 8; ++k) {
      h ^= (bits >> (8 * k)) & 0xffu;
      h *= 1099511628211ull;
    }
  };
  for (const Body& b : world.bodies) {
    mix(b.x.x()), mix(b.x.y()), mix(b.angle), mix(b.v.x()), mix(b.v.y()), mix(b.omega);
  }
  return h;
}

}  // namespace sim::world
