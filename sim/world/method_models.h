// What each collision method models, in one table (design.md: "A method promises what it models";
// Box2D-Lite's toggles and Solver2D's solvers say what each does where it is chosen). `auto` picks
// from it, a scene that names a method is warned from it of what the method leaves out, and
// sim/README.md's section of each method says the same in words.
#pragma once

#include <string>

#include "sim/core/collision_methods.h"
#include "sim/world/contact.h"

namespace sim::world {

using sim::core::bit;
using sim::core::has;
using sim::core::IntegratorUse;
using sim::core::MethodModel;
using sim::core::phenomenaText;
using sim::core::Phenomenon;

// one row per method; `auto` is resolved to one of them before a run (World::start)
inline constexpr MethodModel kMethodModels[] = {
    {CollisionMethod::None, 0u, IntegratorUse::Named, "bodies pass through each other: restitution and friction are never used"},
    {CollisionMethod::Event, Phenomenon::IsolatedImpacts | Phenomenon::FrictionAtImpacts, IntegratorUse::Named,
     "friction acts at impacts only: a contact that persists (a Zeno series of bounces ended) rests without friction, so a body "
     "that lands slides on and a stack gives up"},
    {CollisionMethod::Isolated, Phenomenon::IsolatedImpacts | Phenomenon::FrictionAtImpacts, IntegratorUse::Named,
     "friction acts at impacts only, and resting bodies jitter and sink: it answers each overlap with one impulse"},
    {CollisionMethod::Sequential,
     Phenomenon::IsolatedImpacts | Phenomenon::FrictionAtImpacts | Phenomenon::SlidingFriction | Phenomenon::RestingContact |
         Phenomenon::Stacks,
     IntegratorUse::Named, "impacts slower than 1 m/s do not bounce (restitution threshold)"},
    {CollisionMethod::SoftStep,
     Phenomenon::IsolatedImpacts | Phenomenon::FrictionAtImpacts | Phenomenon::SlidingFriction | Phenomenon::RestingContact |
         Phenomenon::Stacks,
     IntegratorUse::Own, "forces act by symplectic Euler in each substep, whatever the scene's integrator"},
};

// the row of a method (not `auto`)
const MethodModel& methodModel(CollisionMethod method);
inline bool models(CollisionMethod method, Phenomenon p) { return has(methodModel(method).models, p); }
// whether the method's contacts are right with this integrator (it moves the bodies by it)
inline bool usesIntegrator(CollisionMethod method) { return methodModel(method).integrators == IntegratorUse::Named; }

// the least of `none`, `event` and `sequential` that models every phenomenon of `needs` (`auto`'s
// choice: `isolated` shows the notes' model failing and `soft_step` is for piles `sequential`
// loses, so `auto` never picks them)
CollisionMethod leastMethodFor(unsigned needs);

}  // namespace sim::world
