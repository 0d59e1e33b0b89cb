#include "render/draw/style.h"

#include <algorithm>
#include <cmath>

namespace render::draw {

Style makeStyle(const sim::scene::SceneDef& scene, int frameHeight) {
  const sim::scene::RenderDef& r = scene.render;
  const sim::scene::ColorsDef& c = r.colors;
  Style s;
  s.background = Color::parse(r.background);
  s.staticBody = Color::parse(c.staticBody);
  s.contact = Color::parse(c.contact);
  s.normal = Color::parse(c.normal);
  s.impulse = Color::parse(c.impulse);
  s.velocity = Color::parse(c.velocity);
  s.trail = Color::parse(c.trail);
  s.referenceEdge = Color::parse(c.referenceEdge);
  s.incidentVertex = Color::parse(c.incidentVertex);
  s.spring = Color::parse(c.spring);
  s.text = Color::parse(c.text);
  s.offset = Color::parse(c.offset);
  s.omega = Color::parse(c.omega);
  s.frame = Color::parse(c.frame);
  s.path = Color::parse(c.path);
  s.force = Color::parse(c.force);
  s.torque = Color::parse(c.torque);
  s.momentum = Color::parse(c.momentum);
  s.potential = Color::parse(c.potential);
  s.total = Color::parse(c.total);
  s.panel = Color::parse(c.panel);
  for (const sim::scene::ArrowDef& a : r.overlays.arrows) s.arrows.push_back(a.color.empty() ? Color{0.0, 0.0, 0.0, 0.0} : Color::parse(a.color));
  // the palette in order over the bodies without a color of their own (static ones are gray)
  size_t next = 0;
  for (const sim::scene::BodyDef& b : scene.bodies) {
    if (!b.color.empty()) s.bodies.push_back(Color::parse(b.color));
    else if (b.isStatic) s.bodies.push_back(s.staticBody);
    else s.bodies.push_back(Color::parse(c.palette[next++ % c.palette.size()]));
  }
  s.lineWidth = r.lineWidth;
  s.fontSize = fontSizeFor(r, frameHeight);
  return s;
}

int fontSizeFor(const sim::scene::RenderDef& r, int frameHeight) {
  if (r.fontSize > 0) return static_cast<int>(std::lround(r.fontSize));
  return std::max(11, static_cast<int>(std::lround(frameHeight / 36.0)));
}

}  // namespace render::draw
