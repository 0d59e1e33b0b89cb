// The `none` method: bodies move freely and pass through each other. Its step, the free motion
// by the chosen integrator, is the first stage of the fixed-step methods too.
#include "sim/world/methods.h"
#include "sim/world/world.h"

namespace sim::world {
using sim::core::Rates;
using sim::core::States;
using namespace sim::core;
using namespace sim::collision;

namespace {

class FreeMotion final : public Method {
 public:
  std::unique_ptr<Method> clone() const override { return std::make_unique<FreeMotion>(*this); }
  void step(World& world, const TimeStep& step) override { moveFreely(world, step); }
};

}  // namespace

std::unique_ptr<Method> makeFreeMotion() { return std::make_unique<FreeMotion>(); }

void StepDynamics::rates(double, const States& y, Rates& out) const { world_.rates(midpoint_, y, out); }

void moveFreely(World& world, const TimeStep& step) {
  States y = world.states();
  integrate(world.def().integrator, StepDynamics(world, step), step.start, step.h, y);
  world.setStates(y);
}

}  // namespace sim::world
