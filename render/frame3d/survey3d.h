// A run of the whole 3D scene before anything is drawn, as render/frame's survey does for 2D: the
// region the bodies cover (for the automatic camera), and the largest |v|, |ω|, |L| and energies
// (for the arrows' and the energy panel's scales, fixed over a video).
#pragma once

#include <memory>
#include <vector>

#include "render/draw3d/camera3d.h"
#include "render/frame/kept_run_of.h"
#include "render/frame/stepped_run.h"
#include "render/frame3d/history3d.h"
#include "render/scene3d/scene.h"
#include "sim/world3d/world.h"

namespace render::frame3d {

using SpatialRun =
    render::frame::SteppedRun<sim::world3d::World, History3d, sim::world3d::StepObserver, sim::world3d::ImpulseEvent>;
// the survey's run kept at the pictures' instants, as in 2D (render/frame/kept_run.h)
using KeptRun3d = render::frame::KeptRunOf<SpatialRun::State, History3d::Options>;

struct RunSurvey3d {
  render::draw3d::Box3d bounds;             // every body's bounding ball at every step, and the anchors, m
  double maxSpeed = 0.0;                    // |v| of any body, m/s
  double maxOmega = 0.0;                    // |ω| of any body, rad/s
  double maxAngularMomentum = 0.0;          // |L| of any body about its center, kg·m²/s
  double minEnergy = 0.0, maxEnergy = 0.0;  // of any bar of the energy panel (≤ 0, ≥ 0), J
  double maxLinearMomentum = 0.0;           // |Σ m v|, kg·m/s
  double maxWorldAngularMomentum = 0.0;     // |L| about the origin, kg·m²/s
  std::vector<double> impactTimes;          // every distinct instant of an impact (slow motion, --impacts)
  double maxImpulse = 0.0;                  // |j| of any impact, N·s (the impulse arrows' scale)
  long steps = 0;                           // the steps the run took, as simulate's run of the scene takes them
  std::shared_ptr<const KeptRun3d> kept;    // the run kept at the instants asked for (none: nothing kept)
};

// the scene run from 0 to `until` (its duration when negative), kept at `keepAt` within `keepBytes`; throws
// sim::core::Diverged
RunSurvey3d surveyRun(const render::scene3d::Scene& def, double until = -1.0, const std::vector<double>& keepAt = {},
                      size_t keepBytes = render::scene::kKeptRunBytes);
// what the history of a run of `def` records, whatever the camera: every step's point of each path
History3d::Options keptHistoryOptions(const render::scene3d::Scene& def);
// the scales (not the bounds) of every survey set to the extremes over all, for panels side by side
void shareScales(const std::vector<RunSurvey3d*>& surveys);

// the energy panel's bars now: per body ½ m v·v and ½ ω·L, the potential energy (with gravity or a
// spring), the total
std::vector<double> energyValues(const sim::world3d::World& world);

// the scene's camera: fixed, or fitted over `bounds` (the survey's own by default) along its view
// direction, above the caption's band and left of the energy panel's
render::draw3d::Camera3d cameraFor(const render::scene3d::Scene& def, const RunSurvey3d& survey);
render::draw3d::Camera3d cameraFor(const render::scene3d::Scene& def, const RunSurvey3d& survey,
                                   const render::draw3d::Box3d& bounds);

}  // namespace render::frame3d
