// The `isolated` method: the notes' model of one isolated collision ("Collisions: rigid
// body–obstacle", "two rigid bodies"), applied on fixed steps to every overlap found after the
// bodies moved freely, then the overlaps pushed apart.
#include <algorithm>

#include "sim/collision/impulse.h"
#include "sim/world/methods.h"
#include "sim/world/world.h"

namespace sim::world {
using sim::core::Body;
using sim::core::Vec2;
using namespace sim::core;
using namespace sim::collision;

namespace {

// the notes' impulse once at each approaching contact point, deepest first
void resolveDeepestFirst(World& world, double t) {
  struct Point {
    const Contact* contact;
    int k;
  };
  std::vector<Point> order;
  for (const Contact& c : world.contacts)
    for (int k = 0; k < c.manifold.count; ++k) order.push_back({&c, k});
  std::stable_sort(order.begin(), order.end(), [](const Point& p, const Point& q) {
    return p.contact->manifold.points[p.k].separation < q.contact->manifold.points[q.k].separation;
  });
  for (const Point& p : order) {
    const Contact& c = *p.contact;
    Body &a = world.bodies[c.a], &b = world.bodies[c.b];
    const Vec2 r = c.manifold.points[p.k].point, n = c.manifold.normal;
    ImpactRecord rec{t, c.a, c.b, r, n};
    rec.vnBefore = n.dot(relativeVelocity(a, b, r));
    if (rec.vnBefore >= 0.0) continue;  // separating already: no collision
    const ImpulseResult j = resolveImpact(a, b, r, n, c.restitution, c.friction);
    rec.impulse = j.gamma;
    rec.tangentImpulse = j.tangent;
    rec.vnAfter = n.dot(relativeVelocity(a, b, r));
    world.impacts.push_back(rec);
  }
}

// push each overlapping pair apart along the normal, shared by inverse mass, deepest first
void separateOverlaps(World& world) {
  std::vector<const Contact*> order;
  for (const Contact& c : world.contacts) order.push_back(&c);
  std::stable_sort(order.begin(), order.end(),
                   [](const Contact* p, const Contact* q) { return p->manifold.separation < q->manifold.separation; });
  for (const Contact* c : order) {
    Body &a = world.bodies[c->a], &b = world.bodies[c->b];
    const double depth = -c->manifold.separation;
    const double share = a.invMass + b.invMass;
    if (depth <= 0.0 || share == 0.0) continue;
    a.x += (depth * a.invMass / share) * c->manifold.normal;
    b.x -= (depth * b.invMass / share) * c->manifold.normal;
  }
}

class IsolatedSolver final : public Method {
 public:
  std::unique_ptr<Method> clone() const override { return std::make_unique<IsolatedSolver>(*this); }

  void step(World& world, const TimeStep& step) override {
    moveFreely(world, step);
    // the overlaps where the bodies moved to, each answered with one impulse, then pushed apart
    world.contacts = world.findContacts(0.0);
    resolveDeepestFirst(world, step.end());
    separateOverlaps(world);
  }
};

}  // namespace

std::unique_ptr<Method> makeIsolatedSolver() { return std::make_unique<IsolatedSolver>(); }

}  // namespace sim::world
