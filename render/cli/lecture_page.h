// The page's side of `rigidreel lecture` (render/page): each job leaves its scene's record beside
// its outputs, DIR/<scene>/page.json (what it rendered, the closed-form checks with the values the
// run measured, how long it took); then the page, DIR/index.html, is rebuilt from every record the
// folder holds, which `--page DIR` does alone.
#pragma once

#include <functional>
#include <string>

#include "render/scene/scene.h"
#include "render/video/render_plan.h"

namespace render::cli {

// DIR/<scene>/page.json, the record a scene's job writes last
std::string lectureRecordPath(const std::string& scene, const std::string& root);
// DIR/index.html
std::string lecturePagePath(const std::string& root);

// writes the record of a job that wrote every output of `plan` in `seconds`: the base scene's title,
// description and `panels:`, each video with its poster and fps, each variant's `expect` entries
// checked; tells `wrote` the record's path
void writeLectureRecord(const render::video::RenderPlan& plan, const render::scene::Scene& base, const std::string& file,
                        const std::string& root, double seconds, const std::function<void(const std::string&)>& wrote);
// the same for a 3D scene's plan
void writeLectureRecord(const render::video::RenderPlan3d& plan, const render::scene3d::Scene& base, const std::string& file,
                        const std::string& root, double seconds, const std::function<void(const std::string&)>& wrote);

// the page rebuilt from the records in `root`: "page: DIR/index.html (N scenes)" on standard
// output, or why not on standard error. Returns whether it was written
bool rebuildLecturePage(const std::string& root);

}  // namespace render::cli
