// A run of the whole scene before anything is drawn, to learn what the frames need to know in
// advance: the region the bodies cover (for the automatic camera), the fastest speed and the
// largest event impulse (for arrow scales), and when impacts happen (for `snapshot --impacts`).
#pragma once

#include <memory>
#include <vector>

#include "render/draw/camera.h"
#include "render/frame/kept_run.h"
#include "render/scene/scene.h"
#include "sim/world/world.h"

namespace render::frame {

struct RunSurvey {
  render::draw::Bounds bounds;      // every body's shape at every step, m
  int farthestBody = -1;            // the body that reached furthest from the origin (or not finite)
  double farthest = 0.0;            // how far, m: the largest coordinate of its box
  double maxSpeed = 0.0;            // of any center of mass, m/s
  double maxImpulse = 0.0;          // of the largest event or impact, N·s
  std::vector<double> impactTimes;  // ascending, each once
  // the lecture overlays' scales (render.overlays)
  double maxOmega = 0.0;                    // |ω| of any body, rad/s
  double maxForce = 0.0;                    // of any point force while it is on, N
  double maxContactForce = 0.0;             // of any contact's normal or friction force (arrows that show them), N
  double maxTorque = 0.0;                   // |Σ r′ × f| of the point forces on any body, N·m
  double maxMomentum = 0.0;                 // |m v| of any moving body, kg·m/s
  double minEnergy = 0.0, maxEnergy = 0.0;  // of any bar of the energy panel (≤ 0, ≥ 0), J
  double maxLinearMomentum = 0.0;           // |Σ m v|, kg·m/s
  double maxAngularMomentum = 0.0;          // |L| about the origin, kg·m²/s
  long steps = 0;                           // the steps the run took, as simulate's run of the same scene takes them
  // the run kept at the instants asked for (none: nothing kept), for the drawing to go on from
  std::shared_ptr<const KeptRun> kept;
};

// the scene run from 0 to `until` (its duration when negative), kept at `keepAt` within `keepBytes`
// (kept_run.h); throws sim::core::Diverged
RunSurvey surveyRun(const render::scene::Scene& def, double until = -1.0, const std::vector<double>& keepAt = {},
                    size_t keepBytes = render::scene::kKeptRunBytes);
// the overlays' extremes of the world now, added into `out` (by surveyRun after every step)
void surveyOverlays(const render::scene::Scene& def, const sim::world::World& world, RunSurvey& out);

// every survey's arrow scales and momenta (not its bounds, impacts or energy bars) set to the extremes
// over all of them, so that side-by-side pictures of variants compare at one scale; each keeps its
// energy bars' own scale, which its values are written beside
void shareScales(const std::vector<RunSurvey*>& surveys);

// the region a body's shape covers now (its position alone for shapes without an extent)
render::draw::Bounds bodyBounds(const sim::core::Body& body);

// an arrow scale, m of arrow per unit: `given` when positive, else one that makes `largest` 1/6 of
// the view's height (1 when there is nothing to scale)
double arrowScale(double given, double largest, const render::draw::Camera& camera);

// the scene's camera: its fixed one, or fitted over `bounds` (the survey's own by default) with its
// margin, above the caption's band when it has a caption and left of the energy panel's when it has one
render::draw::Camera cameraFor(const render::scene::Scene& def, const RunSurvey& survey);
render::draw::Camera cameraFor(const render::scene::Scene& def, const RunSurvey& survey, const render::draw::Bounds& bounds);

// a bad scene (sim::yaml::SceneError at the `camera` key, or at the body that stretched the automatic
// camera so) when `camera`'s view is not finite or past render::scene::kMaxViewExtent
void checkView(const render::scene::Scene& def, const RunSurvey& survey, const render::draw::Camera& camera);

// the times at which the world's collision response applied impulses so far, ascending, each once
std::vector<double> impactTimes(const sim::world::World& world);

}  // namespace render::frame
