#include "render/frame/kept_run.h"

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

KeptRun keepRun(const render::scene::Scene& def, sim::world::World world, double end, std::vector<double> instants, size_t budget,
                sim::world::StepObserver& follower, const std::function<void(const sim::world::World&)>& ended) {
  return keepRunOf<PlanarRun::State, History::Options, sim::world::StepObserver, sim::world::ImpulseEvent>(
      keptHistoryOptions(def), std::move(world), end, std::move(instants), budget, follower, keptBytes, ended);
}

void goOnFrom(PlanarRun& run, const std::shared_ptr<const KeptRun>& kept, const History::Options& options) {
  if (!kept || !sameRecord(kept->options, options)) return;
  // the lambda holds the kept run, so its states outlive the run that reads them
  run.resumeFrom(&kept->states, kept->end,
                 [kept, spacing = options.trailSpacing](PlanarRun::State& s) { s.history.respace(spacing); });
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
