#include "render/frame/upcoming_events.h"

#include <algorithm>

#include "render/frame/dashed.h"
#include "render/frame/label_place.h"
#include "render/frame/quantity_text.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;

namespace {

// a dash and the gap after it, in line widths (the overlay's); the solid head's length, px
constexpr double kDash = 4.0, kGap = 3.0, kHeadPx = 24.0;

}  // namespace

std::string upcomingText(double t) { return "j at t = " + timeToMs(t) + " s"; }

void drawUpcomingEvents(const sim::world::World& world, double impulseScale, const Camera& camera, double lineWidthPx,
                        Canvas& draw) {
  const double px = camera.pixelSize();
  for (const sim::world::ImpulseEvent& e : world.def().events) {
    // an event at the present time has struck already (a frame shows the state after it)
    if (!(e.time > world.time)) continue;
    const sim::core::Body& b = world.bodies[e.body];
    const Vec2 head = e.pointInWorld ? e.point : b.pose().toWorld(e.point);
    const Vec2 tail = head - impulseScale * e.impulse;
    const Pen pen{Role::Impulse, e.body, 1.0};
    const double length = (head - tail).norm();
    if (length > kHeadPx * px) {
      // the shaft dashed, the head solid: where and which way it will strike
      const Vec2 neck = head - (kHeadPx * px / length) * (head - tail);
      dashedLine({tail, neck}, false, kDash * lineWidthPx * px, kGap * lineWidthPx * px, pen, draw);
      draw.arrow(neck, head, pen);
    } else {
      draw.point(head, pen);
    }
    draw.label(tail, directionOr(tail - head, Vec2::UnitY()), upcomingText(e.time), {Role::Label, e.body, 1.0});
  }
}

}  // namespace render::frame
