// The survey of a run (survey.cpp): the scales shared by side-by-side variants.
#include <doctest/doctest.h>

#include "render/frame/survey.h"

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
