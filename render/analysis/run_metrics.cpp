#include "render/analysis/run_metrics.h"

#include <algorithm>
#include <cmath>

#include "render/jobs/interrupt.h"
#include "sim/world/diagnostics.h"

namespace render::analysis {
using sim::world::World;
using namespace sim::core;
using namespace sim::world;

namespace {

// the extent of a shape along a direction: [min, max] of d·r over its points
std::pair<double, double> extent(const Shape& shape, const Pose& p, const Vec2& d) {
  if (shape.kind == ShapeKind::Circle) return {d.dot(p.x) - shape.radius, d.dot(p.x) + shape.radius};
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec2& v : shape.vertices) {
    const double s = d.dot(p.toWorld(v));
    lo = std::min(lo, s), hi = std::max(hi, s);
  }
  // a body of parts: its parts' together
  for (const ShapePart& part : shape.parts) {
    const auto [partLo, partHi] = extent(part.shape, p.then(part.pose), d);
    lo = std::min(lo, partLo), hi = std::max(hi, partHi);
  }
  return {lo, hi};
}
std::pair<double, double> extent(const Body& b, const Vec2& d) { return extent(b.shape, b.pose(), d); }

// a pair of bodies apart at the start, and the axis that separated them (from b toward a)
struct Watched {
  int a, b;
  Vec2 axis;
};

// a has gone through b: it lies wholly on b's far side along the axis that first separated them,
// while still in line with b across it
bool through(const World& w, const Watched& p) {
  const Body &a = w.bodies[p.a], &b = w.bodies[p.b];
  if (b.shape.kind == ShapeKind::Plane) return extent(a, p.axis).second < p.axis.dot(b.x);
  const Vec2 across(-p.axis.y(), p.axis.x());
  const auto [aLo, aHi] = extent(a, p.axis);
  const auto [bLo, bHi] = extent(b, p.axis);
  const auto [cLo, cHi] = extent(a, across);
  const auto [dLo, dHi] = extent(b, across);
  return aHi < bLo && cLo <= dHi && dLo <= cHi;
}

class Recorder : public StepObserver {
 public:
  Recorder(RunMetrics& m, const MetricsOptions& o) : m_(m), o_(o) {}
  void afterStep(const World& w) override {
    // Ctrl-C between two steps of a sweep's or a stability search's run
    render::jobs::checkInterrupted();
    ++m_.steps;
    if (o_.energy) energies.push_back(energy(w).total());
    if (o_.penetration && w.bodies.size() > 1)
      for (const Contact& c : w.findContacts(0.0)) m_.maxPenetration = std::max(m_.maxPenetration, -c.manifold.separation);
    for (const Watched& p : watched)
      if (!m_.tunneled && through(w, p)) m_.tunneled = true, m_.tunnelA = p.a, m_.tunnelB = p.b;
  }
  std::vector<double> energies;
  std::vector<Watched> watched;

 private:
  RunMetrics& m_;
  const MetricsOptions& o_;
};

}  // namespace

void startEnergy(double kinetic, double potential, RunMetrics& m) {
  // energies are relative to the start: |E(0)|, or its kinetic and potential parts when they cancel
  m.energyStart = kinetic + potential;
  m.energyScale = std::max({std::abs(m.energyStart), kinetic + std::abs(potential), 1e-300});
}

void summarizeEnergies(const std::vector<double>& e, RunMetrics& m) {
  if (e.empty()) return;
  for (double x : e) m.energyDrift = std::max(m.energyDrift, std::abs(x - m.energyStart) / m.energyScale);
  const size_t third = std::max<size_t>(1, e.size() / 3);
  const double first = *std::max_element(e.begin(), e.begin() + third);
  const double last = *std::max_element(e.end() - third, e.end());
  m.energyTrend = (last - first) / m.energyScale;
}

RunMetrics measureRun(World& world, double until, const MetricsOptions& options) {
  RunMetrics m;
  world.start();
  Recorder recorder(m, options);
  const Energy e0 = energy(world);
  startEnergy(e0.kinetic, e0.potential, m);

  // watch every pair that starts apart: a dynamic body against anything
  for (const Contact& c : world.findContacts(std::numeric_limits<double>::infinity())) {
    if (c.manifold.separation <= 0.0) continue;
    const Body &a = world.bodies[c.a], &b = world.bodies[c.b];
    // the normal points from b to a
    if (!a.isStatic) recorder.watched.push_back({c.a, c.b, c.manifold.normal});
    if (!b.isStatic) recorder.watched.push_back({c.b, c.a, -c.manifold.normal});
  }
  // the top of the stack: the highest dynamic body
  int top = -1;
  for (size_t i = 0; i < world.bodies.size(); ++i)
    if (!world.bodies[i].isStatic && (top < 0 || world.bodies[i].x.y() > world.bodies[top].x.y())) top = static_cast<int>(i);
  const Vec2 topStart = top >= 0 ? world.bodies[top].x : Vec2::Zero();
  std::vector<Vec2> rest;
  for (const Body& b : world.bodies) rest.push_back(b.x);
  const double topSize = top >= 0 ? 2.0 * boundingRadius(world.bodies[top].shape) / std::sqrt(2.0) : 1.0;

  try {
    world.advanceTo(until, &recorder);
  } catch (const Diverged& d) {
    m.finite = false;
    m.divergedAt = d.time;
  }
  m.energyEnd = energy(world).total();
  summarizeEnergies(recorder.energies, m);
  if (top >= 0 && m.finite) m.topDrift = (world.bodies[top].x - topStart).norm() / topSize;
  if (top >= 0 && m.finite) m.topDisplacement = (world.bodies[top].x - topStart).norm();
  for (size_t i = 0; i < world.bodies.size() && m.finite; ++i) {
    const Body& b = world.bodies[i];
    if (b.isStatic) continue;
    m.maxDisplacement = std::max(m.maxDisplacement, (b.x - rest[i]).norm());
    m.fastest = std::max(m.fastest, b.v.norm());
  }
  return m;
}

bool holds(RunMetrics& m, const MetricsOptions& o) {
  if (!m.finite) m.failure = "non-finite state";
  else if (o.energy && (!std::isfinite(m.energyTrend) || m.energyTrend > 0.10)) m.failure = "energy grows";
  else if (m.tunneled) m.failure = "tunneling";
  else if (o.stack && m.topDrift > 0.05) m.failure = "stack drifts";
  else if (o.within > 0.0 && m.maxDisplacement > o.within) m.failure = "a body leaves its rest pose";
  else if (o.within > 0.0 && m.fastest > kRestSpeed) m.failure = "not at rest";
  else if (o.penetration && m.maxPenetration > 2.0 * settings::kLinearSlop) m.failure = "penetration";
  else m.failure = "";
  return *m.failure == '\0';
}

}  // namespace render::analysis
