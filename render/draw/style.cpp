#include "render/draw/style.h"

namespace render::draw {

std::array<Color, kRoleCount> Style::defaultRoleColors() {
  std::array<Color, kRoleCount> colors;
  for (const RoleInfo& r : kRoles)
    if (!r.color.empty()) colors[static_cast<size_t>(r.role)] = Color::parse(std::string(r.color));
  return colors;
}

}  // namespace render::draw
