// A frame of a scene, described through DebugDraw from the world, its history and the render:
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
#include "render/frame/survey.h"
#include "render/frame/teaching_arrows.h"
#include "sim/scene/scene_def.h"
#include "sim/world/world.h"

namespace render::frame {
using namespace render::draw;

// the contacts touching now (world.contacts): a dot at each manifold point and an arrow
// `normalLength` long along its normal, from B into A (into B when A is static)
void describeContacts(const sim::world::World& world, double normalLength, sim::debug::DebugDraw& draw);

// the notes' separating-axis overlay of every polygon pair (not both static) whose separation is at
// most `maxGap`: the reference edge, the incident vertex, and the separation written `labelOffset`
// inside the reference polygon from the edge; with `everyAxis`, every other candidate edge too
void describeSeparatingAxes(const sim::world::World& world, double maxGap, double labelOffset, sim::debug::DebugDraw& draw,
                            bool everyAxis = false);

class FramePainter {
 public:
  // `width` measures text at the frame's font size, to wrap the caption (empty: an estimate)
  FramePainter(const sim::scene::SceneDef& def, const Camera& camera, const RunSurvey& survey, const TextWidth& width = {});

  // what the history of a run must record for these frames
  History::Options historyOptions() const;
  // the frame at the world's present time; `ghosts` are earlier poses (strobe), oldest first
  void paint(const sim::world::World& world, const History& history, const std::vector<DrawList>& ghosts,
             sim::debug::DebugDraw& draw) const;
  // the text of the time caption, e.g. "t = 0.500 s"
  static std::string timeText(double t);
  // how many times slower a video shows simulation time t (the video's time map); frames say
  // "slow motion ×1/4" under the time while it is above 1 (empty: never)
  using SlowFactor = std::function<double(double t)>;
  void showSlowMotion(SlowFactor factorAt) { slowMotion_ = std::move(factorAt); }
  static std::string slowMotionText(double factor);

  double impulseScale() const { return impulseScale_; }
  double velocityScale() const { return velocityScale_; }

 private:
  const sim::scene::SceneDef& def_;
  Camera camera_;
  double impulseScale_, velocityScale_;  // m of arrow per N·s, per m/s
  // video timing and text: the slow-motion note and the caption, drawn last
  void paintTimingText(double t, sim::debug::DebugDraw& draw) const;
  std::vector<std::string> captionLines_;
  SlowFactor slowMotion_;
  TeachingArrows arrows_;                 // the lecture overlays
  EnergyPanel panel_;
};

}  // namespace render::frame
