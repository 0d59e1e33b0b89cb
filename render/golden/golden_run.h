// One run of a scene variant for a golden record: the world advanced once, and at each checkpoint
// (every expect time, every golden time, the end) its state hash and trace rows, at each golden time
// its draw list and frame; each instant reached as a fresh run reaches it (SceneRun::shotsAt).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "render/draw/image.h"
#include "render/golden/draw_list_json.h"
#include "render/golden/golden_def.h"
#include "render/trace/trace_csv.h"
#include "render/scene/scene.h"
#include "render/video/output_names.h"

namespace render::golden {

struct Checkpoint {
  double t = 0.0;
  unsigned long long hash = 0;                     // sim::world::stateHash
  std::vector<render::trace::TraceSample> bodies;  // by the scene's body index
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

// the times a scene's golden: block asks for, given its run's impacts (ascending, each once): frames
// at `at` (else the end) and those impacts (up to kMaxImpactFrames) unless `impacts: false`;
// checkpoints at those, every expect time and the end. 2D and 3D models alike.
template <class Model>
GoldenTimes goldenTimes(const Model& model, const GoldenDef& golden, const std::vector<double>& impactTimes) {
  const auto sortUnique = [](std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  };
  GoldenTimes times;
  times.frames = golden.at.empty() ? std::vector<double>{model.duration} : golden.at;
  if (golden.impacts)
    times.frames.insert(times.frames.end(), impactTimes.begin(),
                        impactTimes.begin() + static_cast<std::ptrdiff_t>(std::min(kMaxImpactFrames, impactTimes.size())));
  sortUnique(times.frames);
  times.checkpoints = times.frames;
  for (const auto& e : model.expects) times.checkpoints.push_back(e.time);
  times.checkpoints.push_back(model.duration);
  sortUnique(times.checkpoints);
  return times;
}

// the scene (2D or 3D) drawn at the golden size
template <class Scene>
Scene atGoldenSize(Scene scene, const GoldenDef& golden) {
  scene.render.width = golden.width;
  scene.render.height = golden.height;
  return scene;
}

// a run of `model` (2D or 3D) before its checkpoints and frames: its record's name and its bodies
template <class Model>
GoldenRun goldenRunOf(const Model& model, bool threeD) {
  GoldenRun run;
  run.name = render::video::outputBase(model.name, model.variant);
  for (const auto& b : model.bodies) run.bodies.push_back(b.name);
  run.threeD = threeD;
  return run;
}

// a golden record's survey and times: the survey (by `surveyRun`, 2D's or 3D's) keeps its run at the
// instants known before it (all but its impacts'), for the shots to go on from; the times are `asked`
// or, when null, those the scene's golden: block asks for with the survey's impacts
template <class Survey>
struct GoldenSurvey {
  Survey survey;
  GoldenTimes times;
};
template <class Scene, class SurveyRun>
auto surveyGolden(const Scene& scene, const GoldenDef& golden, const GoldenTimes* asked, SurveyRun surveyRun) {
  auto survey = surveyRun(scene, -1.0, asked ? asked->checkpoints : goldenTimes(scene.model, golden, {}).checkpoints);
  GoldenTimes times = asked ? *asked : goldenTimes(scene.model, golden, survey.impactTimes);
  return GoldenSurvey<decltype(survey)>{std::move(survey), std::move(times)};
}

// the run at `times`, or (null) at those its golden: block asks for, the impacts taken from the
// survey the drawing needs anyway, which keeps its run at the instants known before it (the scene is
// stepped once; an impact's frame steps from the kept state before it); frames at the
// golden size; without `pixels` no GL is loaded and the frames are draw lists alone. Throws
// sim::core::Diverged, std::runtime_error (GL).
GoldenRun runGolden(const render::scene::Scene& scene, const GoldenDef& golden, const GoldenTimes* times, bool pixels);

// "frame-t1.5"
std::string frameName(double t);

}  // namespace render::golden
