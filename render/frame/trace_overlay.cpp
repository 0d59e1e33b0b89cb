#include "render/frame/trace_overlay.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/frame/dashed.h"
#include "render/scene/scene_style.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;
using namespace render::scene;

namespace {

// a dash and the gap after it, in line widths: clearly dashed at any frame size
constexpr double kDash = 4.0, kGap = 3.0;
// a circle's outline as a polygon of this many sides (within a tenth of a pixel below 150 px radius)
constexpr int kCircleSides = 64;
// the legend's sample line, in line heights
constexpr double kSample = 1.5;
// the arrow at the frame's edge toward a body of theirs out of it, and its inset, in 4 line widths
constexpr double kEdgeArrow = 3.0;

}  // namespace

void drawTraceOverlay(const render::scene::Scene& def, const render::scene::TraceOverlayDef& overlay,
                      const sim::world::World& world, const Camera& camera, Canvas& draw) {
  const double px = camera.pixelSize();
  const double lineWidth = lineWidthFor(def.render, camera.heightPx());
  const double dash = kDash * lineWidth * px, gap = kGap * lineWidth * px;
  const Pen pen{Role::Overlay, -1, 1.0};
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    render::scene::TraceOverlayDef::Pose p;
    const sim::core::Shape& shape = world.bodies[i].shape;
    if (shape.kind == sim::core::ShapeKind::Plane || !overlay.poseAt(i, world.time, p)) continue;
    const sim::core::Pose pose{p.x, sim::core::Rot::fromAngle(p.angle)};
    // a body of theirs out of the frame (a fixed camera): an arrow at the frame's edge points to it
    const Vec2 at = camera.toPixel(p.x);
    const double edge = kEdgeArrow * lineWidth * 4.0;
    const Vec2 inside(std::clamp(at.x(), edge, camera.widthPx() - edge), std::clamp(at.y(), edge, camera.heightPx() - edge));
    if ((at - inside).norm() > edge) {
      const Vec2 toward = (at - inside).normalized();
      draw.arrow(camera.toWorld(inside - edge * toward), camera.toWorld(inside), pen);
    }
    // each convex part's outline (a body of parts: every part's, seams and all, as their run gives no more)
    const int parts = shape.kind == sim::core::ShapeKind::Compound ? static_cast<int>(shape.parts.size()) : 1;
    for (int k = 0; k < parts; ++k) {
      const sim::core::Shape& part = shape.kind == sim::core::ShapeKind::Compound ? shape.parts[k].shape : shape;
      const sim::core::Pose at = shape.kind == sim::core::ShapeKind::Compound ? pose.then(shape.parts[k].pose) : pose;
      std::vector<Vec2> outline;
      if (part.kind == sim::core::ShapeKind::Polygon) {
        for (const Vec2& v : part.vertices) outline.push_back(at.toWorld(v));
      } else {
        for (int c = 0; c < kCircleSides; ++c) {
          const double a = 2.0 * std::numbers::pi * c / kCircleSides;
          outline.push_back(at.toWorld(part.radius * Vec2(std::cos(a), std::sin(a))));
        }
        // its radius along the body's x axis, as our circles show their turn
        dashedLine({at.x, at.toWorld({part.radius, 0.0})}, false, dash, gap, pen, draw);
      }
      dashedLine(outline, true, dash, gap, pen, draw);
    }
  }
  // the legend, under the clock and the slow-motion note: a solid sample for ours, a dashed one for theirs
  const int size = fontSizeFor(def.render, camera.heightPx());
  const CaptionLayout layout = captionLayout(size);
  const double sample = kSample * layout.line;
  const std::string ours = "rigidreel", theirs = overlay.name;
  for (int row = 0; row < 2; ++row) {
    const double top = layout.inset + (2 + row) * layout.line;
    const double middle = top + 0.5 * layout.line;
    const Vec2 a = camera.toWorld({layout.inset, middle}), b = camera.toWorld({layout.inset + sample, middle});
    if (row == 0) draw.segment(a, b, {Role::Caption, -1, 1.0});
    else dashedLine({a, b}, false, dash, gap, pen, draw);
    draw.text(camera.toWorld({layout.inset + sample + 0.5 * layout.line, top}), row == 0 ? ours : theirs,
              {Role::Caption, -1, 1.0});
  }
}

}  // namespace render::frame
