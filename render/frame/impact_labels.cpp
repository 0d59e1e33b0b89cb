#include "render/frame/impact_labels.h"

#include <cmath>

#include "render/frame/label_place.h"
#include "render/frame/quantity_text.h"
#include "sim/core/settings.h"

namespace render::frame {
using namespace render::draw;

using sim::core::Vec2;

void ImpactLabels::impact(const sim::world::World& world, const sim::world::ImpactRecord& r, bool first, Canvas& draw) const {
  const Pen style{Role::Label, -1, 1.0};
  // the arrows as the history draws them: γ n̂ on A, −γ n̂ on B; the normal into the moving body
  const Vec2 j = impulseScale_ * r.impulse * r.normal;
  const Vec2 n = world.bodies[r.a].isStatic ? Vec2(-r.normal) : r.normal;
  const Vec2 along = directionOr(j, n);
  if (!world.bodies[r.a].isStatic && j.norm() > 0.0) draw.label(r.point + j, along, "j", style);
  if (!world.bodies[r.b].isStatic && j.norm() > 0.0) draw.label(r.point - j, -along, "j", style);
  if (!first) return;
  // across the normal, not along it: along it lie the impulse arrows and the bodies themselves. The
  // velocities go below the contact (right of it on a floor), leaning a little into the moving body's
  // side so as not to sit on an obstacle's edge; n̂ beside the normal's head, across
  const Vec2 across = std::abs(n.x()) < 1e-9 ? Vec2(1, 0) : (n.x() > 0.0 ? Vec2(n.y(), -n.x()) : Vec2(-n.y(), n.x()));
  draw.label(r.point + normalLength_ * n, -across, "n̂", style);
  draw.label(r.point + 0.6 * em_ * n, across, velocitiesText(r.vnBefore, r.vnAfter), style);
}

void ImpactLabels::event(const sim::world::ImpulseEvent& e, const Vec2& tail, const Vec2& head, Canvas& draw) const {
  const std::string text = quantityText("j", e.impulse.norm(), "N·s");
  // before the tail: the head strikes the body
  draw.label(tail, directionOr(tail - head, Vec2::UnitY()), text, {Role::Label, e.body, 1.0});
}

std::string ImpactLabels::velocitiesText(double vnBefore, double vnAfter) {
  // a normal speed under the resting speed is a resting contact's, round-off of a plastic impact
  const auto shown = [](double vn) { return std::abs(vn) < sim::core::settings::kRestingSpeed ? 0.0 : vn; };
  return quantityText("v_n⁻", shown(vnBefore), "m/s") + " → " + quantityText("v_n⁺", shown(vnAfter), "m/s");
}

}  // namespace render::frame
