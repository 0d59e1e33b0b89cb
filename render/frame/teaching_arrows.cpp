#include "render/frame/teaching_arrows.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/draw/style.h"
#include "render/frame/contact_forces.h"
#include "render/frame/label_place.h"
#include "render/frame/point_forces.h"
#include "render/frame/quantity_text.h"
#include "render/scene/scene_style.h"
#include "sim/scene/scene_build.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;
using namespace render::scene;

namespace {

using Show = render::scene::ArrowDef::Show;

constexpr double kPi = std::numbers::pi;
// the largest |ω| (|τ|) of the run sweeps this much; the arcs' radii as fractions of the view's height
// (ω inside τ, so both fit around one body), and the body frame's axes likewise
constexpr double kMaxSweep = 1.5 * kPi;
constexpr double kOmegaRadius = 0.06, kTorqueRadius = 0.09, kFrameLength = 0.1;
// a curved arrow's head is drawn as a straight arrow over its last 14 px of arc
constexpr double kHeadPx = 14.0;

Role roleOf(Show show) {
  switch (show) {
    case Show::Velocity: return Role::Velocity;
    case Show::Offset: return Role::Offset;
    case Show::Omega: return Role::AngularVelocity;
    case Show::Frame: return Role::BodyFrame;
    case Show::Path: return Role::Path;
    case Show::Force: return Role::Force;
    case Show::Torque: return Role::Torque;
    case Show::Momentum: return Role::Momentum;
    case Show::NormalForce: return Role::NormalForce;
    case Show::Friction: return Role::Friction;
    case Show::Center: return Role::CenterOfMass;
  }
  return Role::Velocity;
}

Vec2 onCircle(const Vec2& center, double radius, double angle) {
  return center + radius * Vec2(std::cos(angle), std::sin(angle));
}

}  // namespace

TeachingArrows::TeachingArrows(const render::scene::Scene& def, const Camera& camera, const RunSurvey& survey,
                               double velocityScale)
    : px_(camera.pixelSize()),
      viewHeight_(camera.worldHeight()),
      velocityScale_(velocityScale),
      // point and contact forces on one scale: a push beside the friction that holds against it
      forceScale_(arrowScale(def.render.overlays.forceScale, std::max(survey.maxForce, survey.maxContactForce), camera)),
      momentumScale_(arrowScale(def.render.overlays.momentumScale, survey.maxMomentum, camera)),
      maxOmega_(survey.maxOmega),
      maxTorque_(survey.maxTorque),
      speedFloor_(noiseFloor(survey.maxSpeed + survey.maxOmega * camera.worldHeight())),
      forceFloor_(noiseFloor(std::max(survey.maxForce, survey.maxContactForce))),
      momentumFloor_(noiseFloor(survey.maxMomentum)),
      omegaFloor_(noiseFloor(survey.maxOmega)),
      torqueFloor_(noiseFloor(survey.maxTorque)),
      lengthFloor_(noiseFloor(camera.worldHeight())) {
  int paths = 0;
  for (const render::scene::ArrowDef& a : def.render.overlays.arrows)
    arrows_.push_back({a, localPoint(def, a), a.show == Show::Path ? paths++ : -1});
}

Vec2 TeachingArrows::localPoint(const render::scene::Scene& def, const render::scene::ArrowDef& a) {
  // `at` is written as a force's point: in the shape's coordinates, before the centroid shift
  return a.at - sim::scene::massProperties(def.model.bodies[a.body]).centroid;
}

std::vector<std::pair<int, Vec2>> TeachingArrows::pathsOf(const render::scene::Scene& def) {
  std::vector<std::pair<int, Vec2>> out;
  for (const render::scene::ArrowDef& a : def.render.overlays.arrows)
    if (a.show == Show::Path) out.emplace_back(a.body, localPoint(def, a));
  return out;
}

std::string TeachingArrows::defaultLabel(Show show) {
  switch (show) {
    case Show::Velocity: return "v";
    case Show::Offset: return "r′";
    case Show::Omega: return "ω";
    case Show::Frame: return "x_b";
    case Show::Path: return "r";
    case Show::Force: return "f";
    case Show::Torque: return "τ";
    case Show::Momentum: return "p";
    case Show::NormalForce: return "N";
    case Show::Friction: return "F_f";
    case Show::Center: return "c";
  }
  return "";
}

void TeachingArrows::curvedArrow(const Vec2& center, double radius, double middle, double sweep, double pixel, const Pen& style,
                                 Canvas& draw) {
  const double length = std::abs(sweep) * radius;
  if (!(length > pixel)) return;
  const double sign = sweep > 0.0 ? 1.0 : -1.0, from = middle - 0.5 * sweep, to = middle + 0.5 * sweep;
  // the arc in pieces of at most π/32 (under 0.1 px off the circle at these radii), then the head
  const double head = std::min(std::abs(sweep), kHeadPx * pixel / radius);
  const double arc = std::abs(sweep) - head;
  const int pieces = static_cast<int>(std::ceil(arc / (kPi / 32.0)));
  for (int k = 0; k < pieces; ++k)
    draw.segment(onCircle(center, radius, from + sign * arc * k / pieces),
                 onCircle(center, radius, from + sign * arc * (k + 1) / pieces), style);
  draw.arrow(onCircle(center, radius, to - sign * head), onCircle(center, radius, to), style);
}

void TeachingArrows::draw(const sim::world::World& world, const History& history, Canvas& draw) const {
  for (size_t i = 0; i < arrows_.size(); ++i) drawOne(arrows_[i], static_cast<int>(i), world, history, draw);
}

void TeachingArrows::label(const Arrow& a, const std::string& value, const Vec2& anchor, const Vec2& direction,
                           Canvas& draw) const {
  const std::string name = a.def.label.empty() ? defaultLabel(a.def.show) : a.def.label;
  const std::string text = a.def.value && !value.empty() ? name + value : name;
  draw.label(anchor, direction, text, {Role::Label, a.def.body, 1.0});
}

// a straight arrow from `tail` along `vector`, labeled past its head; one under a pixel long is a
// dot with its label, out from the body's center (the rolling disk's "v = 0" at its contact)
void TeachingArrows::straight(const Arrow& a, const Pen& style, const sim::core::Body& b, const Vec2& tail, const Vec2& vector,
                              const std::string& shown, Canvas& draw) const {
  if (vector.norm() > px_) {
    draw.arrow(tail, tail + vector, style);
    label(a, shown, tail + vector, vector.normalized(), draw);
    return;
  }
  draw.point(tail, style);
  label(a, shown, tail, directionOr(tail - b.x, Vec2::UnitY()), draw);
}

// ω arcs over the top, τ under the bottom, each labeled out from its middle
void TeachingArrows::spin(const Arrow& a, const Pen& style, const sim::core::Body& b, const sim::world::World& world,
                          Canvas& draw) const {
  const bool omega = a.def.show == Show::Omega;
  const double amount = omega ? b.omega : torqueOf(b, pointForcesOn(world, a.def.body));
  const double largest = omega ? maxOmega_ : maxTorque_;
  const double radius = (omega ? kOmegaRadius : kTorqueRadius) * viewHeight_, middle = omega ? 0.5 * kPi : -0.5 * kPi;
  if (!(largest > 0.0) || amount == 0.0) return;
  curvedArrow(b.x, radius, middle, kMaxSweep * amount / largest, px_, style, draw);
  const Vec2 out(0.0, omega ? 1.0 : -1.0);
  label(a, quantityText("", amount, omega ? "rad/s" : "N·m", omega ? omegaFloor_ : torqueFloor_), b.x + radius * out, out, draw);
}

// the body frame's axes x_b and y_b from its center of mass
void TeachingArrows::frame(const Arrow& a, const Pen& style, const sim::core::Body& b, Canvas& draw) const {
  const double length = kFrameLength * viewHeight_;
  const Vec2 x = b.q().apply(Vec2::UnitX()), y = b.q().apply(Vec2::UnitY());
  draw.arrow(b.x, b.x + length * x, style);
  draw.arrow(b.x, b.x + length * y, style);
  const Pen text{Role::Label, a.def.body, 1.0};
  draw.label(b.x + length * x, x, "x_b", text);
  draw.label(b.x + length * y, y, "y_b", text);
}

void TeachingArrows::drawOne(const Arrow& a, int index, const sim::world::World& world, const History& history,
                             Canvas& draw) const {
  const sim::core::Body& b = world.bodies[a.def.body];
  const Pen style{roleOf(a.def.show), a.def.body, 1.0, a.def.color.empty() ? -1 : index};
  const Vec2 point = b.pose().toWorld(a.local);
  // the value after the label: " = 1.25 m/s", 0 below its noise floor
  const auto value = [](double x, const std::string& unit, double floor) { return quantityText("", x, unit, floor); };
  switch (a.def.show) {
    case Show::Velocity: {
      // the notes' velocity of a body point: v + ω × r′
      const Vec2 v = b.pointVelocity(point);
      straight(a, style, b, point, velocityScale_ * v, value(v.norm(), "m/s", speedFloor_), draw);
      break;
    }
    case Show::Offset: {
      const Vec2 r = point - b.x;
      if (!(r.norm() > px_)) break;
      draw.arrow(b.x, point, style);
      // beside its middle, to the left: its head is where a velocity arrow starts
      label(a, value(r.norm(), "m", lengthFloor_), 0.5 * (b.x + point), Vec2(-r.y(), r.x()).normalized(), draw);
      break;
    }
    case Show::Momentum:
      straight(a, style, b, b.x, momentumScale_ * b.mass * b.v, value(b.mass * b.v.norm(), "kg·m/s", momentumFloor_), draw);
      break;
    case Show::Force:
      for (const AppliedForce& f : pointForcesOn(world, a.def.body))
        straight(a, style, b, f.point, forceScale_ * f.force, value(f.force.norm(), "N", forceFloor_), draw);
      break;
    case Show::NormalForce:
    case Show::Friction:
      // at each pair the body touches, from where its normal impulses are centred
      for (const ContactForce& f : contactForcesOn(world, a.def.body)) {
        const Vec2 force = a.def.show == Show::NormalForce ? f.normal : f.friction;
        straight(a, style, b, f.point, forceScale_ * force, value(force.norm(), "N", forceFloor_), draw);
      }
      break;
    case Show::Omega:
    case Show::Torque: spin(a, style, b, world, draw); break;
    case Show::Frame: frame(a, style, b, draw); break;
    case Show::Center:
      // the center of mass, wherever `at` is: the quartered disc, labeled out from it
      draw.point(b.x, style);
      label(a, vectorText("", b.x, "m", lengthFloor_), b.x, Vec2(-1.0, 0.0), draw);
      break;
    case Show::Path: {
      History::drawPath(history.pointPath(a.path), 1.5 * px_, style, draw);
      draw.point(point, style);
      label(a, vectorText("", point, "m", lengthFloor_), point, directionOr(point - b.x, Vec2::UnitY()), draw);
      break;
    }
  }
}

}  // namespace render::frame
