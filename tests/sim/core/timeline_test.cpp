#include "sim/core/timeline.h"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using sim::core::Timeline;

namespace {

struct Event {
  double time = 0.0;
  int id = 0;
};

// a world that records what the timeline asks of it: each step's end and each event, in order
struct RecordingWorld {
  double time = 0.0;
  std::vector<double> ends;
  std::vector<std::string> log;
  int starts = 0;
  // the timeline readies the world before its first step or event
  void start() { ++starts; }
  void step(double stop, double end) {
    CHECK(starts > 0);
    CHECK(stop > time);
    ends.push_back(end);
    log.push_back("step");
    time = end;
  }
  void applyEvent(const Event& e) {
    CHECK(starts > 0);
    log.push_back("event " + std::to_string(e.id) + " at " + std::to_string(time));
  }
};

// counts what an observer is told
struct CountingObserver {
  int steps = 0, events = 0;
  void afterStep(const RecordingWorld&) { ++steps; }
  void afterEvent(const RecordingWorld&, const Event&) { ++events; }
};

}  // namespace

TEST_CASE("steps are cut at the events and the force switches, and the events applied there in time order") {
  // events out of order, two at one instant (kept in the order given), one before the start
  Timeline<Event> timeline(0.1, {{0.25, 1}, {-1.0, 0}, {0.25, 2}}, {0.32});
  RecordingWorld world;
  CountingObserver observer;
  timeline.advanceTo(world, 0.5, &observer);
  CHECK(world.ends == std::vector<double>{0.1, 2 * 0.1, 0.25, 3 * 0.1, 0.32, 4 * 0.1, 0.5});
  CHECK(world.log == std::vector<std::string>{"event 0 at 0.000000", "step", "step", "step", "event 1 at 0.250000",
                                              "event 2 at 0.250000", "step", "step", "step", "step"});
  CHECK(world.time == 0.5);
  CHECK(observer.steps == 7);
  CHECK(observer.events == 3);
  CHECK(world.starts == 1);
}

TEST_CASE("advanceWithin takes the steps that end by t and never splits one at t") {
  Timeline<Event> timeline(0.1, {}, {});
  RecordingWorld world;
  timeline.advanceWithin(world, 0.35, 1.0, static_cast<CountingObserver*>(nullptr));
  CHECK(world.ends == std::vector<double>{0.1, 2 * 0.1, 3 * 0.1});
  // a step that ends at t within round-off is taken
  timeline.advanceWithin(world, 0.4 - 1e-14, 1.0, static_cast<CountingObserver*>(nullptr));
  CHECK(world.ends.back() == 4 * 0.1);
  // advanceTo goes on from there on the same grid
  timeline.advanceTo(world, 0.6, static_cast<CountingObserver*>(nullptr));
  CHECK(world.ends == std::vector<double>{0.1, 2 * 0.1, 3 * 0.1, 4 * 0.1, 5 * 0.1, 0.6});
}
