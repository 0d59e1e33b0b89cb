// The energy panel of 3D frames: render/frame's BarPanel with a 3D world's bars (per body ½ m v·v
// and ½ ω·L, then U and E) and, with `momentum: true`, p and L about the origin as vectors.
#pragma once

#include <string>
#include <vector>

#include "render/frame/energy_panel.h"
#include "render/frame3d/survey3d.h"

namespace render::frame3d {

// the bars at the world's present state, in the order drawn (energyValues' order)
std::vector<render::frame::EnergyBar> energyBars(const render::scene3d::Scene& def, const sim::world3d::World& world);

class EnergyPanel3d {
 public:
  // `camera` is the overlay's (pixels, y up)
  EnergyPanel3d(const render::scene3d::Scene& def, const render::draw::Camera& camera, const RunSurvey3d& survey);
  void draw(const sim::world3d::World& world, render::draw::Canvas& draw) const;
  // the right-hand band of the frame the panel takes (0 without one), px
  static double bandPx(const render::scene3d::Scene& def, const RunSurvey3d& survey, int heightPx);

 private:
  static std::vector<std::string> widestBarTexts(const render::scene3d::Scene& def, const RunSurvey3d& survey);
  static std::vector<std::string> widestLines(const render::scene3d::Scene& def, const RunSurvey3d& survey);

  const render::scene3d::Scene& def_;
  bool energy_, momentum_;
  render::frame::BarPanel panel_;
};

}  // namespace render::frame3d
