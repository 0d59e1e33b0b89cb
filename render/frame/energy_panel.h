// The energy panel, fixed to the frame's top-right corner: for each moving body a bar of ½mv² and
// one of ½Iω², then the potential energy (when the scene has any) and the total, each with its value
// in J; bars share one scale over the whole run (the survey's extremes), so a video can be compared
// frame to frame. With `momentum: true`, p and L about the origin as text below (or alone).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "render/draw/camera.h"
#include "render/frame/conserved_total.h"
#include "render/frame/survey.h"
#include "render/draw/canvas.h"
#include "render/scene/scene.h"
#include "sim/world/world.h"

namespace render::frame {

struct EnergyBar {
  std::string name;    // e.g. "bar ½mv²", "U", "E"
  double value = 0.0;  // J
  render::draw::Role role = render::draw::Role::TotalBar;
  int body = -1;
};

// the bars' values now, in the order drawn, without their names (the survey takes them every step)
std::vector<double> energyValues(const sim::world::World& world);
// the panel's bars at the world's present state, in the order drawn
std::vector<EnergyBar> energyBars(const render::scene::Scene& def, const sim::world::World& world);

// a panel fixed to the frame's top-right corner: rows of bars, each with its text, then lines of
// text; laid out once from the widest texts it will hold, its bars on one scale from `lowest` to
// `highest` (≤ 0, ≥ 0) so that it neither moves nor rescales over a run. The energy panel of 2D and
// 3D frames alike.
class BarPanel {
 public:
  // `topPx`: the panel's top edge (by default half a line in, as the clock)
  BarPanel(const std::vector<std::string>& widestBarTexts, const std::vector<std::string>& widestLines, double lowest,
           double highest, const render::draw::Camera& camera, double em, double topPx = -1.0);
  // the bars (each with its value in J after its name, 0 below the run's noise floor) and the lines
  // under them; with `measure` (the frame's text widths, px) the panel widens to its widest line where
  // the layout's estimate falls short, so that no number is cut
  void draw(const std::vector<EnergyBar>& bars, const std::vector<std::string>& lines, render::draw::Canvas& draw,
            const std::function<int(const std::string&)>& measure = {}) const;
  // the panel's width at text size `em` px, insets excluded
  static double widthPx(const std::vector<std::string>& widestBarTexts, const std::vector<std::string>& widestLines, double em);
  // the right-hand band of the frame a panel of width `widthPx` takes, insets included, px
  static double bandPx(double widthPx, double em);
  // the top band of the frame a panel of `rows` rows (bars and lines) from `topPx` down takes, its
  // inset below included, px
  static double topBandPx(size_t rows, double em, double topPx);
  // where a panel `widthPx` wide in a frame `frameWidth` wide starts, px from the top: half a line in,
  // or under the texts of the top-left corner (`leftTexts`: the clock, the slow-motion note) where it
  // would reach them
  static double topPx(double widthPx, int frameWidth, double em, const std::vector<std::string>& leftTexts);
  // a bar's text: "name = 1.50 J", 0 below `zeroBelow`
  static std::string barText(const EnergyBar& bar, double zeroBelow = 0.0);

 private:
  // a pixel of the frame in world coordinates
  sim::core::Vec2 at(double xPx, double yPx) const { return camera_.toWorld({xPx, yPx}); }

  render::draw::Camera camera_;
  double lowest_, span_;  // the bars' scale: the run's least value (≤ 0) and largest − least, J
  double zeroBelow_;      // the bars' noise floor, J
  double em_;             // the text size, px
  double top_;            // the panel's top edge, px
  double width_;          // the panel's width as laid out from the run's widest texts, px
};

class EnergyPanel {
 public:
  EnergyPanel(const render::scene::Scene& def, const render::draw::Camera& camera, const RunSurvey& survey);
  // `measure`: the frame's text widths (px), or none (the panel's estimate)
  void draw(const sim::world::World& world, render::draw::Canvas& draw,
            const std::function<int(const std::string&)>& measure = {}) const;
  // the width of the frame's right-hand band the panel takes, insets included (0 without a panel),
  // px: the automatic camera keeps the bodies out of it
  static double bandPx(const render::scene::Scene& def, const RunSurvey& survey, int heightPx);
  // the height of the frame's top band it takes, insets included (0 without a panel), px: the
  // automatic camera keeps the bodies under it where that shows them larger than beside it
  static double topBandPx(const render::scene::Scene& def, const RunSurvey& survey, int widthPx, int heightPx);
  // the panel's top edge in a frame of that size, px (BarPanel::topPx)
  static double topPx(const render::scene::Scene& def, const RunSurvey& survey, int widthPx, int heightPx);

 private:
  // the widest texts over the run: each bar's name with the run's largest magnitude, negative; p and
  // L likewise
  static std::vector<std::string> widestBarTexts(const render::scene::Scene& def, const RunSurvey& survey);
  static std::vector<std::string> widestLines(const render::scene::Scene& def, const RunSurvey& survey);

  // the totals of the scene's first state
  struct Totals {
    double energy = 0.0;
    sim::core::Vec2 momentum = sim::core::Vec2::Zero();
    double angular = 0.0;
  };
  static Totals initialTotals(const render::scene::Scene& def);
  EnergyPanel(const render::scene::Scene& def, const render::draw::Camera& camera, const RunSurvey& survey, const Totals& first);

  const render::scene::Scene& def_;
  bool energy_, momentum_;
  BarPanel panel_;
  // E, p (x, y) and L shown with their first digits wherever the run conserves them
  ConservedTotal energyTotal_, momentumX_, momentumY_, angularTotal_;
  double momentumFloor_, angularFloor_;  // p's and L's noise floors
};

}  // namespace render::frame
