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
  observeImpacts(world);
  observeContacts(world);
  forgetOld(world.time);
}

void History::afterEvent(const sim::World& world, const sim::ImpulseEvent& e) {
  if (!options_.eventImpulses) return;
  const sim::Body& b = world.bodies[e.body];
  const Vec2 r = e.pointInWorld ? e.point : b.pose().toWorld(e.point);
  // the arrow ends where the impulse is applied, as a blow that strikes the body there
  Moment m{world.time, {}, Moment::Kind::Event};
  m.calls.arrow(r - options_.impulseScale * e.impulse, r, {sim::DrawRole::Impulse, e.body, 1.0});
  moments_.push_back(std::move(m));
}

void History::observeImpacts(const sim::World& world) {
  if (!options_.impacts) {
    impactsSeen_ = world.impacts.size();
    return;
  }
  // one moment per instant: the points of a manifold, or simultaneous impacts, together
  for (; impactsSeen_ < world.impacts.size(); ++impactsSeen_) {
    const sim::ImpactRecord& r = world.impacts[impactsSeen_];
    if (moments_.empty() || moments_.back().time != r.t || moments_.back().kind != Moment::Kind::Impact)
      moments_.push_back({r.t, {}, Moment::Kind::Impact});
    DrawList& d = moments_.back().calls;
    // the impulse γ n̂ on A and −γ n̂ on B from the point, then the unit normal and the point on top
    const Vec2 j = options_.impulseScale * r.impulse * r.normal;
    d.arrow(r.point, r.point + j, {sim::DrawRole::Impulse, r.a, 1.0});
    d.arrow(r.point, r.point - j, {sim::DrawRole::Impulse, r.b, 1.0});
    d.arrow(r.point, r.point + options_.normalLength * r.normal, {sim::DrawRole::ContactNormal, -1, 1.0});
    d.point(r.point, {sim::DrawRole::ContactPoint, -1, 1.0});
  }
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
    moments_[touching_] = {world.time, std::move(now), Moment::Kind::Contact};
  } else {
    moments_.push_back({world.time, std::move(now), Moment::Kind::Contact});
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
