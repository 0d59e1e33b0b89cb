#include "render/frame/contact_forces.h"

namespace render::frame {
using sim::core::Vec2;

std::vector<ContactForce> contactForcesOn(const sim::world::World& world, int body) {
  // the time the stored impulses act over: a step of the sequential solver, a substep of soft_step's
  double over = 0.0;
  if (world.collisions() == sim::core::CollisionMethod::Sequential) over = world.lastStep;
  if (world.collisions() == sim::core::CollisionMethod::SoftStep) over = world.lastStep / std::max(1, world.def().substeps);
  std::vector<ContactForce> out;
  if (!(over > 0.0)) return out;
  for (const sim::world::Contact& c : world.contacts) {
    if (c.a != body && c.b != body) continue;
    // the impulses go to A along n̂ (from B to A) and t̂, and the opposite to B
    const double sign = c.a == body ? 1.0 : -1.0;
    const Vec2 n = c.manifold.normal, t = sim::world::tangentOf(n);
    double normal = 0.0, tangent = 0.0;
    Vec2 weighted = Vec2::Zero(), mean = Vec2::Zero();
    for (int k = 0; k < c.manifold.count; ++k) {
      normal += c.state[k].normalImpulse, tangent += c.state[k].tangentImpulse;
      weighted += c.state[k].normalImpulse * c.manifold.points[k].point;
      mean += c.manifold.points[k].point / c.manifold.count;
    }
    if (c.manifold.count == 0) continue;
    out.push_back({normal > 0.0 ? Vec2(weighted / normal) : mean, sign * normal / over * n, sign * tangent / over * t});
  }
  return out;
}

}  // namespace render::frame
