// What each collision method models, in one table (design.md: "A method promises what it models";
// Box2D-Lite's toggles and Solver2D's solvers say what each does where it is chosen). `auto` picks
// from it, a scene that names a method is warned from it of what the method leaves out, and
// sim/README.md's section of each method says the same in words.
#pragma once

#include <string>

#include "sim/core/collision_methods.h"
#include "sim/world/contact.h"

namespace sim::world {

// one row per method; `auto` is resolved to one of them before a run (World::start)
inline constexpr sim::core::MethodModel kMethodModels[] = {
    {sim::core::CollisionMethod::None, 0u, sim::core::IntegratorUse::Named,
     "bodies pass through each other: restitution and friction are never used"},
    {sim::core::CollisionMethod::Event, sim::core::Phenomenon::IsolatedImpacts | sim::core::Phenomenon::FrictionAtImpacts,
     sim::core::IntegratorUse::Named,
     "friction acts at impacts only: a contact that persists (a Zeno series of bounces ended) rests without friction, so a body "
     "that lands slides on and a stack gives up"},
    {sim::core::CollisionMethod::Isolated, sim::core::Phenomenon::IsolatedImpacts | sim::core::Phenomenon::FrictionAtImpacts,
     sim::core::IntegratorUse::Named,
     "friction acts at impacts only, and resting bodies jitter and sink: it answers each overlap with one impulse"},
    {sim::core::CollisionMethod::Sequential,
     sim::core::Phenomenon::IsolatedImpacts | sim::core::Phenomenon::FrictionAtImpacts | sim::core::Phenomenon::SlidingFriction |
         sim::core::Phenomenon::RestingContact | sim::core::Phenomenon::Stacks,
     sim::core::IntegratorUse::Named, "impacts slower than 1 m/s do not bounce (restitution threshold)"},
    {sim::core::CollisionMethod::SoftStep,
     sim::core::Phenomenon::IsolatedImpacts | sim::core::Phenomenon::FrictionAtImpacts | sim::core::Phenomenon::SlidingFriction |
         sim::core::Phenomenon::RestingContact | sim::core::Phenomenon::Stacks,
     sim::core::IntegratorUse::Own, "forces act by symplectic Euler in each substep, whatever the scene's integrator"},
};

// the row of a method (not `auto`)
const sim::core::MethodModel& methodModel(sim::core::CollisionMethod method);
inline bool models(sim::core::CollisionMethod method, sim::core::Phenomenon p) {
  return sim::core::has(methodModel(method).models, p);
}
// whether the method's contacts are right with this integrator (it moves the bodies by it)
inline bool usesIntegrator(sim::core::CollisionMethod method) {
  return methodModel(method).integrators == sim::core::IntegratorUse::Named;
}

// the least of `none`, `event` and `sequential` that models every phenomenon of `needs` (`auto`'s
// choice: `isolated` shows the notes' model failing and `soft_step` is for piles `sequential`
// loses, so `auto` never picks them)
sim::core::CollisionMethod leastMethodFor(unsigned needs);

}  // namespace sim::world
