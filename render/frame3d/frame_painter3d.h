// A 3D frame of a scene, on a Canvas3d from the world, its history and the render: block, back to
// front: the solids (shaded, outlined, with a depth buffer); then over them, in pixels: trails,
// springs, the paths of body points and of ω's tip, the teaching arrows (body axes, ω, L, v) with
// their labels, the bodies' labels, the time and the state text (x, q, |q|), the world's axes, the
// energy panel, the slow-motion note and the caption.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "render/draw/canvas.h"
#include "render/draw3d/canvas3d.h"
#include "render/frame/caption.h"
#include "render/frame/label_place.h"
#include "render/frame3d/energy3d.h"
#include "render/frame3d/history3d.h"
#include "render/frame3d/survey3d.h"

namespace render::frame3d {

class FramePainter3d {
 public:
  // `width` measures text at the frame's font size, to wrap the caption (empty: an estimate)
  FramePainter3d(const render::scene3d::Scene& def, const render::draw3d::Camera3d& camera, const RunSurvey3d& survey,
                 const render::frame::TextWidth& width = {});

  // what the history of a run must record for these frames
  History3d::Options historyOptions() const;
  void paint(const sim::world3d::World& world, const History3d& history, render::draw3d::Canvas3d& canvas) const;
  void showSlowMotion(std::function<double(double)> factorAt) { slowMotion_ = std::move(factorAt); }
  const std::function<double(double)>& slowMotion() const { return slowMotion_; }

  // "x = (1.00, −0.50, 0.20) m", "q = [0.924, 0.000, 0.383, 0.000]", "|q| = 1.000000"
  // (positions below `lengthFloor` m, the noise floor of the run's extent, are 0)
  static std::vector<std::string> stateText(const sim::world3d::Body& body, double lengthFloor = 0.0);

  double omegaScale() const { return omegaScale_; }
  double angularMomentumScale() const { return momentumScale_; }

 private:
  // a world point on the overlay (pixels, y up), when it lies in front of the camera
  std::optional<sim::core::Vec2> screen(const sim::world3d::Vec3& world) const;
  void arrow(const sim::world3d::Vec3& tail, const sim::world3d::Vec3& head, const render::draw::Pen& pen,
             const std::string& label, render::draw::Canvas& draw) const;
  void path(const std::vector<sim::world3d::Vec3>& points, const sim::world3d::Vec3& offset, const render::draw::Pen& pen,
            render::draw::Canvas& draw) const;
  void paintArrows(const sim::world3d::World& world, const History3d& history, render::draw::Canvas& draw) const;
  void paintText(const sim::world3d::World& world, render::draw::Canvas& draw) const;
  void paintWorldAxes(render::draw::Canvas& draw) const;
  // each plane as a ruled square around where the bodies go, before the bodies
  void paintPlanes(const sim::world3d::World& world, render::draw3d::Canvas3d& canvas) const;
  // the contacts touching now (a dot and the normal at each point) and, held for contact_hold after
  // each impact, its point, normal and the impulse on the body (2D's contacts overlay)
  void paintContacts(const sim::world3d::World& world, render::draw::Canvas& draw) const;

  const render::scene3d::Scene& def_;
  render::draw3d::Camera3d camera_;
  render::draw::Camera overlay_;                  // pixels, y up
  render::frame::TextWidth textWidth_;            // of the frame's texts, px (empty: estimated)
  mutable render::frame::DroppedLabels dropped_;  // labels with no free spot, said once each per run
  // body i's mesh: one per shape and level of detail (mesh.h: segmentsFor its size on screen),
  // shared by every body of that shape and size, so that memory does not grow with the bodies
  const render::draw3d::Mesh& meshFor(size_t body, const sim::world3d::Body& b) const;
  std::vector<std::string> shapeKeys_;  // by body: its shape, as text
  std::vector<double> radii_;           // by body: the radius of a ball around its shape, m
  mutable std::map<std::pair<std::string, int>, render::draw3d::Mesh> meshes_;
  double omegaScale_, momentumScale_, velocityScale_;  // m of arrow per rad/s, kg·m²/s, m/s
  double impulseScale_;                                // m of arrow per N·s
  render::draw3d::Mesh planeMesh_;                     // every plane's patch, square around the run
  sim::world3d::Vec3 planeCenter_;                     // the center of the run's bounds, projected on each plane
  double em_;                                          // text size, px
  double lengthFloor_ = 0.0;                           // positions below it are round-off, m
  EnergyPanel3d panel_;
  std::vector<std::string> captionLines_;
  std::function<double(double)> slowMotion_;
};

}  // namespace render::frame3d
