// The survey of a run (survey.cpp): the scales shared by side-by-side variants, and what it finds
// of a run while skipping what cannot change.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "render/frame/survey.h"
#include "sim/scene/scene_build.h"
#include "support/drawn_scene.h"

TEST_CASE("shareScales gives every survey the extremes of all, and keeps each one's bounds, impacts and energy bars") {
  render::frame::RunSurvey a, b;
  a.maxSpeed = 1.0, b.maxSpeed = 3.0;
  a.maxImpulse = 2.0, b.maxImpulse = 0.5;
  a.maxOmega = 0.1, b.maxOmega = 0.2;
  a.maxForce = 4.0, b.maxTorque = 5.0, a.maxMomentum = 6.0;
  a.minEnergy = -1.0, b.minEnergy = -2.0;
  a.maxEnergy = 5.41, b.maxEnergy = 2.0;
  a.maxLinearMomentum = 1.0, b.maxAngularMomentum = 7.0;
  a.bounds.add(sim::core::Vec2(0, 0));
  b.bounds.add(sim::core::Vec2(10, 10));
  a.impactTimes = {0.5};
  render::frame::shareScales({&a, &b});
  for (const render::frame::RunSurvey* s : {&a, &b}) {
    CHECK(s->maxSpeed == 3.0);
    CHECK(s->maxImpulse == 2.0);
    CHECK(s->maxOmega == 0.2);
    CHECK(s->maxForce == 4.0);
    CHECK(s->maxTorque == 5.0);
    CHECK(s->maxMomentum == 6.0);
    CHECK(s->maxLinearMomentum == 1.0);
    CHECK(s->maxAngularMomentum == 7.0);
  }
  // a 2 J variant's bars are not shrunk beside a 5.41 J one's
  CHECK(a.minEnergy == -1.0);
  CHECK(a.maxEnergy == 5.41);
  CHECK(b.minEnergy == -2.0);
  CHECK(b.maxEnergy == 2.0);
  CHECK(a.impactTimes == std::vector<double>{0.5});
  CHECK(b.impactTimes.empty());
  CHECK(a.bounds.max == sim::core::Vec2(0, 0));
  CHECK(b.bounds.min == sim::core::Vec2(10, 10));
}

namespace {

// what the survey finds when it looks at every body after every step, skipping nothing
struct EveryStep : sim::world::StepObserver {
  render::draw::Bounds bounds;
  double farthest = -1.0, maxSpeed = 0.0, maxMomentum = 0.0;
  int farthestBody = -1;
  void afterStep(const sim::world::World& w) override {
    for (size_t i = 0; i < w.bodies.size(); ++i) {
      const sim::core::Body& b = w.bodies[i];
      const render::draw::Bounds box = render::frame::bodyBounds(b);
      bounds.add(box);
      const double reach = std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
      if (!(reach <= farthest)) farthest = reach, farthestBody = static_cast<int>(i);
      maxSpeed = std::max(maxSpeed, b.v.norm());
      if (!b.isStatic) maxMomentum = std::max(maxMomentum, b.mass * b.v.norm());
    }
  }
  void afterEvent(const sim::world::World& w, const sim::world::ImpulseEvent&) override { afterStep(w); }
};

}  // namespace

TEST_CASE("the survey skips a body's bounds and square roots only where they change nothing: the same to the bit") {
  // bodies that fall, bounce, spin and come to rest on a floor at the view's edges, a body of parts
  // and a static box: the survey looks at most of them by their extent or their last bounds moved
  const std::string scenes[] = {R"(
duration: 2
world: {gravity: [0, -9.81], restitution: 0.8}
sim: {collisions: event, integrator: rk4, dt: 1.0e-3}
bodies:
  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}
  - {name: a, shape: {circle: 0.2}, position: [-2, 1.0]}
  - {name: c, shape: {box: [0.4, 0.3]}, position: [0, 1.4], angle: 0.3, angular_velocity: 2}
  - {name: e, shape: {box: [0.3, 0.3]}, position: [2, 1.8], velocity: [0.5, 0]}
)",
                                R"(
duration: 3
world: {gravity: [0, -9.81], friction: 0.4}
bodies:
  - {name: ledge, shape: {box: [4, 0.5]}, position: [0, -0.25], static: true}
  - {name: hammer, shape: {compound: [{box: [1, 0.1]}, {box: [0.2, 0.4], position: [0.6, 0]}]}, position: [0, 1], angular_velocity: 3, velocity: [1, 0]}
  - {name: block, shape: {box: [0.5, 0.5]}, position: [-1, 0.26]}
)",
                                // a box sliding along the floor, its extent past the view's bottom
                                // edge all along, out past the post that first bounds the view
                                R"(
duration: 2
world: {gravity: [0, -9.81], friction: 0.2}
sim: {collisions: sequential}
bodies:
  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}
  - {name: post, shape: {circle: 0.2}, position: [1, 2], static: true}
  - {name: slider, shape: {box: [0.5, 0.5]}, position: [0, 0.25], velocity: [3, 0]}
)",
                                // a turning box flying out of the view the post bounds, in free space
                                R"(
duration: 1
bodies:
  - {name: post, shape: {circle: 0.2}, position: [1, 1.5], static: true}
  - {name: flier, shape: {box: [0.5, 0.5]}, position: [0, 0], velocity: [2, 0.5], angular_velocity: 3}
)",
                                // the same box at 45°, not turning, flying straight out past the
                                // posts that bound the view: its last bounds must move with it
                                R"(
duration: 1
bodies:
  - {name: top, shape: {circle: 0.2}, position: [1, 1.5], static: true}
  - {name: bottom, shape: {circle: 0.2}, position: [1, -1.5], static: true}
  - {name: flier, shape: {box: [0.5, 0.5]}, position: [0, 0], angle: 0.785, velocity: [2, 0]}
)"};
  for (const std::string& yaml : scenes) {
    const render::scene::Scene def = drawn_scene::load(yaml);
    const render::frame::RunSurvey survey = render::frame::surveyRun(def);
    sim::world::World world = sim::scene::buildWorld(def.model);
    EveryStep every;
    every.afterStep(world);
    world.advanceTo(def.model.duration, &every);
    CHECK(survey.steps == world.steps);
    CHECK(survey.bounds.min == every.bounds.min);
    CHECK(survey.bounds.max == every.bounds.max);
    CHECK(survey.farthest == every.farthest);
    CHECK(survey.farthestBody == every.farthestBody);
    CHECK(survey.maxSpeed == every.maxSpeed);
    CHECK(survey.maxMomentum == every.maxMomentum);
  }
}
