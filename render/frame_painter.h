// A frame of a scene, described through DebugDraw from the world, its history and the render:
// block, back to front: static bodies and planes, trails, strobe ghosts, the moving bodies,
// springs, contacts and impulses (held after they happen), velocity arrows, labels, the time, the
// slow-motion note and the caption.
#pragma once

#include <vector>

#include "camera.h"
#include "caption.h"
#include "draw_list.h"
#include "energy_panel.h"
#include "history.h"
#include "scene_def.h"
#include "survey.h"
#include "time_map.h"
#include "teaching_arrows.h"
#include "world.h"

namespace render {

// the contacts touching now (world.contacts): a dot at each manifold point and an arrow
// `normalLength` long along its normal, from B into A (into B when A is static)
void describeContacts(const sim::World& world, double normalLength, sim::DebugDraw& draw);

// the notes' separating-axis overlay of every polygon pair (not both static) whose separation is at
// most `maxGap`: the reference edge, the incident vertex, and the separation written `labelOffset`
// inside the reference polygon from the edge; with `everyAxis`, every other candidate edge too
void describeSeparatingAxes(const sim::World& world, double maxGap, double labelOffset, sim::DebugDraw& draw,
                            bool everyAxis = false);

class FramePainter {
 public:
  // `width` measures text at the frame's font size, to wrap the caption (empty: an estimate)
  FramePainter(const sim::SceneDef& def, const Camera& camera, const RunSurvey& survey, const TextWidth& width = {});

  // what the history of a run must record for these frames
  History::Options historyOptions() const;
  // the frame at the world's present time; `ghosts` are earlier poses (strobe), oldest first
  void paint(const sim::World& world, const History& history, const std::vector<DrawList>& ghosts,
             sim::DebugDraw& draw) const;
  // the text of the time caption, e.g. "t = 0.500 s"
  static std::string timeText(double t);
  // video frames say "slow motion ×1/4" under the time while `map` slows them (nullptr: never)
  void showSlowMotion(const TimeMap* map) { slowMotion_ = map; }
  static std::string slowMotionText(double factor);

  double impulseScale() const { return impulseScale_; }
  double velocityScale() const { return velocityScale_; }

 private:
  const sim::SceneDef& def_;
  Camera camera_;
  double impulseScale_, velocityScale_;  // m of arrow per N·s, per m/s
  // video timing and text: the slow-motion note and the caption, drawn last
  void paintTimingText(double t, sim::DebugDraw& draw) const;
  std::vector<std::string> captionLines_;
  const TimeMap* slowMotion_ = nullptr;
  TeachingArrows arrows_;                 // the lecture overlays
  EnergyPanel panel_;
};

}  // namespace render
