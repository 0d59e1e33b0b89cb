// The run's timeline, one for the 2D and the 3D world: the fixed step grid (step_grid.h) cut at
// every timed impulse and force switch, the impulses applied in time order at their exact
// instants, and the stepping to a time on that grid (notes: "Impulses"). A world keeps what is
// its own, the hooks the timeline calls (step and applyEvent private ones, with the timeline a friend):
//   world.start(): ready to step (the method chosen, the start state checked), a no-op once done;
//   world.step(stop, end): one step from world.time to `stop`, arriving at `end` (the grid point
//     or the end itself where `stop` is one of them to within round-off), world.time = end after;
//   world.applyEvent(e): the impulse e, now.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "sim/core/step_grid.h"

namespace sim::core {

// Event: a timed impulse with its `time`
template <class Event>
class Timeline {
 public:
  Timeline() = default;
  // `events` in any order (applied in time order, those at one instant in the order given);
  // `switches`: the times the forces switch on or off
  Timeline(double dt, std::vector<Event> events, std::vector<double> switches) : pending_(std::move(events)) {
    std::stable_sort(pending_.begin(), pending_.end(), [](const Event& a, const Event& b) { return a.time < b.time; });
    for (const Event& e : pending_) switches.push_back(e.time);
    grid_ = StepGrid(dt, std::move(switches));
  }

  // the world advanced to exactly tEnd (events at tEnd included); `observer` told of every step
  // and every event
  template <class World, class Observer>
  void advanceTo(World& world, double tEnd, Observer* observer) {
    world.start();
    applyDueEvents(world, observer);
    while (world.time < tEnd && !grid_.same(world.time, tEnd)) stepTo(world, grid_.nextStop(world.time, tEnd), tEnd, observer);
    world.time = std::max(world.time, tEnd);
  }

  // the world advanced by the steps that advanceTo(tEnd) takes as long as they end by t, never
  // splitting one at t
  template <class World, class Observer>
  void advanceWithin(World& world, double t, double tEnd, Observer* observer) {
    world.start();
    applyDueEvents(world, observer);
    while (world.time < tEnd && !grid_.same(world.time, tEnd)) {
      const double stop = grid_.nextStop(world.time, tEnd);
      if (stop > t && !grid_.same(stop, t)) break;
      stepTo(world, stop, tEnd, observer);
    }
  }

 private:
  // one step from now to `stop` on the way to tEnd, the events due there applied
  template <class World, class Observer>
  void stepTo(World& world, double stop, double tEnd, Observer* observer) {
    world.step(stop, grid_.arrive(stop, tEnd));
    if (observer) observer->afterStep(world);
    applyDueEvents(world, observer);
  }

  // every event up to now: events before the start of the run are applied at its start
  template <class World, class Observer>
  void applyDueEvents(World& world, Observer* observer) {
    while (next_ < pending_.size() && (pending_[next_].time < world.time || grid_.same(pending_[next_].time, world.time))) {
      const Event& e = pending_[next_++];
      world.applyEvent(e);
      if (observer) observer->afterEvent(world, e);
    }
  }

  StepGrid grid_;               // steps of dt, cut at the events and force switches
  std::vector<Event> pending_;  // sorted by time
  size_t next_ = 0;             // the first not applied yet
};

}  // namespace sim::core
