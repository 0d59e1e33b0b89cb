#include "render/frame/kept_run.h"

#include <algorithm>

#include "render/frame/teaching_arrows.h"
#include "sim/describe/describe.h"

namespace render::frame {

History::Options keptHistoryOptions(const render::scene::Scene& def) {
  const render::scene::RenderDef& r = def.render;
  History::Options o;
  o.trails = r.trails;
  o.hold = r.contactHold;
  o.eventImpulses = r.impulses;
  o.impacts = r.contacts;
  o.points = TeachingArrows::pathsOf(def);
  if (r.contacts) o.contacts = sim::describe::contactMarks;
  return o;
}

namespace {

// the history and the survey told of each step while states are kept, then the survey alone
class Recorder : public sim::world::StepObserver {
 public:
  Recorder(History& history, sim::world::StepObserver& follower) : history_(history), follower_(follower) {}
  void afterStep(const sim::world::World& w) override {
    if (recording()) history_.afterStep(w);
    follower_.afterStep(w);
  }
  void afterEvent(const sim::world::World& w, const sim::world::ImpulseEvent& e) override {
    if (recording()) history_.afterEvent(w, e);
    follower_.afterEvent(w, e);
  }
  // the history is told of every step until its paths, which keep every step's point, outgrow their
  // bound: from then on nothing more is kept (a trail of 10 bodies over 10⁶ steps is 160 MB)
  bool recording() {
    full_ = full_ || history_.pathBytes() > render::scene::kKeptPathBytes;
    return !full_;
  }

 private:
  History& history_;
  sim::world::StepObserver& follower_;
  bool full_ = false;
};

}  // namespace

KeptRun keepRun(const render::scene::Scene& def, sim::world::World world, double end, std::vector<double> instants,
                sim::world::StepObserver& follower, const std::function<void(const sim::world::World&)>& ended) {
  KeptRun kept{keptHistoryOptions(def), end, {}, 0};
  History history(world, kept.options);
  Recorder recorder(history, follower);
  std::sort(instants.begin(), instants.end());
  for (double t : instants) {
    if (t > end) break;
    // the run's own steps that end by t, as SteppedRun::reach takes them
    world.advanceWithin(t, end, &recorder);
    if (!recorder.recording()) break;
    // two instants between the same two steps share one state
    if (!kept.states.empty() && kept.states.back().world.steps == world.steps) continue;
    PlanarRun::State state{world, history};
    const size_t bytes = keptBytes(state);
    if (kept.bytes + bytes > render::scene::kKeptRunBytes) break;
    kept.bytes += bytes;
    kept.states.push_back(std::move(state));
  }
  world.advanceTo(end, &follower);
  ended(world);
  return kept;
}

bool sameRecord(const History::Options& a, const History::Options& b) {
  return a.trails == b.trails && a.hold == b.hold && a.eventImpulses == b.eventImpulses && a.impacts == b.impacts &&
         static_cast<bool>(a.contacts) == static_cast<bool>(b.contacts) && a.points == b.points;
}

size_t keptBytes(const PlanarRun::State& state) {
  const sim::world::World& w = state.world;
  size_t total = sizeof(PlanarRun::State) + state.history.bytes();
  for (const sim::core::Body& b : w.bodies) total += sizeof(b) + b.shape.vertices.capacity() * sizeof(sim::core::Vec2);
  // the contacts, and as many again for what the contact finder keeps of them (pairs, manifolds)
  size_t contacts = w.contacts.capacity();
  for (const std::vector<sim::world::Contact>& island : w.sleepingContacts()) contacts += island.capacity();
  total += 2 * contacts * sizeof(sim::world::Contact);
  return total + w.impacts.capacity() * sizeof(sim::world::ImpactRecord);
}

}  // namespace render::frame
