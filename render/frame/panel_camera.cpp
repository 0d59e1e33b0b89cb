#include "render/frame/panel_camera.h"

#include <iostream>
#include <sstream>

#include "render/frame/scene_run.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;

namespace {

// rounds of growing the view: an arrow is at most a sixth of the view, so each round's overshoot is
// a sixth of the last and a few rounds settle it
constexpr int kFitRounds = 8;
// instants of a run the camera is fitted over, besides its impacts: an arrow changes smoothly between
// impacts, and at 48 a run of a few seconds is looked at every few hundredths of a second
constexpr int kFitInstants = 48;

bool fixedToFrame(Role r) {
  switch (r) {
    case Role::Caption:
    case Role::Label:
    case Role::KineticBar:
    case Role::RotationalBar:
    case Role::PotentialBar:
    case Role::TotalBar:
    case Role::Panel:
    case Role::Backing: return true;
    default: return false;
  }
}

// standard error held back while the camera is fitted: the frames drawn to fit it are never shown,
// so a label they drop is no news (the frames drawn later say so themselves); planning is one thread
class QuietErrors {
 public:
  QuietErrors() : saved_(std::cerr.rdbuf(held_.rdbuf())) {}
  ~QuietErrors() { std::cerr.rdbuf(saved_); }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  std::ostringstream held_;
  std::streambuf* saved_;
};

bool inside(const Bounds& outer, const Bounds& inner) {
  return inner.empty() || (outer.min.x() <= inner.min.x() && outer.min.y() <= inner.min.y() && inner.max.x() <= outer.max.x() &&
                           inner.max.y() <= outer.max.y());
}

}  // namespace

Bounds drawnBounds(const DrawList& list) {
  Bounds b;
  for (const DrawList::Call& c : list.calls()) {
    if (fixedToFrame(c.style.role)) continue;
    switch (c.kind) {
      case DrawList::Kind::Text:
      case DrawList::Kind::Label:
      case DrawList::Kind::HalfPlane: break;
      case DrawList::Kind::Circle:
        b.add(c.points.at(0) - Vec2(c.radius, c.radius));
        b.add(c.points.at(0) + Vec2(c.radius, c.radius));
        break;
      default:
        for (const Vec2& p : c.points) b.add(p);
    }
  }
  return b;
}

std::vector<double> fittingInstants(const render::scene::Scene& scene, const RunSurvey& survey) {
  std::vector<double> at;
  for (int k = 0; k < kFitInstants; ++k) at.push_back(scene.model.duration * k / (kFitInstants - 1));
  at.insert(at.end(), survey.impactTimes.begin(), survey.impactTimes.end());
  return at;
}

Camera panelCamera(const std::vector<render::scene::Scene>& scenes, const std::vector<RunSurvey>& surveys, size_t widest) {
  Bounds bounds;
  for (const RunSurvey& s : surveys) bounds.add(s.bounds);
  Camera camera = cameraFor(scenes[widest], surveys[widest], bounds);
  if (scenes[widest].render.camera.automatic == false) return camera;  // a fixed window is the scene's to choose
  const QuietErrors quiet;
  for (int round = 0; round < kFitRounds; ++round) {
    Bounds drawn;
    for (size_t v = 0; v < scenes.size(); ++v) {
      SceneRun run(scenes[v], camera, surveys[v]);
      run.drawListsAt(fittingInstants(scenes[v], surveys[v]), 0, [&](size_t, DrawList list) { drawn.add(drawnBounds(list)); });
    }
    if (inside(bounds, drawn)) break;
    bounds.add(drawn);
    camera = cameraFor(scenes[widest], surveys[widest], bounds);
  }
  return camera;
}

}  // namespace render::frame
