#include "render/frame/impulse_beside.h"

namespace render::frame {
using render::draw::Pen;
using render::draw::Role;
using sim::core::Vec2;
using namespace render::draw;

void ImpulseBeside::arrow(const Vec2& tail, const Vec2& head, const Pen& p) {
  const Vec2 along = head - tail;
  if (p.role != Role::Impulse || !(along.norm() > 0.0)) return target_.arrow(tail, head, p);
  // to the arrow's left, whichever way it points: both sides of a contact keep their own side
  const Vec2 side = Vec2(-along.y(), along.x()).normalized() * offset_;
  target_.arrow(tail + side, head + side, p);
}

}  // namespace render::frame
