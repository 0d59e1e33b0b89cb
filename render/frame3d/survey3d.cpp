#include "render/frame3d/survey3d.h"

#include <algorithm>
#include <cmath>

#include "render/frame/caption.h"
#include "render/frame/shared_scales.h"
#include "render/frame3d/energy3d.h"
#include "render/jobs/interrupt.h"
#include "render/scene/scene_style.h"
#include "sim/scene3d/scene_build.h"
#include "sim/world3d/diagnostics.h"

namespace render::frame3d {
using namespace sim::world3d;
using namespace render::draw3d;

namespace {

class Surveyor : public StepObserver {
 public:
  Surveyor(const render::scene3d::Scene& def, RunSurvey3d& out) : def_(def), out_(out) {}
  void afterStep(const World& w) override {
    // the survey runs the whole scene before the first frame: Ctrl-C must stop it too
    render::jobs::checkInterrupted();
    for (const Body& b : w.bodies) {
      out_.bounds.add(Ball{b.x, boundingRadius(b.shape)});
      out_.maxSpeed = std::max(out_.maxSpeed, b.v.norm());
      out_.maxOmega = std::max(out_.maxOmega, b.omega.norm());
      out_.maxAngularMomentum = std::max(out_.maxAngularMomentum, b.angularMomentum().norm());
    }
    // the panel's values cost a pass over the bodies: only for scenes that show it
    if (def_.render.overlays.energy)
      for (double value : energyValues(w))
        out_.minEnergy = std::min(out_.minEnergy, value), out_.maxEnergy = std::max(out_.maxEnergy, value);
    if (def_.render.overlays.momentum) {
      out_.maxLinearMomentum = std::max(out_.maxLinearMomentum, linearMomentum(w).norm());
      out_.maxWorldAngularMomentum = std::max(out_.maxWorldAngularMomentum, angularMomentum(w).norm());
    }
  }
  void afterEvent(const World& w, const ImpulseEvent&) override { afterStep(w); }

 private:
  const render::scene3d::Scene& def_;
  RunSurvey3d& out_;
};

}  // namespace

std::vector<double> energyValues(const World& world) {
  std::vector<double> values;
  for (const Body& b : world.bodies) {
    const KineticEnergy k = kineticEnergy(b);
    values.push_back(k.translational);
    values.push_back(k.rotational);
  }
  const Energy e = energy(world);
  // gravity or a spring: the scene has a potential energy (zero at the world origin, as in `check`)
  if (world.def().forces.gravity != Vec3::Zero() || !world.def().forces.springs.empty()) values.push_back(e.potential);
  values.push_back(e.total());
  return values;
}

RunSurvey3d surveyRun(const render::scene3d::Scene& def, double until, const std::vector<double>& keepAt, size_t keepBytes) {
  RunSurvey3d survey;
  World world = sim::scene3d::buildWorld(def.model);
  Surveyor surveyor(def, survey);
  surveyor.afterStep(world);
  // a spring's world anchor belongs in the picture with what hangs from it
  for (const Spring& sp : world.def().forces.springs)
    if (sp.bodyB == sim::core::kWorldAnchor) survey.bounds.add(sp.pointB);
  const double end = until < 0.0 ? def.model.duration : until;
  const auto ended = [&survey](const World& last) {
    // impacts closer than this are one instant (the corners of a face landing flat), as in 2D
    constexpr double kSameInstant = 1e-9;
    for (const ImpactRecord3& r : last.impacts) {
      if (survey.impactTimes.empty() || r.t - survey.impactTimes.back() > kSameInstant) survey.impactTimes.push_back(r.t);
      survey.maxImpulse = std::max(survey.maxImpulse, (r.impulse * r.normal + r.tangentImpulse).norm());
    }
    survey.steps = last.steps;
  };
  if (keepAt.empty()) {
    world.advanceTo(end, &surveyor);
    ended(world);
  } else {
    const auto bytes = [](const SpatialRun::State& s) {
      return sizeof(s) + s.history.pathBytes() + s.world.bodies.capacity() * sizeof(Body) +
             2 * s.world.contacts.capacity() * sizeof(s.world.contacts.front()) +
             s.world.impacts.capacity() * sizeof(ImpactRecord3);
    };
    survey.kept = std::make_shared<const KeptRun3d>(
        render::frame::keepRunOf<SpatialRun::State, History3d::Options, StepObserver, ImpulseEvent, World>(
            keptHistoryOptions(def), std::move(world), end, keepAt, keepBytes, surveyor, bytes, ended));
  }
  return survey;
}

History3d::Options keptHistoryOptions(const render::scene3d::Scene& def) {
  History3d::Options o;
  o.trails = def.render.trails;
  for (const render::scene3d::Arrow3dDef& a : def.space.arrows) {
    if (a.show == render::scene3d::Arrow3dDef::Show::Path) o.points.emplace_back(a.body, a.at);
    if (a.show == render::scene3d::Arrow3dDef::Show::OmegaPath) o.omegaTips.push_back(a.body);
  }
  return o;
}

void shareScales(const std::vector<RunSurvey3d*>& surveys) {
  // (each panel's energy bars on its own run's scale: the values are written beside them)
  render::frame::shareLargest(surveys, &RunSurvey3d::maxSpeed, &RunSurvey3d::maxOmega, &RunSurvey3d::maxAngularMomentum,
                              &RunSurvey3d::maxLinearMomentum, &RunSurvey3d::maxWorldAngularMomentum, &RunSurvey3d::maxImpulse);
}

Camera3d cameraFor(const render::scene3d::Scene& def, const RunSurvey3d& survey) { return cameraFor(def, survey, survey.bounds); }

Camera3d cameraFor(const render::scene3d::Scene& def, const RunSurvey3d& survey, const Box3d& bounds) {
  const render::scene::RenderDef& r = def.render;
  const render::scene3d::Camera3dDef& c = def.space.camera;
  if (!c.automatic) return Camera3d::look(c.eye, c.target, c.up, c.fov, r.width, r.height, bounds.ball());
  // with a caption the bodies are fitted above its band, with an energy panel left of it (a panel
  // wider than half the frame is drawn over the bodies instead: they need the room more)
  const double band = render::frame::captionOf(r, def.model.description).empty()
                          ? 0.0
                          : render::frame::captionLayout(render::scene::fontSizeFor(r, r.height)).band();
  const double panel = EnergyPanel3d::bandPx(def, survey, r.height);
  const int above = static_cast<int>(std::lround(r.height - band));
  const int left = static_cast<int>(std::lround(panel <= 0.5 * r.width ? r.width - panel : r.width));
  return Camera3d::fit(bounds, c.direction, c.up, c.fov, c.margin, r.width, r.height, left, above);
}

}  // namespace render::frame3d
