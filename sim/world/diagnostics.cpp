#include "sim/world/diagnostics.h"

#include "sim/core/bit_hash.h"
#include "sim/core/world_energy.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

KineticEnergy kineticEnergy(const Body& b) {
  if (b.isStatic) return {};
  return {0.5 * b.mass * b.v.squaredNorm(), 0.5 * b.inertia * b.omega * b.omega};
}

Energy energy(const World& world) { return worldEnergy<Energy>(world, kineticEnergy); }

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
  sim::core::BitHash h;
  for (const Body& b : world.bodies)
    for (double x : {b.x.x(), b.x.y(), b.angle, b.v.x(), b.v.y(), b.omega}) h.mix(x);
  return h.value();
}

}  // namespace sim::world
