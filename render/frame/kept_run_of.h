// The survey's run kept at the pictures' instants, over the dimension (2D kept_run.h, 3D
// render/frame3d/survey3d.h): the states a SteppedRun goes on from, and the loop that keeps them.
#pragma once

#include <malloc.h>

#include <algorithm>
#include <functional>
#include <vector>

#include "render/scene/render_def.h"

namespace render::frame {

// the bytes the heap has handed out now (glibc's count; 0 where it keeps none, as under a sanitizer)
inline size_t allocatedBytes() { return ::mallinfo2().uordblks; }

template <class State, class Options>
struct KeptRunOf {
  Options options;            // what every kept history records
  double end = 0.0;           // where the run ended
  std::vector<State> states;  // ascending in time, each at the last step that ends by its instant
  size_t bytes = 0;           // about how much memory they hold
};

// the run of `world` to `end`, `follower` told of every step and event, its world and a history of
// `options` kept at each of `instants` (in any order). Not kept: instants past the end, those fewer
// than render::scene::kKeptMinSteps steps after the state kept before, those past `budget` bytes of
// states, and all once the history's paths pass kKeptPathBytes. `ended` is shown the world at the
// end. Throws what the world's steps throw.
template <class State, class Options, class StepObserver, class ImpulseEvent, class World>
KeptRunOf<State, Options> keepRunOf(Options options, World world, double end, std::vector<double> instants, size_t budget,
                                    StepObserver& follower, const std::function<size_t(const State&)>& bytesOf,
                                    const std::function<void(const World&)>& ended) {
  using History = decltype(State::history);
  // the history and the survey told of each step while states are kept, then the survey alone
  class Recorder : public StepObserver {
   public:
    Recorder(History& history, StepObserver& follower) : history_(history), follower_(follower) {}
    void afterStep(const World& w) override {
      if (recording()) history_.afterStep(w);
      follower_.afterStep(w);
    }
    void afterEvent(const World& w, const ImpulseEvent& e) override {
      if (recording()) history_.afterEvent(w, e);
      follower_.afterEvent(w, e);
    }
    // the history is told of every step until its paths, which keep every step's point, outgrow
    // their bound: from then on nothing more is kept (a trail of 10 bodies over 10⁶ steps: 160 MB).
    // Their size is a sum over the bodies, so it is looked at every 64th step: the paths grow by a
    // point a step, 64 points past the bound at most
    bool recording() {
      if (!full_ && calls_++ % 64 == 0) full_ = history_.pathBytes() > render::scene::kKeptPathBytes;
      return !full_;
    }

   private:
    History& history_;
    StepObserver& follower_;
    bool full_ = false;
    unsigned long calls_ = 0;
  };

  KeptRunOf<State, Options> kept{std::move(options), end, {}, 0};
  History history(world, kept.options);
  Recorder recorder(history, follower);
  std::sort(instants.begin(), instants.end());
  for (double t : instants) {
    if (t > end) break;
    // the run's own steps that end by t, as SteppedRun::reach takes them
    world.advanceWithin(t, end, &recorder);
    if (!recorder.recording()) break;
    // a state only where it saves steps enough to pay for its copy (instants between the same two
    // steps share one; a pile's 1 step a frame is cheaper to take again than to keep)
    const long since = kept.states.empty() ? world.steps : world.steps - kept.states.back().world.steps;
    if (since < render::scene::kKeptMinSteps) continue;
    // its size as the allocator counts it where it can (a world's contact finder and method hold
    // more than the estimate sees), else the estimate
    const size_t before = allocatedBytes();
    State state{world, history};
    const size_t bytes = std::max(bytesOf(state), allocatedBytes() - std::min(before, allocatedBytes()));
    if (kept.bytes + bytes > budget) break;
    kept.bytes += bytes;
    kept.states.push_back(std::move(state));
  }
  world.advanceTo(end, &follower);
  ended(world);
  return kept;
}

}  // namespace render::frame
