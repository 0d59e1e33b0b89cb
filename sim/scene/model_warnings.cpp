#include "sim/scene/model_warnings.h"

#include "sim/world/method_models.h"

namespace sim::scene {
using namespace sim::core;
using namespace sim::world;

namespace {

// the μ some body names above zero (its own, or the world's for every body that names none)
bool namesFriction(const SceneDef& def) {
  for (const BodyDef& b : def.bodies)
    if (b.friction.value_or(def.friction.value_or(0.0)) > 0.0) return true;
  return false;
}

// a load presses bodies together (gravity or an applied force): whatever lands slides or rests
bool loaded(const SceneDef& def) { return def.gravity != Vec2::Zero() || !def.pointForces.empty() || !def.springs.empty(); }

// bodies that can meet: a dynamic body and another body
bool bodiesMeet(const SceneDef& def) {
  int dynamic = 0;
  for (const BodyDef& b : def.bodies) dynamic += !b.isStatic;
  return dynamic > 0 && def.bodies.size() >= 2;
}

}  // namespace

std::vector<ModelWarning> modelWarnings(const SceneDef& def) {
  std::vector<ModelWarning> out;
  const CollisionMethod m = def.collisions;
  if (m == CollisionMethod::Auto) return out;
  const std::string name(collisionMethodName(m));
  // the phenomena the scene sets up that its method leaves out
  unsigned asks = 0;
  if (bodiesMeet(def) && namesFriction(def)) {
    asks |= bit(Phenomenon::FrictionAtImpacts);
    if (loaded(def)) asks |= bit(Phenomenon::SlidingFriction);
  }
  if (const unsigned missing = asks & ~methodModel(m).models; missing) {
    out.push_back({def.collisionsLoc, "collisions", name,
                   "the scene names friction, and '" + name + "' does not model " + phenomenaText(missing) + ": " +
                       methodModel(m).limits +
                       "; for friction while bodies slide or rest, use 'sequential' or 'soft_step' (or "
                       "'auto', which hands a contact that persists to 'sequential')"});
  }
  if (!usesIntegrator(m) && def.integrator != sim::core::Integrator::SymplecticEuler) {
    const std::string integrator(sim::core::integratorName(def.integrator));
    out.push_back({def.integratorLoc, "integrator", integrator,
                   "'" + name + "' does not use it: " + methodModel(m).limits +
                       "; for the integrator's accuracy between contacts use 'sequential', whose contacts are right with every "
                       "integrator, or drop 'integrator'"});
  }
  return out;
}

}  // namespace sim::scene
