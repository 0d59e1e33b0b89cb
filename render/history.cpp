#include "history.h"

#include <algorithm>

namespace render {

History::History(const sim::World& world, Options options) : options_(std::move(options)) {
  trails_.resize(world.bodies.size());
  afterStep(world);
}

void History::afterStep(const sim::World& world) {
  if (options_.trails)
    for (size_t i = 0; i < world.bodies.size(); ++i)
      if (!world.bodies[i].isStatic) trails_[i].push_back(world.bodies[i].x);
  observeContacts(world);
  forgetOld(world.time);
}

void History::afterEvent(const sim::World& world, const sim::ImpulseEvent& e) {
  if (!options_.eventImpulses) return;
  const sim::Body& b = world.bodies[e.body];
  const Vec2 r = e.pointInWorld ? e.point : b.pose().toWorld(e.point);
  // the arrow ends where the impulse is applied, as a blow that strikes the body there
  Moment m{world.time, {}};
  m.calls.arrow(r - options_.impulseScale * e.impulse, r, {sim::DrawRole::Impulse, e.body, 1.0});
  moments_.push_back(std::move(m));
}

void History::observeContacts(const sim::World& world) {
  if (!options_.contacts) return;
  DrawList now;
  options_.contacts(world, now);
  if (now.empty()) {
    touching_ = -1;
    return;
  }
  // contacts that go on touching step after step are one moment, kept up to date; a new touch
  // after a separation is a new moment, so that the last one fades while the next one shows
  if (touching_ >= 0) {
    moments_[touching_] = {world.time, std::move(now)};
  } else {
    moments_.push_back({world.time, std::move(now)});
    touching_ = static_cast<long>(moments_.size()) - 1;
  }
}

void History::forgetOld(double now) {
  const double hold = options_.hold;
  const auto keep = [&](const Moment& m) { return now - m.time <= hold; };
  if (std::all_of(moments_.begin(), moments_.end(), keep)) return;
  const Moment* touching = touching_ >= 0 ? &moments_[touching_] : nullptr;
  std::vector<Moment> kept;
  long index = -1;
  for (const Moment& m : moments_) {
    if (!keep(m)) continue;
    if (&m == touching) index = static_cast<long>(kept.size());
    kept.push_back(m);
  }
  moments_ = std::move(kept);
  touching_ = index;
}

void History::drawTrails(sim::DebugDraw& draw, double spacing) const {
  for (size_t i = 0; i < trails_.size(); ++i) {
    const std::vector<Vec2>& path = trails_[i];
    if (path.size() < 2) continue;
    const sim::DrawStyle style{sim::DrawRole::Trail, static_cast<int>(i), 1.0};
    Vec2 from = path.front();
    for (size_t k = 1; k < path.size(); ++k) {
      const bool last = k + 1 == path.size();
      if ((path[k] - from).norm() < spacing && !last) continue;
      draw.segment(from, path[k], style);
      from = path[k];
    }
  }
}

void History::drawAfterimages(double t, sim::DebugDraw& draw) const {
  const double hold = options_.hold;
  for (const Moment& m : moments_) {
    const double age = t - m.time;
    if (age < 0.0 || age > hold) continue;
    m.calls.replay(draw, hold > 0.0 ? 1.0 - age / hold : 1.0);
  }
}

}  // namespace render
