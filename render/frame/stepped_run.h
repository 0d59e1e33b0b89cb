// A run of a scene as the renderer draws it (2D SceneRun and 3D SceneRun3d alike): its world and
// history stepped on the scene's own grid, a follower (a trace) told of each of its steps, and a
// picture at any time without splitting the run's steps: the run advanced by its steps that end by
// t, then, when t falls between two of them, a copy of the run (its history too, so that an impact
// inside the part step shows) advanced to t. The run's trajectory is then the scene's own whatever
// the pictures' times.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

#include "sim/core/settings.h"

namespace render::frame {

// over the dimension: sim::world::World or sim::world3d::World, its History, StepObserver and
// ImpulseEvent
template <class World, class History, class StepObserver, class ImpulseEvent>
class SteppedRun {
 public:
  // the world and what its history holds, at one moment of a run (copied to draw between steps)
  struct State {
    World world;
    History history;
  };

  SteppedRun(State start, double end) : run_(std::move(start)), end_(end) {}

  // where the run ends, its last step cut there
  void endAt(double end) { end_ = end; }
  double end() const { return end_; }
  // told of every step and event of the run itself, never of the copies drawn between steps
  void follow(StepObserver* observer) { observers_.follower = observer; }
  // nothing drawn and no step taken yet
  bool fresh() const { return run_.world.time <= 0.0 && !shown_; }

  // states of this very run, ascending in time, taken by an earlier pass that ended at `end`: the
  // run goes on from the latest one not past where it is asked to go instead of stepping there
  // (never while a follower must be told of every step, nor once the run's end differs); `adopt`
  // fits a kept state's history to this run's. `kept` must outlive the run.
  void resumeFrom(const std::vector<State>* kept, double end, std::function<void(State&)> adopt) {
    kept_ = kept, keptEnd_ = end, adopt_ = std::move(adopt);
  }
  // the steps this run's worlds took, its copies between steps included: those it started past by
  // resuming are not counted
  long stepsTaken() const { return taken_; }

  // the run itself advanced by the steps that end by t (none past its end), and its state there
  const State& advanceWithin(double t) {
    resumeToward(t);
    observers_.history = &run_.history;
    World& world = run_.world;
    const long before = world.steps;
    world.advanceWithin(t, std::max(t, end_), &observers_);
    taken_ += world.steps - before;
    return run_;
  }

  // the state to draw at t: the run itself advanced toward the end as far as t allows, or a copy
  // (reused) advanced to t. A copy's part step that fails where the run does not (impacts piling
  // up in a step cut short) gives the run: the run meets its own failures in its own steps. Throws
  // std::logic_error for t before the run's time, and what the world's steps throw.
  const State& reach(double t) {
    const double snap = sim::core::settings::kTimeSnap * run_.world.def().dt;
    if (t < run_.world.time - snap) throw std::logic_error("a picture earlier than the run's time");
    const World& world = advanceWithin(t).world;
    shown_ = &run_;
    if (std::abs(world.time - t) <= snap) return run_;
    if (!between_) between_ = std::make_unique<State>(run_);
    else *between_ = run_;
    const long before = between_->world.steps;
    try {
      between_->world.advanceTo(t, &between_->history);
    } catch (const std::runtime_error&) {
      taken_ += between_->world.steps - before;
      return run_;
    }
    taken_ += between_->world.steps - before;
    shown_ = between_.get();
    return *between_;
  }
  // the run taken on to its end
  void finish() {
    resumeToward(end_);
    observers_.history = &run_.history;
    const long before = run_.world.steps;
    run_.world.advanceTo(end_, &observers_);
    taken_ += run_.world.steps - before;
    shown_ = &run_;
  }

  // the world the last picture was drawn from: the run's own, or its copy between two steps
  const World& world() const { return shown_ ? shown_->world : run_.world; }
  // the run's own world, at its last step
  const World& runWorld() const { return run_.world; }

 private:
  // what the run's own steps are told: its history, and the follower
  struct Observers : StepObserver {
    History* history = nullptr;
    StepObserver* follower = nullptr;
    void afterStep(const World& w) override {
      history->afterStep(w);
      if (follower) follower->afterStep(w);
    }
    void afterEvent(const World& w, const ImpulseEvent& e) override {
      history->afterEvent(w, e);
      if (follower) follower->afterEvent(w, e);
    }
  };

  // the run moved on to the latest kept state not past t, when it is ahead of the run
  void resumeToward(double t) {
    if (!kept_ || observers_.follower || keptEnd_ != end_) return;
    const double snap = sim::core::settings::kTimeSnap * run_.world.def().dt;
    const State* latest = nullptr;
    // the grid's own test (StepGrid::same): a state the run's steps within t would reach
    const auto within = [&](double time) { return time <= t || std::abs(time - t) <= snap; };
    for (; next_ < kept_->size() && within((*kept_)[next_].world.time); ++next_) latest = &(*kept_)[next_];
    if (!latest || latest->world.time <= run_.world.time) return;
    run_ = *latest;
    if (adopt_) adopt_(run_);
  }

  State run_;
  Observers observers_;
  double end_;
  std::unique_ptr<State> between_;            // the copy drawn between steps (kept for its storage)
  const State* shown_ = nullptr;              // the state of the last picture
  const std::vector<State>* kept_ = nullptr;  // resumeFrom's states, and the first not yet passed
  size_t next_ = 0;
  double keptEnd_ = 0.0;
  std::function<void(State&)> adopt_;
  long taken_ = 0;  // stepsTaken()
};

}  // namespace render::frame
