#include "impact_labels.h"

#include "label_place.h"
#include "quantity_text.h"

namespace render {

using sim::DrawRole;
using sim::Vec2;

void ImpactLabels::impact(const sim::World& world, const sim::ImpactRecord& r, bool first, sim::DebugDraw& draw) const {
  const sim::DrawStyle style{DrawRole::Label, -1, 1.0};
  // the arrows as the history draws them: γ n̂ on A, −γ n̂ on B; the normal into the moving body
  const Vec2 j = impulseScale_ * r.impulse * r.normal;
  const Vec2 n = world.bodies[r.a].isStatic ? Vec2(-r.normal) : r.normal;
  const Vec2 along = directionOr(j, n);
  if (!world.bodies[r.a].isStatic && j.norm() > 0.0) draw.text(labelBeyond(r.point + j, along, "j", em_), "j", style);
  if (!world.bodies[r.b].isStatic && j.norm() > 0.0) draw.text(labelBeyond(r.point - j, -along, "j", em_), "j", style);
  if (!first) return;
  draw.text(labelBeyond(r.point + normalLength_ * n, n, "n̂", em_), "n̂", style);
  // the velocities on the side away from the normal's arrow, where nothing else is written
  const std::string v = velocitiesText(r.vnBefore, r.vnAfter);
  draw.text(labelBeyond(r.point, -n, v, em_), v, style);
}

void ImpactLabels::event(const sim::ImpulseEvent& e, const Vec2& tail, const Vec2& head, sim::DebugDraw& draw) const {
  const std::string text = quantityText("j", e.impulse.norm(), "N·s");
  // before the tail: the head strikes the body
  draw.text(labelBeyond(tail, directionOr(tail - head, Vec2::UnitY()), text, em_), text, {DrawRole::Label, e.body, 1.0});
}

std::string ImpactLabels::velocitiesText(double vnBefore, double vnAfter) {
  return quantityText("v_n⁻", vnBefore, "m/s") + " → " + quantityText("v_n⁺", vnAfter, "m/s");
}

}  // namespace render
