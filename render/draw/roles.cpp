#include "render/draw/roles.h"

namespace render::draw {

namespace {

// every row of the table is in Role's order, and the physics roles come first, in their order
constexpr bool tableInOrder() {
  for (size_t i = 0; i < kRoleCount; ++i)
    if (static_cast<size_t>(kRoles[i].role) != i) return false;
  return true;
}
static_assert(tableInOrder(), "kRoles must list the roles in the order of Role");

}  // namespace

Role fromPhysics(sim::debug_draw::DrawRole role) {
  using sim::debug_draw::DrawRole;
  switch (role) {
    case DrawRole::Body: return Role::Body;
    case DrawRole::StaticBody: return Role::StaticBody;
    case DrawRole::BodyAxis: return Role::BodyAxis;
    case DrawRole::ContactPoint: return Role::ContactPoint;
    case DrawRole::ContactNormal: return Role::ContactNormal;
    case DrawRole::Impulse: return Role::Impulse;
    case DrawRole::Spring: return Role::Spring;
    case DrawRole::ReferenceEdge: return Role::ReferenceEdge;
    case DrawRole::IncidentVertex: return Role::IncidentVertex;
    case DrawRole::Label: return Role::Label;
    case DrawRole::BodyPart: return Role::BodyPart;
    case DrawRole::BodyEdge: return Role::BodyEdge;
  }
  return Role::Label;
}

}  // namespace render::draw
