// The `arrows:` of the render: block, drawn every frame: the notes' vectors of a rigid body (notes:
// "Dynamics of a free body", "Forces and torques") at a body point `at`, each labeled: v + ω × r′,
// r′ = R r_b, ω and τ as curved arrows, the body frame, the path of the point, the point forces, m v.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/draw/camera.h"
#include "render/frame/history.h"
#include "render/frame/survey.h"
#include "render/scene/scene.h"
#include "sim/world/world.h"

namespace render::frame {

class TeachingArrows {
 public:
  // `velocityScale`: m of arrow per m/s, as the frame's velocity arrows
  TeachingArrows(const render::scene::Scene& def, const render::draw::Camera& camera, const RunSurvey& survey,
                 double velocityScale);

  // the body points whose paths the history must keep (`show: path`), in body coordinates
  static std::vector<std::pair<int, sim::core::Vec2>> pathsOf(const render::scene::Scene& def);
  // every arrow at the world's present state; `history` kept the pathsOf(def)
  void draw(const sim::world::World& world, const History& history, render::draw::Canvas& draw) const;

  // "v", "r′", "ω", "x_b", "r", "f", "τ", "p"
  static std::string defaultLabel(render::scene::ArrowDef::Show show);
  // a curved arrow around `center`, `radius` from it, sweeping `sweep` (counter-clockwise when
  // positive) centered on the direction `middle` (an angle); `pixel`: the world length of a pixel
  static void curvedArrow(const sim::core::Vec2& center, double radius, double middle, double sweep, double pixel,
                          const render::draw::Pen& style, render::draw::Canvas& draw);

 private:
  struct Arrow {
    render::scene::ArrowDef def;
    sim::core::Vec2 local;  // `at` in body coordinates after the centroid shift
    int path = -1;          // index among pathsOf(def)
  };
  // `at` in body coordinates after the centroid shift
  static sim::core::Vec2 localPoint(const render::scene::Scene& def, const render::scene::ArrowDef& a);
  void drawOne(const Arrow& a, int index, const sim::world::World& world, const History& history,
               render::draw::Canvas& draw) const;
  // drawOne's stages: a straight arrow with its label, ω's or τ's arc, the body frame's axes
  void straight(const Arrow& a, const render::draw::Pen& style, const sim::core::Body& b, const sim::core::Vec2& tail,
                const sim::core::Vec2& vector, const std::string& shown, render::draw::Canvas& draw) const;
  void spin(const Arrow& a, const render::draw::Pen& style, const sim::core::Body& b, const sim::world::World& world,
            render::draw::Canvas& draw) const;
  void frame(const Arrow& a, const render::draw::Pen& style, const sim::core::Body& b, render::draw::Canvas& draw) const;
  // the arrow's label (with its value) beyond `anchor` in `direction`
  void label(const Arrow& a, const std::string& value, const sim::core::Vec2& anchor, const sim::core::Vec2& direction,
             render::draw::Canvas& draw) const;

  std::vector<Arrow> arrows_;
  double px_, viewHeight_;                             // world lengths of a pixel and of the view
  double velocityScale_, forceScale_, momentumScale_;  // m of arrow per m/s, N, kg·m/s
  double maxOmega_, maxTorque_;                        // the run's, for the curved arrows' sweeps
  // the values' noise floors (quantity_text.h): speeds, forces, momenta, ω, τ and lengths below them are 0
  double speedFloor_, forceFloor_, momentumFloor_, omegaFloor_, torqueFloor_, lengthFloor_;
};

}  // namespace render::frame
