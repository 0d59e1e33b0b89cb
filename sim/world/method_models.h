// What each collision method models, in one table (design.md: "A method promises what it models";
// Box2D-Lite's toggles and Solver2D's solvers say what each does where it is chosen). `auto` picks
// from it, a scene that names a method is warned from it of what the method leaves out, and
// sim/README.md's section of each method says the same in words.
#pragma once

#include <string>

#include "sim/core/integrators.h"
#include "sim/world/contact.h"

namespace sim::world {

// what a scene can set up that a collision method models or leaves out
enum class Phenomenon : unsigned {
  IsolatedImpacts = 1u << 0,    // two bodies meet and part: the notes' impulse
  FrictionAtImpacts = 1u << 1,  // Coulomb friction in the impulse of an impact
  SlidingFriction = 1u << 2,    // Coulomb friction while a body slides on, or rests against, another
  RestingContact = 1u << 3,     // a body that comes to rest on another (or on a floor) stays there
  Stacks = 1u << 4,             // bodies resting on bodies resting on bodies
};
// sets of phenomena as bits
constexpr unsigned bit(Phenomenon p) { return static_cast<unsigned>(p); }
constexpr unsigned operator|(Phenomenon a, Phenomenon b) { return bit(a) | bit(b); }
constexpr unsigned operator|(unsigned a, Phenomenon b) { return a | bit(b); }
constexpr bool has(unsigned set, Phenomenon p) { return (set & bit(p)) != 0; }

// how a method moves the bodies between its contact solves
enum class IntegratorUse {
  Named,  // by the scene's integrator, each of the four right with its contacts
  Own,    // by its own symplectic Euler in each substep: the scene's integrator is not used
};

struct MethodModel {
  CollisionMethod method;
  unsigned models;  // Phenomenon bits
  IntegratorUse integrators;
  // what it leaves out, said where a scene that names it needs it (one sentence, no period)
  const char* limits;
};

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
// "isolated impacts, friction at impacts, ...": the phenomena of a set of bits, in the table's order
std::string phenomenaText(unsigned bits);

// the least of `none`, `event` and `sequential` that models every phenomenon of `needs` (`auto`'s
// choice: `isolated` shows the notes' model failing and `soft_step` is for piles `sequential`
// loses, so `auto` never picks them)
CollisionMethod leastMethodFor(unsigned needs);

}  // namespace sim::world
