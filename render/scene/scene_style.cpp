#include "render/scene/scene_style.h"

#include <algorithm>
#include <cmath>

namespace render::scene {
using draw::Color;
using draw::Role;

draw::Style makeStyle(const Scene& scene, int frameHeight) {
  std::vector<bool> statics;
  for (const sim::scene::BodyDef& b : scene.model.bodies) statics.push_back(b.isStatic);
  std::vector<std::string> arrowColors;
  for (const ArrowDef& a : scene.render.overlays.arrows) arrowColors.push_back(a.color);
  return makeStyle(scene.render, statics, arrowColors, frameHeight);
}

draw::Style makeStyle(const RenderDef& r, const std::vector<bool>& staticBodies, const std::vector<std::string>& arrowColors,
                      int frameHeight) {
  draw::Style s;
  s.background = Color::parse(r.background);
  for (const draw::RoleInfo& role : draw::kRoles)
    if (!role.colorKey.empty()) s.roles[static_cast<size_t>(role.role)] = Color::parse(r.colors[role.role]);
  for (const std::string& c : arrowColors) s.arrows.push_back(c.empty() ? Color{0.0, 0.0, 0.0, 0.0} : Color::parse(c));
  // the palette in order over the bodies without a color of their own (static ones are gray)
  size_t next = 0;
  for (size_t i = 0; i < staticBodies.size(); ++i) {
    const std::string& own = i < r.bodies.size() ? r.bodies[i].color : std::string();
    if (!own.empty()) s.bodies.push_back(Color::parse(own));
    else if (staticBodies[i]) s.bodies.push_back(s.role(Role::StaticBody));
    else s.bodies.push_back(Color::parse(r.colors.palette[next++ % r.colors.palette.size()]));
  }
  s.lineWidth = lineWidthFor(r, frameHeight);
  s.fontSize = fontSizeFor(r, frameHeight);
  return s;
}

double lineWidthFor(const RenderDef& r, int frameHeight) {
  if (r.lineWidth > 0) return r.lineWidth;
  // 3 px at 1080p, read on a projector; 2 px at 720p, scaled with the frame
  return frameHeight / 360.0;
}

int fontSizeFor(const RenderDef& r, int frameHeight) {
  if (r.fontSize > 0) return static_cast<int>(std::lround(r.fontSize));
  return std::max(11, static_cast<int>(std::lround(frameHeight / 36.0)));
}

}  // namespace render::scene
