#include "render/cli/lecture_page.h"

#include <filesystem>
#include <iostream>

#include "render/cli/output.h"
#include "render/frame/caption.h"
#include "render/page/page.h"
#include "sim/scene/expect.h"

namespace render::cli {

namespace fs = std::filesystem;

std::string lectureRecordPath(const LecturePlan& plan, const std::string& root) {
  return (fs::path(root) / plan.base.model.name / render::page::kRecordName).string();
}

std::string lecturePagePath(const std::string& root) { return (fs::path(root) / render::page::kPageName).string(); }

void writeLectureRecord(const LecturePlan& plan, const LectureOptions& o, double seconds, const Wrote& wrote) {
  render::page::SceneRecord r;
  r.scene = plan.base.model.name;
  r.file = plan.file;
  r.title = render::frame::titleOf(plan.base);
  r.description = plan.base.model.description;
  r.seconds = seconds;
  // the files as lectureOutputs names them: each video and its poster, then each panel
  const std::vector<std::string> paths = lectureOutputs(plan, o.output);
  const auto name = [&](size_t i) { return fs::path(paths[i]).filename().string(); };
  size_t next = 0;
  for (const render::scene::Scene& def : plan.videos) {
    r.videos.push_back({def.model.variant, name(next), name(next + 1), o.fps.value_or(def.render.fps)});
    next += 2;
  }
  // a panel at t = 0 shows the poll's question (nothing has happened yet); any later one, its answer
  const render::scene::PanelsDef& panels = plan.base.render.panels;
  for (double t : panels.times) r.panels.push_back({name(next++), "t = " + timeForName(t) + " s", t == 0.0});
  if (panels.impacts)
    for (size_t i = 1; i <= plan.mostImpacts; ++i) r.panels.push_back({name(next++), "impact " + std::to_string(i), false});
  // the closed forms of every variant, as `rigidreel check` measures them
  for (const render::scene::Scene& def : plan.videos)
    for (const sim::scene::CheckResult& c : sim::scene::runExpects(def.model))
      r.checks.push_back({def.model.variant, c.time, c.quantity, c.expected, c.actual, c.error, c.tolerance});
  const std::string path = lectureRecordPath(plan, o.output);
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
