#include "render/frame/history.h"

#include "render/jobs/interrupt.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;

History::History(const sim::world::World& world, Options options) : options_(std::move(options)) {
  trails_.resize(world.bodies.size());
  tentative_.resize(world.bodies.size(), false);
  points_.resize(options_.points.size());
  afterStep(world);
}

void History::afterStep(const sim::world::World& world) {
  // a snapshot's run to its time: Ctrl-C between two steps
  render::jobs::checkInterrupted();
  if (options_.trails)
    for (size_t i = 0; i < world.bodies.size(); ++i)
      if (!world.bodies[i].isStatic) keepTrailPoint(i, world.bodies[i].x);
  for (size_t k = 0; k < points_.size(); ++k) {
    const auto& [body, local] = options_.points[k];
    points_[k].push_back(world.bodies[body].pose().toWorld(local));
  }
  observeImpacts(world);
  observeContacts(world);
  forgetOld(world.time);
}

void History::afterEvent(const sim::world::World& world, const sim::world::ImpulseEvent& e) {
  if (!options_.eventImpulses) return;
  // where it strikes, now: the body moves on, the arrow stays where the blow fell
  sim::world::ImpulseEvent at = e;
  at.point = e.pointInWorld ? e.point : world.bodies[e.body].pose().toWorld(e.point);
  at.pointInWorld = true;
  begin({.time = world.time, .kind = Moment::Kind::Event, .pair = {-1, -1}, .event = at});
}

void History::keepTrailPoint(size_t body, const Vec2& x) {
  std::vector<Vec2>& trail = trails_[body];
  if (tentative_[body]) trail.pop_back();
  const Vec2 kept = trail.empty() ? x : trail.back();
  tentative_[body] = !trail.empty() && (x - kept).norm() < options_.trailSpacing;
  trail.push_back(x);
}

void History::respace(double spacing) {
  options_.trailSpacing = spacing;
  for (size_t i = 0; i < trails_.size(); ++i) {
    std::vector<Vec2> every = std::move(trails_[i]);
    trails_[i].clear();
    tentative_[i] = false;
    for (const Vec2& x : every) keepTrailPoint(i, x);
  }
}

size_t History::pathBytes() const {
  size_t total = 0;
  for (const auto& trail : trails_) total += trail.capacity() * sizeof(Vec2);
  for (const auto& path : points_) total += path.capacity() * sizeof(Vec2);
  return total;
}

size_t History::bytes() const {
  size_t total = sizeof(History) + pathBytes();
  for (const auto& [id, m] : moments_)
    total += sizeof(Moment) + m.contacts.capacity() * sizeof(sim::describe::ContactMark) +
             m.impacts.capacity() * sizeof(sim::world::ImpactRecord);
  return total + spare_.capacity() * sizeof(sim::describe::ContactMark);
}

long History::begin(Moment moment) {
  const long id = next_++;
  byTime_.emplace(moment.time, id);
  if (moment.kind == Moment::Kind::Impact) impactOfPair_[moment.pair] = id;
  moments_.emplace(id, std::move(moment));
  return id;
}

void History::retime(long id, double time) {
  Moment& m = moments_.at(id);
  byTime_.erase({m.time, id});
  m.time = time;
  byTime_.emplace(time, id);
}

void History::observeImpacts(const sim::world::World& world) {
  if (!options_.impacts) {
    impactsSeen_ = world.impacts.size();
    return;
  }
  for (; impactsSeen_ < world.impacts.size(); ++impactsSeen_) {
    const sim::world::ImpactRecord& r = world.impacts[impactsSeen_];
    // one moment per pair: its latest impact (all the points of that instant) replaces the ones
    // before, so that a pair hitting again and again (a jittering stack, a ball's last bounces)
    // shows one set of arrows and not a pile of fading ones
    const std::pair<int, int> pair(r.a, r.b);
    const auto held = impactOfPair_.find(pair);
    long id = 0;
    if (held == impactOfPair_.end()) {
      id = begin({.time = r.t, .kind = Moment::Kind::Impact, .pair = pair});
    } else {
      id = held->second;
      if (moments_.at(id).time != r.t) {
        retime(id, r.t);
        moments_.at(id).impacts.clear();
      }
    }
    moments_.at(id).impacts.push_back(r);
  }
}

void History::observeContacts(const sim::world::World& world) {
  if (!options_.contacts) return;
  // marked into the last step's storage, which keeps its capacity: no allocation a step
  std::vector<sim::describe::ContactMark>& now = spare_;
  now.clear();
  options_.contacts(world, now);
  if (now.empty()) {
    touching_ = -1;
    return;
  }
  // contacts that go on touching step after step are one moment, kept up to date; a new touch
  // after a separation is a new moment, so that the last one fades while the next one shows
  if (touching_ >= 0) {
    retime(touching_, world.time);
    std::swap(moments_.at(touching_).contacts, now);
  } else {
    touching_ = begin({.time = world.time, .kind = Moment::Kind::Contact, .pair = {-1, -1}, .contacts = std::move(now)});
  }
}

void History::forgetOld(double now) {
  // the oldest first, up to the first still held
  while (!byTime_.empty() && now - byTime_.begin()->first > options_.hold) {
    const long id = byTime_.begin()->second;
    byTime_.erase(byTime_.begin());
    const auto m = moments_.find(id);
    if (m->second.kind == Moment::Kind::Impact) impactOfPair_.erase(m->second.pair);
    moments_.erase(m);
    if (id == touching_) touching_ = -1;
  }
}

void History::drawTrails(Canvas& draw, double spacing) const {
  for (size_t i = 0; i < trails_.size(); ++i) drawPath(trails_[i], spacing, {Role::Trail, static_cast<int>(i), 1.0}, draw);
}

void History::drawPath(const std::vector<Vec2>& path, double spacing, const Pen& style, Canvas& draw) {
  if (path.size() < 2) return;
  Vec2 from = path.front();
  for (size_t k = 1; k < path.size(); ++k) {
    const bool last = k + 1 == path.size();
    if ((path[k] - from).norm() < spacing && !last) continue;
    draw.segment(from, path[k], style);
    from = path[k];
  }
}

void History::describe(const sim::world::World& world, const Moment& m, const Look& look, Canvas& draw) {
  PhysicsDraw physics(draw);
  switch (m.kind) {
    case Moment::Kind::Contact: sim::describe::describeContactMarks(m.contacts, look.normalLength, physics); break;
    case Moment::Kind::Impact:
      for (size_t k = 0; k < m.impacts.size(); ++k) {
        sim::describe::describeImpact(world, m.impacts[k], look.impulseScale, look.normalLength, physics);
        // the normal and the velocities once per pair and instant
        if (look.labels) look.labels->impact(world, m.impacts[k], k == 0, draw);
      }
      break;
    case Moment::Kind::Event: {
      const sim::describe::Arrow arrow = sim::describe::describeEventImpulse(world, m.event, look.impulseScale, physics);
      if (look.labels) look.labels->event(m.event, arrow.tail, arrow.head, draw);
      break;
    }
  }
}

void History::drawAfterimages(const sim::world::World& world, const Look& look, Canvas& draw) const {
  const double hold = options_.hold, t = world.time;
  for (const auto& [id, m] : moments_) {
    const double age = t - m.time;
    if (age < 0.0 || age > hold) continue;
    // described as it is drawn, never recorded: a pile's contacts are tens of thousands of calls
    Faded faded(draw, hold > 0.0 ? 1.0 - age / hold : 1.0);
    describe(world, m, look, faded);
  }
}

}  // namespace render::frame
