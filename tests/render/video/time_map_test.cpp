// Video time to simulation time: the identity without a card or slow motion (so existing videos are
// unchanged, frame for frame), a card that holds t = 0, windows stretched by their factor, merged when
// they overlap, and a monotone, continuous map whose frames land on the expected simulation times.
#include <doctest/doctest.h>

#include <cmath>

#include "render/jobs/exit_status.h"
#include "render/video/time_map.h"

using render::video::SlowWindow;
using render::video::TimeMap;

TEST_CASE("without a card or windows the map is the identity, bit for bit, with the old frame count") {
  for (double duration : {0.4, 1.5, 2.0, 3.3333}) {
    const TimeMap map(duration);
    CHECK(map.videoLength() == duration);
    for (double fps : {5.0, 10.0, 30.0, 60.0}) {
      const long count = map.frameCount(fps);
      CHECK(count == std::max(1L, static_cast<long>(std::ceil(duration * fps - 1e-9))));
      for (long k = 0; k < count; ++k) {
        const double u = static_cast<double>(k) / fps;
        CHECK(map.simTime(u) == u);
        CHECK_FALSE(map.inTitleCard(u));
      }
    }
    CHECK(map.factorAt(0.3) == 1.0);
  }
  CHECK(TimeMap(1.5).frameCount(10.0) == 15);
}

// a count past a long's range was converted unchecked: undefined behavior, a one-frame video
TEST_CASE("a video of more than kMaxFrames frames is refused before its count is converted") {
  CHECK(TimeMap(1e7 / 60.0).frameCount(60.0) == 10000000);
  CHECK_THROWS_AS(TimeMap(1e7 / 60.0 + 1.0).frameCount(60.0), render::jobs::UsageError);
  CHECK_THROWS_AS(TimeMap(1.0, 1e300).frameCount(60.0), render::jobs::UsageError);
  CHECK_THROWS_AS(TimeMap(1e300).frameCount(1.0), render::jobs::UsageError);
}

TEST_CASE("a title card holds t = 0 and delays the run by its length") {
  const TimeMap map(1.0, 0.5);
  CHECK(map.videoLength() == 1.5);
  CHECK(map.frameCount(10.0) == 15);
  CHECK(map.inTitleCard(0.0));
  CHECK(map.inTitleCard(0.49));
  CHECK_FALSE(map.inTitleCard(0.5));
  CHECK(map.simTime(0.3) == 0.0);
  CHECK(map.simTime(0.5) == 0.0);
  CHECK(map.simTime(0.75) == doctest::Approx(0.25).epsilon(1e-15));
}

TEST_CASE("an answer card closes the video after the run, holding its last instant") {
  const TimeMap map(1.0, 0.5, {}, 2.0);
  CHECK(map.videoLength() == 3.5);
  CHECK(map.frameCount(10.0) == 35);
  CHECK_FALSE(map.inAnswerCard(0.0));
  CHECK_FALSE(map.inAnswerCard(1.49));
  CHECK(map.inAnswerCard(1.5));
  CHECK(map.inAnswerCard(3.4));
  CHECK(map.simTime(1.49) == doctest::Approx(0.99).epsilon(1e-12));
  CHECK(map.simTime(2.0) == 1.0);
  // none by default
  CHECK_FALSE(TimeMap(1.0, 0.5).inAnswerCard(1.49));
}

TEST_CASE("a window runs factor times slower, and the run resumes its pace after it") {
  // [0.4, 0.6) at 4×: 0.2 s of simulation take 0.8 s of video
  const TimeMap map(1.0, 0.0, {{0.4, 0.6, 4.0}});
  CHECK(map.videoLength() == doctest::Approx(1.6).epsilon(1e-15));
  CHECK(map.frameCount(10.0) == 16);
  const double expected[] = {0.0, 0.1, 0.2, 0.3, 0.4, 0.425, 0.45, 0.475, 0.5, 0.525, 0.55, 0.575, 0.6, 0.7, 0.8, 0.9};
  for (long k = 0; k < 16; ++k) CHECK(map.simTime(k / 10.0) == doctest::Approx(expected[k]).epsilon(1e-12));
  CHECK(map.factorAt(0.39) == 1.0);
  CHECK(map.factorAt(0.4) == 4.0);
  CHECK(map.factorAt(0.59) == 4.0);
  CHECK(map.factorAt(0.6) == 1.0);
}

TEST_CASE("the map is monotone and continuous, and ends at the duration") {
  const TimeMap map(2.0, 0.7, {{0.1, 0.3, 3.0}, {0.25, 0.5, 5.0}, {1.2, 1.3, 2.0}, {1.9, 2.4, 4.0}});
  double previous = 0.0;
  for (int i = 0; i <= 20000; ++i) {
    const double u = map.videoLength() * i / 20000.0;
    const double t = map.simTime(u);
    CHECK(t >= previous);
    // at most the slowest pace: one unit of video is at most one of simulation
    CHECK(t - previous <= map.videoLength() / 20000.0 + 1e-12);
    previous = t;
  }
  CHECK(map.simTime(map.videoLength()) == doctest::Approx(2.0).epsilon(1e-12));
}

TEST_CASE("windows are sorted, clipped to the run, and merged where they overlap or touch, at the larger factor") {
  const auto merged = render::video::mergeWindows(
      {{0.9, 1.0, 3.0}, {0.4, 0.7, 4.0}, {0.2, 0.5, 2.0}, {-0.1, 0.1, 2.0}, {0.1, 0.15, 6.0}, {1.9, 2.5, 2.0}, {2.2, 2.4, 9.0}},
      2.0);
  CHECK(merged == std::vector<SlowWindow>{{0.0, 0.15, 6.0}, {0.2, 0.7, 4.0}, {0.9, 1.0, 3.0}, {1.9, 2.0, 2.0}});
  const TimeMap map(2.0, 0.0, {{0.2, 0.5, 2.0}, {0.4, 0.7, 4.0}});
  CHECK(map.videoLength() == doctest::Approx(2.0 + 3.0 * 0.5).epsilon(1e-15));
}

TEST_CASE("windows around impacts come from the survey's impact times, plus the explicit ones") {
  render::scene::RenderDef r;
  r.titleCard = 1.0;
  r.slowMotion = {{4.0, 0.2, 0.0, 0.0}, {2.0, 0.0, 0.0, 0.05}};
  // impacts 0.05 s apart share one window; the last is cut at the end of the run
  const TimeMap map = render::video::timeMapFor(r, {0.5, 0.55, 1.0}, 1.05);
  CHECK(map.windows() == std::vector<SlowWindow>{{0.0, 0.05, 2.0}, {0.4, 0.65, 4.0}, {0.9, 1.05, 4.0}});
  CHECK(map.videoLength() == doctest::Approx(1.0 + 1.05 + 0.05 + 3 * 0.25 + 3 * 0.15).epsilon(1e-12));
  // without impacts a window around them is nothing
  render::scene::RenderDef around;
  around.slowMotion = {{4.0, 0.2, 0.0, 0.0}};
  CHECK(render::video::timeMapFor(around, {}, 2.0).videoLength() == 2.0);
}
