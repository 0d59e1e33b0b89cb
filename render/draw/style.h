// What each role looks like in one scene's frames: the role table's colors as the scene sets them,
// each body's color, the line width and the text size in output pixels. The canvas turns a Pen
// (role, body, opacity) into GL colors and sizes through this.
#pragma once

#include <array>
#include <vector>

#include "render/draw/color.h"
#include "render/draw/roles.h"

namespace render::draw {

struct Style {
  Color background{1.0, 1.0, 1.0, 1.0};
  std::array<Color, kRoleCount> roles = defaultRoleColors();  // by role (unused for a body's color)
  std::vector<Color> bodies;                                  // by body index
  std::vector<Color> arrows;  // by teaching arrow (render.overlays.arrows): its own color or none (alpha 0)
  double lineWidth = 2.0;     // output pixels
  int fontSize = 20;          // output pixels per em

  const Color& role(Role r) const { return roles[static_cast<size_t>(r)]; }
  // a body's base color; the trail's for -1 or an index past the end
  Color body(int index) const {
    return index >= 0 && index < static_cast<int>(bodies.size()) ? bodies[index] : role(Role::Trail);
  }
  // the table's default color of every role
  static std::array<Color, kRoleCount> defaultRoleColors();
  // a pen's base colour, before its opacity: a teaching arrow's own, a role's from the table, else
  // its body's
  Color penColor(const Pen& pen) const;
};

}  // namespace render::draw
