#include "sim/world3d/diagnostics.h"

#include <algorithm>
#include <cmath>

#include "sim/core/bit_hash.h"
#include "sim/core/world_energy.h"

namespace sim::world3d {

KineticEnergy kineticEnergy(const Body& b) { return {0.5 * b.mass * b.v.squaredNorm(), 0.5 * b.omega.dot(b.angularMomentum())}; }

Energy energy(const World& world) { return sim::core::worldEnergy<Energy>(world, kineticEnergy); }

Vec3 linearMomentum(const World& world) {
  Vec3 p = Vec3::Zero();
  for (const Body& b : world.bodies) p += b.mass * b.v;
  return p;
}

Vec3 angularMomentum(const World& world) {
  Vec3 l = Vec3::Zero();
  for (const Body& b : world.bodies) l += b.x.cross(b.mass * b.v) + b.angularMomentum();
  return l;
}

double quaternionDrift(const World& world) {
  double drift = 0.0;
  for (const Body& b : world.bodies) drift = std::max(drift, std::abs(b.q.norm() - 1.0));
  return drift;
}

unsigned long long stateHash(const World& world) {
  sim::core::BitHash h;
  for (const Body& b : world.bodies)
    for (double x : {b.x.x(), b.x.y(), b.x.z(), b.q.w(), b.q.x(), b.q.y(), b.q.z(), b.v.x(), b.v.y(), b.v.z(), b.omega.x(),
                     b.omega.y(), b.omega.z()})
      h.mix(x);
  return h.value();
}

}  // namespace sim::world3d
