// What each 3D collision method models, in one table as in 2D (sim/world/method_models.h): `auto`
// picks from it, and sim/README.md's 3D part says the same in words. 3D has three methods:
// `isolated` and `soft_step` are 2D's only.
#pragma once

#include <memory>

#include "sim/core/collision_methods.h"
#include "sim/world3d/methods3d.h"

namespace sim::world3d {

inline constexpr sim::core::MethodModel kMethodModels3d[] = {
    {sim::core::CollisionMethod::None, 0u, sim::core::IntegratorUse::Named,
     "bodies pass through each other and the planes: restitution and friction are never used"},
    {sim::core::CollisionMethod::Event, sim::core::Phenomenon::IsolatedImpacts | sim::core::Phenomenon::FrictionAtImpacts,
     sim::core::IntegratorUse::Named,
     "it resolves isolated impacts exactly, and stops where a contact persists (a body too slow to part): named, the run "
     "fails there; under 'auto', 'sequential' takes over"},
    {sim::core::CollisionMethod::Sequential,
     sim::core::Phenomenon::IsolatedImpacts | sim::core::Phenomenon::FrictionAtImpacts | sim::core::Phenomenon::SlidingFriction |
         sim::core::Phenomenon::RestingContact | sim::core::Phenomenon::Stacks,
     sim::core::IntegratorUse::Named, "impacts slower than 1 m/s do not bounce (restitution threshold)"},
};

// the row of a 3D method, or none for a method 3D does not have (isolated, soft_step)
inline const sim::core::MethodModel* methodModel3d(sim::core::CollisionMethod m) {
  return sim::core::findMethod(kMethodModels3d, m);
}
// the least of none, event and sequential that models every phenomenon of `needs`
sim::core::CollisionMethod leastMethodFor3(unsigned needs);
// the unit of a 3D method by name (`auto` resolved first)
std::unique_ptr<Method3> makeMethod3(sim::core::CollisionMethod method);

}  // namespace sim::world3d
