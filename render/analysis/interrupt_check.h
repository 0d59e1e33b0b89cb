// Ctrl-C during a sweep or a stability search: every run, measured or timed, steps with this
// observer, which throws render::jobs::Interrupted between two steps once SIGINT or SIGTERM came
// (a flag read a step: far below a step's own cost, so the timings stand).
#pragma once

#include "render/jobs/interrupt.h"
#include "sim/world/world.h"
#include "sim/world3d/world.h"

namespace render::analysis {

struct InterruptCheck : sim::world::StepObserver {
  void afterStep(const sim::world::World&) override { render::jobs::checkInterrupted(); }
};

struct InterruptCheck3d : sim::world3d::StepObserver {
  void afterStep(const sim::world3d::World&) override { render::jobs::checkInterrupted(); }
};

}  // namespace render::analysis
