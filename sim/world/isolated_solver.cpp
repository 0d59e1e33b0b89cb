// The `isolated` method's stages: the notes' model of one isolated collision, applied on fixed
// steps to every overlap found after the step.
#include <algorithm>

#include "sim/collision/impulse.h"
#include "sim/world/world.h"

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;

// the notes' impulse once at each approaching contact point, deepest first
void World::resolveDeepestFirst() {
  struct Point {
    const Contact* contact;
    int k;
  };
  std::vector<Point> order;
  for (const Contact& c : contacts)
    for (int k = 0; k < c.manifold.count; ++k) order.push_back({&c, k});
  std::stable_sort(order.begin(), order.end(), [](const Point& p, const Point& q) {
    return p.contact->manifold.points[p.k].separation < q.contact->manifold.points[q.k].separation;
  });
  for (const Point& p : order) {
    const Contact& c = *p.contact;
    Body &a = bodies[c.a], &b = bodies[c.b];
    const Vec2 r = c.manifold.points[p.k].point, n = c.manifold.normal;
    ImpactRecord rec{now_, c.a, c.b, r, n};
    rec.vnBefore = n.dot(relativeVelocity(a, b, r));
    if (rec.vnBefore >= 0.0) continue;  // separating already: no collision
    const ImpulseResult j = resolveImpact(a, b, r, n, c.restitution, c.friction);
    rec.impulse = j.gamma;
    rec.tangentImpulse = j.tangent;
    rec.vnAfter = n.dot(relativeVelocity(a, b, r));
    impacts.push_back(rec);
  }
}

// push each overlapping pair apart along the normal, shared by inverse mass, deepest first
void World::separateOverlaps() {
  std::vector<const Contact*> order;
  for (const Contact& c : contacts) order.push_back(&c);
  std::stable_sort(order.begin(), order.end(),
                   [](const Contact* p, const Contact* q) { return p->manifold.separation < q->manifold.separation; });
  for (const Contact* c : order) {
    Body &a = bodies[c->a], &b = bodies[c->b];
    const double depth = -c->manifold.separation;
    const double share = a.invMass + b.invMass;
    if (depth <= 0.0 || share == 0.0) continue;
    a.x += (depth * a.invMass / share) * c->manifold.normal;
    b.x -= (depth * b.invMass / share) * c->manifold.normal;
  }
}

}  // namespace sim::world
