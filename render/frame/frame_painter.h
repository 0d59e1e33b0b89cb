// A frame of a scene, described on a Canvas from the world, its history and the render:
// block, back to front: static bodies and planes, trails, strobe ghosts, the moving bodies,
// springs, contacts and impulses (held after they happen), velocity arrows, labels, the time, the
// slow-motion note and the caption.
#pragma once

#include <functional>
#include <vector>

#include "render/draw/camera.h"
#include "render/draw/draw_list.h"
#include "render/frame/caption.h"
#include "render/frame/energy_panel.h"
#include "render/frame/history.h"
#include "render/frame/label_place.h"
#include "render/frame/survey.h"
#include "render/frame/teaching_arrows.h"
#include "render/scene/scene.h"
#include "sim/world/world.h"

namespace render::frame {

class FramePainter {
 public:
  // `width` measures text at the frame's font size, to wrap the caption (empty: an estimate)
  FramePainter(const render::scene::Scene& def, const render::draw::Camera& camera, const RunSurvey& survey,
               const TextWidth& width = {});

  // what the history of a run must record for these frames
  History::Options historyOptions() const;
  // how these frames draw the history's afterimages: their arrows' scales and labels
  History::Look afterimageLook() const;
  // the frame at the world's present time; `ghosts` are earlier poses (strobe), oldest first. Every
  // text goes through one LabelPlacer (label_place.h) and reaches `draw` last, placed; `placed` (when
  // given) is told where each went
  void paint(const sim::world::World& world, const History& history, const std::vector<render::draw::DrawList>& ghosts,
             render::draw::Canvas& draw, std::vector<PlacedText>* placed = nullptr) const;
  // the text of the time caption, e.g. "t = 0.500 s"
  static std::string timeText(double t);
  // how many times slower a video shows simulation time t (the video's time map); frames say
  // "slow motion ×1/4" under the time while it is above 1 (empty: never)
  using SlowFactor = std::function<double(double t)>;
  void showSlowMotion(SlowFactor factorAt) { slowMotion_ = std::move(factorAt); }
  const SlowFactor& slowMotion() const { return slowMotion_; }
  static std::string slowMotionText(double factor);

  double impulseScale() const { return impulseScale_; }
  double velocityScale() const { return velocityScale_; }

 private:
  const render::scene::Scene& def_;
  render::draw::Camera camera_;
  double impulseScale_, velocityScale_;  // m of arrow per N·s, per m/s
  // video timing and text: the slow-motion note and the caption, drawn last
  void paintTimingText(double t, render::draw::Canvas& draw) const;
  // the bodies' labels, as `labels:` says (auto: those that fit, or all of a small scene)
  void paintLabels(const sim::world::World& world, LabelPlacer& draw) const;
  bool labelFits(size_t index, const sim::core::Body& body, const std::string& label) const;
  // many contact points: their dots' radius in px, scaled to the moving bodies' width on the frame
  double manyDotRadiusPx(const sim::world::World& world) const;
  mutable bool unfitTold_ = false;  // labels that do not fit: said once per run
  // each body's label width in px, measured once (a body's label is the same in every frame; a
  // frame of 5,050 boxes spent 3 % of its render measuring them), negative until measured
  mutable std::vector<double> labelWidthsPx_;
  std::vector<std::string> captionLines_;
  TextWidth textWidth_;            // of the frame's texts, px (empty: estimated)
  mutable DroppedLabels dropped_;  // said once each per run
  SlowFactor slowMotion_;
  TeachingArrows arrows_;  // the lecture overlays
  EnergyPanel panel_;
  History::Look look_;  // afterimageLook(), made once
};

}  // namespace render::frame
