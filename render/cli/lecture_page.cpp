#include "render/cli/lecture_page.h"

#include <filesystem>
#include <iostream>

#include "render/cli/scene_order.h"
#include "render/cli/output.h"
#include "render/frame/quantity_text.h"
#include "render/frame/caption.h"
#include "render/page/page.h"
#include "render/video/output_names.h"
#include "sim/scene/expect.h"
#include "sim/scene3d/expect.h"

namespace render::cli {

namespace fs = std::filesystem;

std::string lectureRecordPath(const std::string& scene, const std::string& root) {
  return (fs::path(root) / scene / render::page::kRecordName).string();
}

std::string lecturePagePath(const std::string& root) { return (fs::path(root) / render::page::kPageName).string(); }

namespace {

// the record's part every scene has: its title, description, question, answer and time, its videos
// and its poll panels (a panel at t = 0 shows the poll's question, nothing has happened yet; one at
// or after the scene's `reveal` time, its answer; any other, neither); `variants` names each planned
// variant
template <class Plan>
render::page::SceneRecord recordOf(const Plan& plan, const render::scene::RenderDef& look, const std::string& title,
                                   const std::string& description, const std::vector<std::string>& variants,
                                   const std::string& file, const std::string& path, double seconds) {
  render::page::SceneRecord r;
  r.scene = plan.scene;
  // the scene file as the pack names it, never a path of this machine
  r.file = fs::path(file).filename().string();
  r.title = title;
  r.description = description;
  r.question = look.poll.question;
  r.answer = look.poll.answer;
  r.seconds = seconds;
  r.order = orderInFolder(file);
  // the files as the plan names them, relative to the record's folder (a variant may rename its own)
  const auto name = [&](const std::string& p) { return fs::path(p).lexically_relative(fs::path(path).parent_path()).string(); };
  for (const auto& v : plan.videos) r.videos.push_back({variants[v.variant], name(v.path), name(v.posterPath), v.fps});
  if (plan.stills)
    for (size_t i = 0; i < plan.stills->shots.size(); ++i) {
      const render::video::StillOutput& shot = plan.stills->shots[i];
      const double t = shot.instants.at(0);
      const bool answer = look.poll.tellsAnswer(t);
      if (look.panels.impacts) r.panels.push_back({name(shot.path), "impact " + std::to_string(i + 1), false, answer});
      else r.panels.push_back({name(shot.path), "t = " + render::frame::timeToMs(t) + " s", t == 0.0 && !answer, answer});
    }
  return r;
}

// the closed forms of a variant, as `rigidreel check` measures them
template <class Results>
void addChecks(const std::string& variant, const Results& results, render::page::SceneRecord& r) {
  for (const auto& c : results)
    r.checks.push_back({variant, c.time, c.quantity, c.expected, c.actual, c.error, c.tolerance, c.earlierRun});
}

}  // namespace

void writeLectureRecord(const render::video::RenderPlan& plan, const render::scene::Scene& base, const std::string& file,
                        const std::string& root, double seconds, const std::function<void(const std::string&)>& wrote) {
  const std::string path = lectureRecordPath(plan.scene, root);
  std::vector<std::string> variants;
  for (const render::video::PlannedVariant& v : plan.variants) variants.push_back(v.scene.model.variant);
  render::page::SceneRecord r =
      recordOf(plan, base.render, render::frame::titleOf(base), base.model.description, variants, file, path, seconds);
  for (const render::video::PlannedVariant& v : plan.variants)
    addChecks(v.scene.model.variant, sim::scene::runExpects(v.scene.model), r);
  render::page::writeSceneRecord(r, path);
  wrote(path);
}

void writeLectureRecord(const render::video::RenderPlan3d& plan, const render::scene3d::Scene& base, const std::string& file,
                        const std::string& root, double seconds, const std::function<void(const std::string&)>& wrote) {
  const std::string path = lectureRecordPath(plan.scene, root);
  std::vector<std::string> variants;
  for (const render::video::PlannedVariant3d& v : plan.variants) variants.push_back(v.scene.model.variant);
  render::page::SceneRecord r = recordOf(plan, base.render, render::frame::titleOf(base.render, base.model.name),
                                         base.model.description, variants, file, path, seconds);
  for (const render::video::PlannedVariant3d& v : plan.variants)
    addChecks(v.scene.model.variant, sim::scene3d::runExpects(v.scene.model), r);
  render::page::writeSceneRecord(r, path);
  wrote(path);
}

bool rebuildLecturePage(const std::string& root) {
  try {
    const size_t scenes = render::page::writePage(root);
    std::cout << "page: " << lecturePagePath(root) << " (" << scenes << (scenes == 1 ? " scene" : " scenes") << ")" << std::endl;
    return true;
  } catch (const std::exception& e) {
    std::cerr << "rigidreel: the page was not written: " << e.what() << '\n';
    return false;
  }
}

}  // namespace render::cli
