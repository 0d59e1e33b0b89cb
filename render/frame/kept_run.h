// The survey's run of a scene kept at the instants its pictures will show: the world and its history
// there, so that the drawing goes on from them instead of stepping the scene a second time (MuJoCo's
// recorder steps once per video; so does a render of ours). What a kept history holds does not depend
// on the camera, which is fitted only after the survey: its trails keep every step's point and are
// respaced to the frame's pixels when the drawing takes them up (History::respace).
#pragma once

#include <memory>
#include <vector>

#include "render/frame/history.h"
#include "render/frame/kept_run_of.h"
#include "render/frame/stepped_run.h"
#include "render/scene/scene.h"
#include "sim/world/world.h"

namespace render::frame {

using PlanarRun = SteppedRun<sim::world::World, History, sim::world::StepObserver, sim::world::ImpulseEvent>;

using KeptRun = KeptRunOf<PlanarRun::State, History::Options>;

// what the history of a run of `def` records, whatever the camera: every step's trail point
History::Options keptHistoryOptions(const render::scene::Scene& def);

// the run of `def` from `start` to `end`, `follower` told of every step and event, kept at each of
// `instants` within `budget` bytes of states (keepRunOf says which are not kept); `ended` is shown
// the world at the end. Throws what the world's steps throw.
KeptRun keepRun(const render::scene::Scene& def, sim::world::World start, double end, std::vector<double> instants, size_t budget,
                sim::world::StepObserver& follower, const std::function<void(const sim::world::World&)>& ended);

// `run` (of the same scene, its history recording `options`) set to go on from `kept`'s states, its
// trails respaced to `options`' spacing as it takes each up; nothing when there are none, or when
// they record something else
void goOnFrom(PlanarRun& run, const std::shared_ptr<const KeptRun>& kept, const History::Options& options);

// whether a history with options `b` may go on from a state kept with `a`: the same record, but for
// the trails' spacing (respaced when taken up)
bool sameRecord(const History::Options& a, const History::Options& b);

// about how much memory a kept state holds, bytes
size_t keptBytes(const PlanarRun::State& state);

}  // namespace render::frame
