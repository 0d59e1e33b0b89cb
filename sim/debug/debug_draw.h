// What there is to see, described without any graphics (the idea of Box2D's b2DebugDraw): the
// simulator calls these in world coordinates, a renderer draws them, a test records them as a
// draw list. Styles are semantic (a role and the body it belongs to); the renderer picks colors.
#pragma once

#include <string>
#include <vector>

#include "sim/core/math.h"

namespace sim::debug {
using namespace sim::core;

enum class DrawRole {
  Body,            // a dynamic body's shape: filled and outlined
  StaticBody,      // a static body or a half-plane obstacle: drawn visibly different
  BodyAxis,        // a radius marking a body's rotation (circles)
  ContactPoint,    // a contact point: a dot
  ContactNormal,   // a contact normal: an arrow from the point
  Impulse,         // an impulse applied by an event or an impact: an arrow
  Velocity,        // a body's velocity: an arrow
  Trail,           // the path of a center of mass
  ReferenceEdge,   // the separating-axis reference edge
  IncidentVertex,  // the separating-axis incident vertex
  Label,           // text, centered on its point
  Caption,         // text fixed to the frame (the time): its point is the top-left corner
  Spring,          // a spring's coils, as segments
  // the lecture overlays
  Offset,          // r′ = R r_b, from the center of mass to a body point
  AngularVelocity, // ω as a curved arrow around the center of mass
  BodyFrame,       // the body's axes R x̂, R ŷ
  Path,            // the path of a body point
  Force,           // a point force at its point
  Torque,          // τ as a curved arrow around the center of mass
  Momentum,        // m v from the center of mass
  KineticBar,      // an energy bar of ½ m v², filled
  RotationalBar,   // an energy bar of ½ I ω², filled
  PotentialBar,    // the potential energy's bar, filled
  TotalBar,        // the total energy's bar, filled
  Panel,           // the background of a panel fixed to the frame, filled
};

struct DrawStyle {
  DrawRole role = DrawRole::Body;
  int body = -1;         // index of the body it belongs to (for its color), -1 for none
  double opacity = 1.0;  // fading contacts, strobe ghosts
  int color = -1;        // the color of the i-th teaching arrow (render.overlays.arrows), -1: the role's
};

class DebugDraw {
 public:
  virtual ~DebugDraw() = default;
  // a closed convex polygon
  virtual void polygon(const std::vector<Vec2>& vertices, const DrawStyle& style) = 0;
  virtual void circle(const Vec2& center, double radius, const DrawStyle& style) = 0;
  // the half-plane {r : n·(r − point) ≤ 0}, to be filled out to the edges of the view
  virtual void halfPlane(const Vec2& point, const Vec2& normal, const DrawStyle& style) = 0;
  virtual void segment(const Vec2& a, const Vec2& b, const DrawStyle& style) = 0;
  virtual void point(const Vec2& p, const DrawStyle& style) = 0;
  virtual void arrow(const Vec2& tail, const Vec2& head, const DrawStyle& style) = 0;
  virtual void text(const Vec2& at, const std::string& text, const DrawStyle& style) = 0;
};

}  // namespace sim::debug
