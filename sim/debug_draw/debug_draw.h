// What there is to see, described without any graphics (the idea of Box2D's b2DebugDraw): the
// simulator calls these in world coordinates, a renderer draws them, a test records them as a
// draw list. Styles are semantic (a role and the body it belongs to); how each looks is the drawing
// side's choice.
#pragma once

#include <string>
#include <vector>

#include "sim/core/math.h"

namespace sim::debug_draw {

// the physics a picture of the world shows; a renderer gives each its look
enum class DrawRole {
  Body,            // a dynamic body's shape: filled and outlined
  StaticBody,      // a static body or a half-plane obstacle; a spring's world anchor
  BodyAxis,        // a radius marking a body's rotation (circles)
  ContactPoint,    // a contact point: a dot
  ContactNormal,   // a contact normal: an arrow from the point
  Impulse,         // an impulse applied by an event or an impact: an arrow
  Spring,          // a spring's coils, as segments
  ReferenceEdge,   // the separating-axis reference edge
  IncidentVertex,  // the separating-axis incident vertex
  Label,           // a value written beside what it belongs to (a separation)
  BodyPart,        // a part of a dynamic body made of parts: filled, not outlined
  BodyEdge,        // a piece of the outline of a body made of parts (none where two parts touch)
};

struct DrawStyle {
  DrawRole role = DrawRole::Body;
  int body = -1;         // index of the body it belongs to, -1 for none
  double opacity = 1.0;  // fading afterimages, strobe ghosts
};

class DebugDraw {
 public:
  virtual ~DebugDraw() = default;
  // a closed convex polygon
  virtual void polygon(const std::vector<sim::core::Vec2>& vertices, const DrawStyle& style) = 0;
  virtual void circle(const sim::core::Vec2& center, double radius, const DrawStyle& style) = 0;
  // the half-plane {r : n·(r − point) ≤ 0}, to be filled out to the edges of the view
  virtual void halfPlane(const sim::core::Vec2& point, const sim::core::Vec2& normal, const DrawStyle& style) = 0;
  virtual void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const DrawStyle& style) = 0;
  virtual void point(const sim::core::Vec2& p, const DrawStyle& style) = 0;
  virtual void arrow(const sim::core::Vec2& tail, const sim::core::Vec2& head, const DrawStyle& style) = 0;
  virtual void text(const sim::core::Vec2& at, const std::string& text, const DrawStyle& style) = 0;
};

}  // namespace sim::debug_draw
