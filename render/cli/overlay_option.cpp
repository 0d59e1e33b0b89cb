#include "render/cli/overlay_option.h"

#include <filesystem>
#include <memory>

#include "render/trace/trace_csv.h"

namespace render::cli {

render::video::LoadVariant withOverlay(render::video::LoadVariant load, const std::string& path) {
  if (path.empty()) return load;
  return [load = std::move(load), path](const std::string& variant) {
    render::scene::Scene scene = load(variant);
    const auto trace = std::make_shared<const render::trace::Trace>(render::trace::readTrace(path, scene.model));
    auto overlay = std::make_shared<render::scene::TraceOverlayDef>();
    overlay->name = std::filesystem::path(path).filename().string();
    overlay->poseAt = [trace](size_t body, double t, render::scene::TraceOverlayDef::Pose& pose) {
      render::trace::TraceSample s;
      if (body >= trace->bodies.size() || !render::trace::sampleAt(trace->bodies[body], t, s)) return false;
      pose = {{s.x, s.y}, s.angle};
      return true;
    };
    scene.render.overlay = std::move(overlay);
    return scene;
  };
}

}  // namespace render::cli
