#include "render/cli/lecture_page.h"

#include <filesystem>
#include <iostream>

#include "render/cli/output.h"
#include "render/frame/caption.h"
#include "render/page/page.h"
#include "render/video/output_names.h"
#include "sim/scene/expect.h"

namespace render::cli {

namespace fs = std::filesystem;

std::string lectureRecordPath(const std::string& scene, const std::string& root) {
  return (fs::path(root) / scene / render::page::kRecordName).string();
}

std::string lecturePagePath(const std::string& root) { return (fs::path(root) / render::page::kPageName).string(); }

void writeLectureRecord(const render::video::RenderPlan& plan, const render::scene::Scene& base, const std::string& file,
                        const std::string& root, double seconds, const std::function<void(const std::string&)>& wrote) {
  render::page::SceneRecord r;
  r.scene = plan.scene;
  r.file = file;
  r.title = render::frame::titleOf(base);
  r.description = base.model.description;
  r.seconds = seconds;
  const std::string path = lectureRecordPath(plan.scene, root);
  // the files as the plan names them, relative to the record's folder (a variant may rename its own)
  const auto name = [&](const std::string& p) { return fs::path(p).lexically_relative(fs::path(path).parent_path()).string(); };
  for (const render::video::VideoOutput& v : plan.videos)
    r.videos.push_back({plan.variants[v.variant].scene.model.variant, name(v.path), name(v.posterPath), v.fps});
  // a panel at t = 0 shows the poll's question (nothing has happened yet); any later one, its answer
  if (plan.stills)
    for (size_t i = 0; i < plan.stills->shots.size(); ++i) {
      const render::video::StillOutput& shot = plan.stills->shots[i];
      if (base.render.panels.impacts)
        r.panels.push_back({name(shot.path), "impact " + std::to_string(i + 1), false});
      else
        r.panels.push_back({name(shot.path), "t = " + render::video::timeForName(shot.instants.at(0)) + " s", shot.instants.at(0) == 0.0});
    }
  // the closed forms of every variant, as `rigidreel check` measures them
  for (const render::video::PlannedVariant& v : plan.variants)
    for (const sim::scene::CheckResult& c : sim::scene::runExpects(v.scene.model))
      r.checks.push_back({v.scene.model.variant, c.time, c.quantity, c.expected, c.actual, c.error, c.tolerance});
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
