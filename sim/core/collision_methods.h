// The collision methods by name, what a method models (Phenomenon), and why a run uses the method it
// does: what the 2D and the 3D worlds share. Each world keeps the table of its own methods
// (sim/world/method_models.h, sim/world3d/method_models3d.h); design.md: "A method promises what it
// models".
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "sim/core/enum_names.h"

namespace sim::core {

// collision response, chosen per scene (`sim: {collisions: ...}`) or on the command line
enum class CollisionMethod {
  Auto,        // the least model the scene needs, watched during the run
  None,        // bodies pass through each other: free bodies only
  Event,       // exact: advance to each time of impact, apply the notes' impulse there
  Isolated,    // the notes' model on fixed steps: one impulse per approaching contact, then push apart
  Sequential,  // fixed steps, sequential impulses with warm starting, friction, position correction
  SoftStep,    // fixed steps in substeps, soft contacts with relax passes (Box2D v3)
};

// names as written in scenes and on the command line
inline constexpr EnumNames<CollisionMethod, 6> kCollisionMethodNames{{{
    {CollisionMethod::Auto, "auto"},
    {CollisionMethod::None, "none"},
    {CollisionMethod::Event, "event"},
    {CollisionMethod::Isolated, "isolated"},
    {CollisionMethod::Sequential, "sequential"},
    {CollisionMethod::SoftStep, "soft_step"},
}}};
inline std::string_view collisionMethodName(CollisionMethod method) { return kCollisionMethodNames.name(method); }
inline std::optional<CollisionMethod> collisionMethodFromName(std::string_view name) { return kCollisionMethodNames.parse(name); }

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
// "isolated impacts, friction at impacts, ...": the phenomena of a set of bits, in the enum's order
std::string phenomenaText(unsigned bits);

// how a method moves the bodies between its contact solves
enum class IntegratorUse {
  Named,  // by the scene's integrator, its contacts right with each
  Own,    // by its own symplectic Euler in each substep: the scene's integrator is not used
};

// one row of a world's table of methods
struct MethodModel {
  CollisionMethod method;
  unsigned models;  // Phenomenon bits
  IntegratorUse integrators;
  // what it leaves out, said where a scene that names it needs it (one sentence, no period)
  const char* limits;
};

// the row of `method` in `table`, or none (a method the world does not have, or `auto`)
const MethodModel* findMethod(std::span<const MethodModel> table, CollisionMethod method);
// the first of `order` whose row in `table` models every phenomenon of `needs` (`auto`'s choice),
// else the last of `order`
CollisionMethod leastMethodFor(std::span<const MethodModel> table, std::span<const CollisionMethod> order, unsigned needs);

// why the collision method is what it is (`auto` explains its choice, and its switch during the
// run: StackFormed or ContactPersisted, told by MethodSwitch)
enum class MethodReason { Requested, FewBodies, IsolatedImpacts, PersistentContacts, StackFormed, ContactPersisted };

// what `auto`'s watch saw persist under the event method, and between which bodies
enum class Persistence {
  Rested,    // the event method found the pair too slow to part and made the contact resting
  Rattling,  // its slow impacts repeated within settings::kRepeatWindow
};

// when `auto` went from the event method to the resting-contact solver, and what made it
struct MethodSwitch {
  double time = 0.0;
  // the pair whose contact persisted, or none (-1) when impacts piled up in one step across the
  // scene (b: in 3D, a plane is −1 − its index)
  int a = -1, b = -1;
  Persistence how = Persistence::Rested;
};

}  // namespace sim::core
