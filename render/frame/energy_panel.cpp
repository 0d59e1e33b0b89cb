#include "render/frame/energy_panel.h"

#include <algorithm>
#include <cmath>

#include "render/draw/style.h"
#include "render/draw/text.h"
#include "render/frame/overlay_key.h"
#include "render/frame/quantity_text.h"
#include "render/scene/scene_style.h"
#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;
using namespace render::scene;

namespace {

// the layout in text heights (em): inset from the frame's edges as the time caption, padding inside,
// the pitch of rows, the bars' width
constexpr double kInset = 0.5, kPad = 0.4, kRow = 1.3, kBar = 8.0;
// a bar's top and bottom within its row: centered on a line of text
constexpr double kBarTop = 0.5 * kLineHeight - 0.45, kBarBottom = 0.5 * kLineHeight + 0.45;
// the panel is laid out once, from the widest text the run can write, in em
double textWidth(const std::string& text) { return approximateWidth(text, 1.0); }

}  // namespace

std::vector<double> energyValues(const sim::world::World& world) {
  std::vector<double> values;
  for (const sim::core::Body& b : world.bodies) {
    if (b.isStatic) continue;
    const sim::world::KineticEnergy k = sim::world::kineticEnergy(b);
    values.push_back(k.translational);
    values.push_back(k.rotational);
  }
  const sim::world::Energy e = sim::world::energy(world);
  // gravity or a spring: the scene has a potential energy (its zero is the world origin, as in `check`)
  if (world.def().forces.gravity != Vec2::Zero() || !world.def().forces.springs.empty()) values.push_back(e.potential);
  values.push_back(e.total());
  return values;
}

std::vector<EnergyBar> energyBars(const render::scene::Scene& def, const sim::world::World& world) {
  const std::vector<double> values = energyValues(world);
  std::vector<EnergyBar> bars;
  // the names and roles in energyValues' order: two bars per moving body, then U when there is one, E
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    if (world.bodies[i].isStatic) continue;
    const std::string& name = def.render.bodies[i].label.empty() ? def.model.bodies[i].name : def.render.bodies[i].label;
    bars.push_back({name + " ½mv²", values[bars.size()], Role::KineticBar, static_cast<int>(i)});
    bars.push_back({name + " ½Iω²", values[bars.size()], Role::RotationalBar, static_cast<int>(i)});
  }
  if (bars.size() + 2 == values.size()) bars.push_back({"U", values[bars.size()], Role::PotentialBar, -1});
  bars.push_back({"E", values.back(), Role::TotalBar, -1});
  return bars;
}

BarPanel::BarPanel(const std::vector<std::string>& widestBarTexts, const std::vector<std::string>& widestLines, double lowest,
                   double highest, const Camera& camera, double em, double topPx)
    : camera_(camera),
      lowest_(std::min(0.0, lowest)),
      span_(std::max(0.0, highest) - std::min(0.0, lowest)),
      zeroBelow_(noiseFloor(std::max(std::abs(lowest), std::abs(highest)))),
      em_(em),
      top_(topPx >= 0.0 ? topPx : kInset * em) {
  width_ = widthPx(widestBarTexts, widestLines, em_);
}

std::string BarPanel::barText(const EnergyBar& bar, double zeroBelow) {
  return quantityText(bar.name, bar.value, "J", zeroBelow);
}

double BarPanel::widthPx(const std::vector<std::string>& widestBarTexts, const std::vector<std::string>& widestLines, double em) {
  double barWidth = 0.0, lineWidth = 0.0;
  for (const std::string& t : widestBarTexts) barWidth = std::max(barWidth, kBar + 0.5 + textWidth(t));
  for (const std::string& t : widestLines) lineWidth = std::max(lineWidth, textWidth(t));
  return (2.0 * kPad + std::max(barWidth, lineWidth)) * em;
}

double BarPanel::bandPx(double widthPx, double em) { return widthPx + 2.0 * kInset * em; }

double BarPanel::topBandPx(size_t rows, double em, double topPx) {
  return topPx + (kInset + 2.0 * kPad + kRow * static_cast<double>(rows)) * em;
}

double BarPanel::topPx(double widthPx, int frameWidth, double em, const std::vector<std::string>& leftTexts) {
  // the corner's texts, as the clock stands: half a line in, a caption's line (1.25 em) apart
  double reach = 0.0;
  for (const std::string& t : leftTexts) reach = std::max(reach, kInset * em + approximateWidth(t, em));
  const double left = frameWidth - kInset * em - widthPx;
  if (leftTexts.empty() || left >= reach + em) return kInset * em;
  return kInset * em + 1.25 * em * static_cast<double>(leftTexts.size()) + kInset * em;
}

void BarPanel::draw(const std::vector<EnergyBar>& bars, const std::vector<std::string>& lines, Canvas& draw,
                    const std::function<int(const std::string&)>& measure) const {
  std::vector<std::string> texts;
  for (const EnergyBar& bar : bars) texts.push_back(barText(bar, zeroBelow_));
  // as wide as its widest line: the run's estimate, or wider where this frame's text is
  double width = width_;
  if (measure) {
    double widest = 0.0;
    for (const std::string& t : texts) widest = std::max(widest, (kBar + 0.5) * em_ + measure(t));
    for (const std::string& l : lines) widest = std::max(widest, static_cast<double>(measure(l)));
    width = std::max(width, widest + 2.0 * kPad * em_);
  }
  const double left = camera_.widthPx() - kInset * em_ - width, barLeft = left + kPad * em_,
               textLeft = barLeft + (kBar + 0.5) * em_;
  const int rows = static_cast<int>(bars.size() + lines.size());
  const double top = top_, right = left + width, bottom = top + (2.0 * kPad + kRow * rows) * em_;
  draw.polygon({at(left, top), at(right, top), at(right, bottom), at(left, bottom)}, {Role::Panel, -1, 1.0});
  double y = top + kPad * em_;
  // a bar from the zero of the shared scale, to the right for positive values
  const double zero = barLeft + (span_ > 0.0 ? -lowest_ / span_ : 0.0) * kBar * em_;
  for (size_t i = 0; i < bars.size(); ++i) {
    const EnergyBar& bar = bars[i];
    const double value = std::abs(bar.value) < zeroBelow_ ? 0.0 : bar.value;
    const double end = zero + (span_ > 0.0 ? value / span_ : 0.0) * kBar * em_;
    const double y0 = y + kBarTop * em_, y1 = y + kBarBottom * em_;
    // a bar under half a pixel long is not drawn: nothing to see, and no sliver
    if (std::abs(end - zero) >= 0.5)
      draw.polygon({at(zero, y0), at(end, y0), at(end, y1), at(zero, y1)}, {bar.role, bar.body, 1.0});
    draw.text(at(textLeft, y), texts[i], {Role::Caption, -1, 1.0});
    y += kRow * em_;
  }
  for (const std::string& line : lines) {
    draw.text(at(barLeft, y), line, {Role::Caption, -1, 1.0});
    y += kRow * em_;
  }
}

std::vector<std::string> EnergyPanel::widestBarTexts(const render::scene::Scene& def, const RunSurvey& survey) {
  std::vector<std::string> texts;
  if (!def.render.overlays.energy) return texts;
  const double most = std::max(std::abs(survey.maxEnergy), std::abs(survey.minEnergy));
  for (EnergyBar bar : energyBars(def, sim::scene::buildWorld(def.model))) {
    bar.value = -most;
    texts.push_back(BarPanel::barText(bar));
  }
  return texts;
}

std::vector<std::string> EnergyPanel::widestLines(const render::scene::Scene& def, const RunSurvey& survey) {
  if (!def.render.overlays.momentum) return {};
  const double p = survey.maxLinearMomentum, l = survey.maxAngularMomentum;
  return {vectorText("p", Vec2(-p, -p), "kg·m/s"), quantityText("L", -l, "kg·m²/s")};
}

double EnergyPanel::bandPx(const render::scene::Scene& def, const RunSurvey& survey, int heightPx) {
  const render::scene::OverlaysDef& o = def.render.overlays;
  if (!o.energy && !o.momentum) return 0.0;
  const double em = fontSizeFor(def.render, heightPx);
  return BarPanel::bandPx(BarPanel::widthPx(widestBarTexts(def, survey), widestLines(def, survey), em), em);
}

double EnergyPanel::topPx(const render::scene::Scene& def, const RunSurvey& survey, int widthPx, int heightPx) {
  const double em = fontSizeFor(def.render, heightPx);
  // the clock ("t = 10.000 s" at its widest) and, in a video, the slow-motion note under it
  std::vector<std::string> corner;
  if (def.render.time) corner.push_back("t = 10.000 s");
  if (!def.render.slowMotion.empty()) corner.push_back("slow motion ×1/10");
  // and the overlay key's rows, each with its sample before it
  for (const std::string& row : possibleKeyRows(def.render, !survey.impactTimes.empty())) corner.push_back("MM " + row);
  return BarPanel::topPx(BarPanel::widthPx(widestBarTexts(def, survey), widestLines(def, survey), em), widthPx, em, corner);
}

double EnergyPanel::topBandPx(const render::scene::Scene& def, const RunSurvey& survey, int widthPx, int heightPx) {
  const render::scene::OverlaysDef& o = def.render.overlays;
  if (!o.energy && !o.momentum) return 0.0;
  const size_t rows = (o.energy ? energyBars(def, sim::scene::buildWorld(def.model)).size() : 0) + (o.momentum ? 2 : 0);
  return BarPanel::topBandPx(rows, fontSizeFor(def.render, heightPx), topPx(def, survey, widthPx, heightPx));
}

EnergyPanel::EnergyPanel(const render::scene::Scene& def, const Camera& camera, const RunSurvey& survey)
    : EnergyPanel(def, camera, survey, initialTotals(def)) {}

EnergyPanel::Totals EnergyPanel::initialTotals(const render::scene::Scene& def) {
  const sim::world::World world = sim::scene::buildWorld(def.model);
  return {sim::world::energy(world).total(), sim::world::linearMomentum(world), sim::world::angularMomentum(world)};
}

EnergyPanel::EnergyPanel(const render::scene::Scene& def, const Camera& camera, const RunSurvey& survey, const Totals& first)
    : def_(def),
      energy_(def.render.overlays.energy),
      momentum_(def.render.overlays.momentum),
      panel_(widestBarTexts(def, survey), widestLines(def, survey), survey.minEnergy, survey.maxEnergy, camera,
             fontSizeFor(def.render, camera.heightPx()), topPx(def, survey, camera.widthPx(), camera.heightPx())),
      energyTotal_(first.energy, std::max(std::abs(survey.minEnergy), std::abs(survey.maxEnergy))),
      momentumX_(first.momentum.x(), survey.maxLinearMomentum),
      momentumY_(first.momentum.y(), survey.maxLinearMomentum),
      angularTotal_(first.angular, survey.maxAngularMomentum),
      momentumFloor_(noiseFloor(survey.maxLinearMomentum)),
      angularFloor_(noiseFloor(survey.maxAngularMomentum)) {}

void EnergyPanel::draw(const sim::world::World& world, Canvas& draw,
                       const std::function<int(const std::string&)>& measure) const {
  std::vector<std::string> lines;
  if (momentum_) {
    const Vec2 p = sim::world::linearMomentum(world);
    lines = {vectorText("p", Vec2(momentumX_.shown(p.x()), momentumY_.shown(p.y())), "kg·m/s", momentumFloor_),
             quantityText("L", angularTotal_.shown(sim::world::angularMomentum(world)), "kg·m²/s", angularFloor_)};
  }
  std::vector<EnergyBar> bars = energy_ ? energyBars(def_, world) : std::vector<EnergyBar>{};
  if (!bars.empty()) bars.back().value = energyTotal_.shown(bars.back().value);
  panel_.draw(bars, lines, draw, measure);
}

}  // namespace render::frame
