// One run of a scene variant for a golden record: the world advanced once, and at each checkpoint
// (every expect time, every golden time, the end) its state hash and trace rows, at each golden time
// its draw list and frame; each instant reached as a fresh run reaches it (SceneRun::shotsAt).
#pragma once

#include <string>
#include <vector>

#include "render/draw/image.h"
#include "render/golden/draw_list_json.h"
#include "render/golden/golden_def.h"
#include "render/golden/trace_csv.h"
#include "render/scene/scene.h"

namespace render::golden {

struct Checkpoint {
  double t = 0.0;
  unsigned long long hash = 0;      // sim::world::stateHash
  std::vector<TraceSample> bodies;  // by the scene's body index
};

struct GoldenFrame {
  double t = 0.0;
  std::string name;  // "frame-t<time>", the base of its .png and .json
  DrawnFrame drawn;
  render::draw::Image image;  // empty when the run drew no pixels
};

// the times of a run: the checkpoints, and the frames among them
struct GoldenTimes {
  std::vector<double> checkpoints;  // ascending, each once
  std::vector<double> frames;       // ascending, each once
};

struct GoldenRun {
  std::string name;  // "<scene>[-<variant>]": the record's folder
  std::vector<std::string> bodies;
  std::vector<Checkpoint> checkpoints;
  std::vector<GoldenFrame> frames;
  std::string renderer, rendererVersion;  // as GL reports them ("" without pixels)
  bool threeD = false;                    // a 3D scene's: its trace has the 3D columns
};

// the times the scene's golden: block asks for: frames at `at` (else the end) and its impacts (up to
// kMaxImpactFrames) unless `impacts: false`; checkpoints at those, every expect time and the end.
// Runs the scene once to find its impacts. Throws sim::world::Diverged.
GoldenTimes goldenTimes(const render::scene::Scene& scene, const GoldenDef& golden);
// the run at `times`, frames at the golden size; without `pixels` no GL is loaded and the frames
// are draw lists alone. Throws sim::world::Diverged, std::runtime_error (GL).
GoldenRun runGolden(const render::scene::Scene& scene, const GoldenDef& golden, const GoldenTimes& times, bool pixels);

// "frame-t1.5"
std::string frameName(double t);

}  // namespace render::golden
