#include "render/draw/style.h"

namespace render::draw {

std::array<Color, kRoleCount> Style::defaultRoleColors() {
  std::array<Color, kRoleCount> colors;
  for (const RoleInfo& r : kRoles)
    if (!r.color.empty()) colors[static_cast<size_t>(r.role)] = Color::parse(std::string(r.color));
  return colors;
}

Color Style::penColor(const Pen& pen) const {
  if (pen.color >= 0 && pen.color < static_cast<int>(arrows.size()) && arrows[pen.color].a > 0.0) return arrows[pen.color];
  if (pen.role == Role::Body || pen.role == Role::StaticBody || pen.role == Role::BodyAxis || pen.role == Role::RotationalBar ||
      pen.role == Role::Trail || info(pen.role).colorKey.empty())
    return body(pen.body);
  return role(pen.role);
}

}  // namespace render::draw
