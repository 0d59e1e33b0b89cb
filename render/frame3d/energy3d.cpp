#include "render/frame3d/energy3d.h"

#include <algorithm>
#include <cmath>

#include "render/frame/quantity_text.h"
#include "render/scene/scene_style.h"
#include "sim/scene3d/scene_build.h"
#include "sim/world3d/diagnostics.h"

namespace render::frame3d {
using render::draw::Role;
using render::frame::BarPanel;
using render::frame::EnergyBar;
using sim::world3d::Vec3;

namespace {

// each component below its vector's noise floor written 0
std::vector<std::string> momentumLines(const Vec3& p, const Vec3& l) {
  return {render::frame::vectorText("p", p, "kg·m/s", render::frame::noiseFloor(p.norm())),
          render::frame::vectorText("L", l, "kg·m²/s", render::frame::noiseFloor(l.norm()))};
}

}  // namespace

std::vector<EnergyBar> energyBars(const render::scene3d::Scene& def, const sim::world3d::World& world) {
  const std::vector<double> values = energyValues(world);
  std::vector<EnergyBar> bars;
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    const std::string& label = def.render.bodies[i].label;
    const std::string& name = label.empty() ? def.model.bodies[i].name : label;
    bars.push_back({name + " ½mv²", values[bars.size()], Role::KineticBar, static_cast<int>(i)});
    bars.push_back({name + " ½ω·L", values[bars.size()], Role::RotationalBar, static_cast<int>(i)});
  }
  if (bars.size() + 2 == values.size()) bars.push_back({"U", values[bars.size()], Role::PotentialBar, -1});
  bars.push_back({"E", values.back(), Role::TotalBar, -1});
  return bars;
}

std::vector<std::string> EnergyPanel3d::widestBarTexts(const render::scene3d::Scene& def, const RunSurvey3d& survey) {
  std::vector<std::string> texts;
  if (!def.render.overlays.energy) return texts;
  const double most = std::max(std::abs(survey.maxEnergy), std::abs(survey.minEnergy));
  for (EnergyBar bar : energyBars(def, sim::scene3d::buildWorld(def.model))) {
    bar.value = -most;
    texts.push_back(BarPanel::barText(bar));
  }
  return texts;
}

std::vector<std::string> EnergyPanel3d::widestLines(const render::scene3d::Scene& def, const RunSurvey3d& survey) {
  if (!def.render.overlays.momentum) return {};
  return momentumLines(Vec3::Constant(-survey.maxLinearMomentum), Vec3::Constant(-survey.maxWorldAngularMomentum));
}

double EnergyPanel3d::bandPx(const render::scene3d::Scene& def, const RunSurvey3d& survey, int heightPx) {
  if (!def.render.overlays.energy && !def.render.overlays.momentum) return 0.0;
  const double em = render::scene::fontSizeFor(def.render, heightPx);
  return BarPanel::bandPx(BarPanel::widthPx(widestBarTexts(def, survey), widestLines(def, survey), em), em);
}

EnergyPanel3d::EnergyPanel3d(const render::scene3d::Scene& def, const render::draw::Camera& camera, const RunSurvey3d& survey)
    : def_(def),
      energy_(def.render.overlays.energy),
      momentum_(def.render.overlays.momentum),
      panel_(widestBarTexts(def, survey), widestLines(def, survey), survey.minEnergy, survey.maxEnergy, camera,
             render::scene::fontSizeFor(def.render, camera.heightPx())) {}

void EnergyPanel3d::draw(const sim::world3d::World& world, render::draw::Canvas& canvas) const {
  if (!energy_ && !momentum_) return;
  const std::vector<std::string> lines =
      momentum_ ? momentumLines(sim::world3d::linearMomentum(world), sim::world3d::angularMomentum(world))
                : std::vector<std::string>{};
  panel_.draw(energy_ ? energyBars(def_, world) : std::vector<EnergyBar>{}, lines, canvas);
}

}  // namespace render::frame3d
