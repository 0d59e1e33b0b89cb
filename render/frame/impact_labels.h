// `impact_values: true`: each impact afterimage labeled with its normal "n̂", its impulses "j" and
// the restitution law at work, "v_n⁻ = −1.00 m/s → v_n⁺ = 0.50 m/s" (notes: "Collisions"); each
// event's impulse arrow with "j = 1.00 N·s". The history keeps them with the arrows, fading alike.
#pragma once

#include "render/draw/canvas.h"
#include "sim/world/world.h"

namespace render::frame {

class ImpactLabels {
 public:
  // `em`: the text size; `impulseScale`, `normalLength`: the arrows' as the history draws them
  ImpactLabels(double em, double impulseScale, double normalLength)
      : em_(em), impulseScale_(impulseScale), normalLength_(normalLength) {}

  // the labels of one impact record; the normal and the velocities once per pair and instant (`first`)
  void impact(const sim::world::World& world, const sim::world::ImpactRecord& r, bool first, render::draw::Canvas& draw) const;
  // the label of an event's impulse arrow from `tail` to `head`
  void event(const sim::world::ImpulseEvent& e, const sim::core::Vec2& tail, const sim::core::Vec2& head,
             render::draw::Canvas& draw) const;

  // "v_n⁻ = −1.00 m/s → v_n⁺ = 0.50 m/s"
  static std::string velocitiesText(double vnBefore, double vnAfter);

 private:
  double em_, impulseScale_, normalLength_;
};

}  // namespace render::frame
