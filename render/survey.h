// A run of the whole scene before anything is drawn, to learn what the frames need to know in
// advance: the region the bodies cover (for the automatic camera), the fastest speed and the
// largest event impulse (for arrow scales), and when impacts happen (for `snapshot --impacts`).
#pragma once

#include <vector>

#include "camera.h"
#include "scene_def.h"
#include "world.h"

namespace render {

struct RunSurvey {
  Bounds bounds;                    // every body's shape at every step, m
  double maxSpeed = 0.0;            // of any center of mass, m/s
  double maxImpulse = 0.0;          // of the largest event or impact, N·s
  std::vector<double> impactTimes;  // ascending, each once
};

// the scene run from 0 to `until` (its duration when negative); throws sim::Diverged
RunSurvey surveyRun(const sim::SceneDef& def, double until = -1.0);

// the region a body's shape covers now (its position alone for shapes without an extent)
Bounds bodyBounds(const sim::Body& body);

// the scene's camera: its fixed one, or fitted over `bounds` with its margin (above the caption's band
// when it has a caption)
Camera cameraFor(const sim::SceneDef& def, const Bounds& bounds);

// the times at which the world's collision response applied impulses so far, ascending, each once
std::vector<double> impactTimes(const sim::World& world);

}  // namespace render
