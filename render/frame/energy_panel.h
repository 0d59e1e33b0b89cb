// The energy panel, fixed to the frame's top-right corner: for each moving body a bar of ½mv² and
// one of ½Iω², then the potential energy (when the scene has any) and the total, each with its value
// in J; bars share one scale over the whole run (the survey's extremes), so a video can be compared
// frame to frame. With `momentum: true`, p and L about the origin as text below (or alone).
#pragma once

#include <string>
#include <vector>

#include "render/draw/camera.h"
#include "render/frame/survey.h"
#include "render/draw/canvas.h"
#include "render/scene/scene.h"
#include "sim/world/world.h"

namespace render::frame {
using namespace render::draw;
using namespace render::scene;

struct EnergyBar {
  std::string name;  // e.g. "bar ½mv²", "U", "E"
  double value = 0.0;  // J
  Role role = Role::TotalBar;
  int body = -1;
};

// the bars' values now, in the order drawn, without their names (the survey takes them every step)
std::vector<double> energyValues(const sim::world::World& world);
// the panel's bars at the world's present state, in the order drawn
std::vector<EnergyBar> energyBars(const render::scene::Scene& def, const sim::world::World& world);

class EnergyPanel {
 public:
  EnergyPanel(const render::scene::Scene& def, const Camera& camera, const RunSurvey& survey);
  void draw(const sim::world::World& world, Canvas& draw) const;
  // the width of the frame's right-hand band the panel takes, insets included (0 without a panel),
  // px: the automatic camera keeps the bodies out of it
  static double bandPx(const render::scene::Scene& def, const RunSurvey& survey, int heightPx);

 private:
  // the panel's width at text size `em` px, from its widest texts over the run
  static double widthPx(const render::scene::Scene& def, const RunSurvey& survey, double em);
  // a pixel of the frame in world coordinates
  Vec2 at(double xPx, double yPx) const { return camera_.toWorld({xPx, yPx}); }

  const render::scene::Scene& def_;
  Camera camera_;
  bool energy_, momentum_;
  double lowest_, span_;   // the bars' scale: the run's least value (≤ 0) and largest − least, J
  double em_;              // the text size, px
  double left_, width_;    // the panel's left edge and width, px
  double barLeft_, textLeft_;
};

}  // namespace render::frame
