#include "render/frame/survey.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "render/draw/style.h"
#include "render/frame/caption.h"
#include "render/frame/contact_forces.h"
#include "render/frame/energy_panel.h"
#include "render/frame/shared_scales.h"
#include "sim/collision/collide.h"
#include "render/frame/point_forces.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/json_writer.h"
#include "sim/yaml/scene_error.h"
#include "render/scene/scene_style.h"
#include "sim/scene/scene_build.h"
#include "sim/world/diagnostics.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;
using namespace render::scene;

namespace {

// max(largest, scale·√square), the root taken only where it may be the larger: a step's speeds
// rarely raise the survey's, and the root is monotone (the slack covers the product's rounding), so
// the result is the same to the bit as max(largest, scale·√square)
double largerRoot(double largest, double scale, double square) {
  if (!(scale * scale * square >= largest * largest * (1.0 - 1e-9))) return largest;
  return std::max(largest, scale * std::sqrt(square));
}

// the bodies' extent and speed after every step
class Surveyor : public sim::world::StepObserver {
 public:
  Surveyor(const render::scene::Scene& def, RunSurvey& out) : def_(def), out_(out) {}
  void afterStep(const sim::world::World& world) override {
    // the survey runs the whole scene before the first frame: Ctrl-C must stop it too
    render::jobs::checkInterrupted();
    if (extents_.empty()) {
      for (const sim::core::Body& b : world.bodies) {
        extents_.push_back(extentOf(b.shape));
        radii_.push_back(sim::core::boundingRadius(b.shape));
      }
      last_.resize(world.bodies.size());
    }
    for (size_t i = 0; i < world.bodies.size(); ++i) {
      const sim::core::Body& b = world.bodies[i];
      // a static body never moves: its bounds once, at the start
      if (b.isStatic && staticsSeen_) continue;
      out_.maxSpeed = largerRoot(out_.maxSpeed, 1.0, b.v.squaredNorm());
      if (inside(b.x, extents_[i]) || withinLast(b, i)) continue;
      const Bounds box = bodyBounds(b);
      last_[i] = {box, b.x, b.angle};
      out_.bounds.add(box);
      // which body stretches the automatic camera most: the one to name when the view is too large
      const double reach = std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
      if (!(reach <= out_.farthest)) out_.farthest = reach, out_.farthestBody = static_cast<int>(i);
    }
    surveyOverlays(def_, world, out_);
    // another run drawn over ours (--overlay): its bodies in the picture too, so that the automatic
    // camera shows both runs (a student's bar that flies off is not lost while the legend names it)
    if (const auto& overlay = def_.render.overlay)
      for (size_t i = 0; i < world.bodies.size(); ++i) {
        render::scene::TraceOverlayDef::Pose pose;
        if (world.bodies[i].shape.kind == sim::core::ShapeKind::Plane || !overlay->poseAt(i, world.time, pose)) continue;
        sim::core::Body theirs = world.bodies[i];
        theirs.x = pose.x, theirs.angle = pose.angle;
        out_.bounds.add(bodyBounds(theirs));
      }
    staticsSeen_ = true;
  }
  void afterEvent(const sim::world::World& world, const sim::world::ImpulseEvent&) override { afterStep(world); }

 private:
  // a bound on how far a shape reaches from its center along either axis, whatever its turning (no
  // bound, -1, for shapes of parts or without an extent): |c vx − s vy| ≤ |vx| + |vy| even rounded
  static double extentOf(const sim::core::Shape& shape) {
    if (shape.kind == sim::core::ShapeKind::Circle) return shape.radius;
    if (shape.kind != sim::core::ShapeKind::Polygon) return -1.0;
    double most = 0.0;
    for (const Vec2& v : shape.vertices) most = std::max(most, std::abs(v.x()) + std::abs(v.y()));
    return most;
  }
  // the body's shape at `x` lies inside what the survey holds already, and no farther from the
  // origin than its farthest: bodyBounds (a sine and cosine a polygon) would change nothing. Checked
  // with room for the rounding of x ± the extent; false for a position that is not finite
  bool inside(const Vec2& x, double extent) const {
    if (!(extent >= 0.0)) return false;
    const double reach = extent + 1e-9 * (extent + x.cwiseAbs().maxCoeff());
    return covered(x.array() - reach, x.array() + reach);
  }
  // the same with the body's bounds when they were last taken, moved along with its center and
  // grown by how far its turning since has carried any point of it, r |Δθ| (an arc is longer than
  // its chord), with room for rounding. A body near the view's edge, where its extent reaches past
  // it, then takes its bounds (a sine and cosine) only where it may be going past that edge. Along
  // an axis where neither its center nor its angle has changed, the bounds are the same to the bit,
  // so a body resting at the edge (the one that set it) needs no room there
  bool withinLast(const sim::core::Body& b, size_t i) const {
    const LastBounds& last = last_[i];
    if (last.box.empty()) return false;
    const double r = radii_[i];
    const double grow = r * std::abs(b.angle - last.angle) +
                        1e-9 * (r * (1.0 + std::abs(b.angle)) + b.x.cwiseAbs().maxCoeff() + last.x.cwiseAbs().maxCoeff());
    Vec2 lo = last.box.min, hi = last.box.max;
    for (int a = 0; a < 2; ++a) {
      if (b.x[a] == last.x[a] && b.angle == last.angle) continue;
      lo[a] += b.x[a] - last.x[a] - grow;
      hi[a] += b.x[a] - last.x[a] + grow;
    }
    return covered(lo, hi);
  }
  // [lo, hi] lies inside what the survey holds already, and no farther from the origin than its
  // farthest (false where either is not finite)
  bool covered(const Vec2& lo, const Vec2& hi) const {
    const Bounds& b = out_.bounds;
    return lo.x() >= b.min.x() && lo.y() >= b.min.y() && hi.x() <= b.max.x() && hi.y() <= b.max.y() &&
           std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()) <= out_.farthest;
  }

  // a body's bounds where they were last taken
  struct LastBounds {
    Bounds box;  // empty: not taken yet
    Vec2 x = Vec2::Zero();
    double angle = 0.0;
  };

  const render::scene::Scene& def_;
  RunSurvey& out_;
  std::vector<double> extents_;   // extentOf each body's shape
  std::vector<double> radii_;     // how far each body's shape reaches from its center
  std::vector<LastBounds> last_;  // each body's
  bool staticsSeen_ = false;      // the static bodies' bounds are in
};

}  // namespace

Bounds bodyBounds(const sim::core::Body& b) {
  Bounds box;
  switch (b.shape.kind) {
    case sim::core::ShapeKind::Polygon:
      for (const Vec2& v : b.shape.vertices) box.add(b.pose().toWorld(v));
      break;
    case sim::core::ShapeKind::Circle:
      box.add(b.x - Vec2(b.shape.radius, b.shape.radius));
      box.add(b.x + Vec2(b.shape.radius, b.shape.radius));
      break;
    case sim::core::ShapeKind::Compound: {
      const sim::collision::Aabb parts = sim::collision::bounds(b.shape, b.pose());
      box.add(parts.lower);
      box.add(parts.upper);
      break;
    }
    default:
      // unbounded shapes (a half-plane): the point that anchors them should be in view
      box.add(b.x);
  }
  return box;
}

RunSurvey surveyRun(const render::scene::Scene& def, double until, const std::vector<double>& keepAt, size_t keepBytes) {
  RunSurvey survey;
  for (const sim::scene::EventDef& e : def.model.events) survey.maxImpulse = std::max(survey.maxImpulse, e.impulse.norm());
  sim::world::World world = sim::scene::buildWorld(def.model);
  Surveyor surveyor(def, survey);
  surveyor.afterStep(world);
  // a spring's world anchor belongs in the picture with what hangs from it
  for (const sim::core::Spring& sp : world.def().forces.springs)
    if (sp.bodyB == sim::core::kWorldAnchor) survey.bounds.add(sp.pointB);
  const double end = until < 0.0 ? def.model.duration : until;
  const auto ended = [&survey](const sim::world::World& last) {
    for (const sim::world::ImpactRecord& r : last.impacts) survey.maxImpulse = std::max(survey.maxImpulse, std::abs(r.impulse));
    survey.impactTimes = impactTimes(last);
    survey.steps = last.steps;
  };
  if (keepAt.empty()) {
    world.advanceTo(end, &surveyor);
    ended(world);
  } else {
    survey.kept = std::make_shared<const KeptRun>(keepRun(def, std::move(world), end, keepAt, keepBytes, surveyor, ended));
  }
  return survey;
}

void surveyOverlays(const render::scene::Scene& def, const sim::world::World& world, RunSurvey& out) {
  // the contact forces of the bodies whose arrows show them
  for (const render::scene::ArrowDef& a : def.render.overlays.arrows)
    if (a.show == render::scene::ArrowDef::Show::NormalForce || a.show == render::scene::ArrowDef::Show::Friction)
      for (const ContactForce& f : contactForcesOn(world, a.body))
        out.maxContactForce = std::max({out.maxContactForce, f.normal.norm(), f.friction.norm()});
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    const sim::core::Body& b = world.bodies[i];
    if (b.isStatic) continue;
    out.maxOmega = std::max(out.maxOmega, std::abs(b.omega));
    out.maxMomentum = largerRoot(out.maxMomentum, b.mass, b.v.squaredNorm());
    if (world.def().forces.pointForces.empty()) continue;
    const std::vector<AppliedForce> forces = pointForcesOn(world, static_cast<int>(i));
    for (const AppliedForce& f : forces) out.maxForce = std::max(out.maxForce, f.force.norm());
    out.maxTorque = std::max(out.maxTorque, std::abs(torqueOf(b, forces)));
  }
  // the panel's values cost a pass over the bodies: only for scenes that show it
  const render::scene::OverlaysDef& o = def.render.overlays;
  if (o.energy)
    for (double value : energyValues(world)) {
      out.minEnergy = std::min(out.minEnergy, value);
      out.maxEnergy = std::max(out.maxEnergy, value);
    }
  if (o.momentum) {
    out.maxLinearMomentum = std::max(out.maxLinearMomentum, sim::world::linearMomentum(world).norm());
    out.maxAngularMomentum = std::max(out.maxAngularMomentum, std::abs(sim::world::angularMomentum(world)));
  }
}

double arrowScale(double given, double largest, const Camera& camera) {
  // the largest value's arrow is this fraction of the view's height
  constexpr double kArrowFraction = 1.0 / 6.0;
  if (given > 0.0) return given;
  return largest > 0.0 ? kArrowFraction * camera.worldHeight() / largest : 1.0;
}

Camera cameraFor(const render::scene::Scene& def, const RunSurvey& survey) { return cameraFor(def, survey, survey.bounds); }

Camera cameraFor(const render::scene::Scene& def, const RunSurvey& survey, const Bounds& bounds) {
  const render::scene::RenderDef& r = def.render;
  if (!r.camera.automatic) return Camera(r.camera.center, r.camera.height, r.width, r.height);
  // with a caption the bodies are fitted above its band, and with an energy panel beside it or under
  // it, whichever shows them larger, so that neither ever covers them
  const double band = captionOf(def).empty() ? 0.0 : captionLayout(fontSizeFor(r, r.height)).band();
  const int above = static_cast<int>(std::lround(r.height - band));
  // the part of the frame left free for the bodies, px (y down): x in [0, right), y in [top, above)
  int right = r.width, top = 0;
  Camera fitted = Camera::fit(bounds, r.camera.margin, right, above);
  if (const double panel = EnergyPanel::bandPx(def, survey, r.height); panel > 0.0) {
    const int beside = static_cast<int>(std::lround(r.width - panel));
    const int under = static_cast<int>(std::lround(EnergyPanel::topBandPx(def, survey, r.width, r.height)));
    const auto fits = [](int w, int h) { return w >= kMinFrameSide && h >= kMinFrameSide; };
    std::optional<Camera> besideIt, underIt;
    if (fits(beside, above)) besideIt = Camera::fit(bounds, r.camera.margin, beside, above);
    if (fits(r.width, above - under)) underIt = Camera::fit(bounds, r.camera.margin, r.width, above - under);
    // beside it unless under it shows the bodies clearly larger (a tenth): a frame keeps its look
    // where both do alike
    if (underIt && (!besideIt || underIt->pixelSize() < 0.9 * besideIt->pixelSize())) fitted = *underIt, top = under;
    else if (besideIt) fitted = *besideIt, right = beside;
  }
  if (right == r.width && top == 0 && above == r.height) return fitted;
  // the same scale over the whole frame, the fitted region's center moved to the middle of the free part
  const double px = fitted.pixelSize();
  const Vec2 shift((0.5 * r.width - 0.5 * right) * px, -(0.5 * r.height - 0.5 * (top + above)) * px);
  return Camera(fitted.center() + shift, px * r.height, r.width, r.height);
}

void checkView(const render::scene::Scene& def, const RunSurvey& survey, const Camera& camera) {
  const Bounds view = camera.view();
  const double extent = std::max({view.size().maxCoeff(), view.min.cwiseAbs().maxCoeff(), view.max.cwiseAbs().maxCoeff()});
  if (extent <= kMaxViewExtent && camera.pixelSize() > 0.0) return;
  const bool fixed = !def.render.camera.automatic;
  const int body = survey.farthestBody;
  sim::core::SourceLoc at = def.render.camera.loc;
  std::string what = "the fixed camera's view";
  if (!fixed && body >= 0 && body < static_cast<int>(def.model.bodies.size())) {
    at = def.model.bodies[body].loc;
    what = "body '" + def.model.bodies[body].name + "' reaches " + render::jobs::formatNumber(survey.farthest) +
           " m from the origin during the run, so the automatic camera's view";
  }
  throw sim::yaml::SceneError(def.file, at.line, at.column,
                              what +
                                  " spans more than 1e150 m and its pixels are not finite numbers; keep the bodies "
                                  "within that (check gravity, speeds and positions) or give a fixed camera");
}

void shareScales(const std::vector<RunSurvey*>& surveys) {
  // (not the bounds, impacts or energy bars: each panel's bars on its own run's scale, so that a
  // 0.5 J variant's bars do not vanish beside a 200 J one; the values are written beside them)
  shareLargest(surveys, &RunSurvey::maxSpeed, &RunSurvey::maxImpulse, &RunSurvey::maxOmega, &RunSurvey::maxForce,
               &RunSurvey::maxContactForce, &RunSurvey::maxTorque, &RunSurvey::maxMomentum, &RunSurvey::maxLinearMomentum,
               &RunSurvey::maxAngularMomentum);
}

std::vector<double> impactTimes(const sim::world::World& world) {
  // impacts closer than this are one instant (several points of one manifold, simultaneous hits)
  constexpr double kSameInstant = 1e-9;
  std::vector<double> times;
  for (const sim::world::ImpactRecord& r : world.impacts) times.push_back(r.t);
  std::sort(times.begin(), times.end());
  std::vector<double> distinct;
  for (double t : times)
    if (distinct.empty() || t - distinct.back() > kSameInstant) distinct.push_back(t);
  return distinct;
}

}  // namespace render::frame
