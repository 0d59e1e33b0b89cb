#include "render/video/still_draw_lists.h"

#include "render/frame/panels.h"
#include "render/frame/scene_run.h"
#include "render/scene/scene_style.h"

namespace render::video {
using render::frame::PixelDrawList;
using render::frame::SceneRun;
using namespace render::draw;
using namespace render::frame;

PixelDrawList frameDrawList(const Stills& stills, size_t variant, const DrawList& list, TextRenderer& text) {
  const render::scene::Scene& scene = stills.scenes[variant];
  const Style style = render::scene::makeStyle(scene, stills.camera.heightPx());
  const int size = style.fontSize;
  return pixelDrawList(
      list, style, stills.camera, [&text, size](const std::string& s) { return text.measure(s, size).width; }, size);
}

PixelDrawList stillDrawList(const Stills& stills, const StillOutput& shot, const std::vector<PixelDrawList>& frames,
                            TextRenderer& text) {
  if (!stills.panels) return frames.front();
  const render::scene::Scene& first = stills.scenes.front();
  return sheetDrawList(frames, stills.grid, shot.titles, stills.caption, render::scene::makeStyle(first, first.render.height),
                       text);
}

void stillDrawLists(const Stills& stills, const std::function<void(size_t, const PixelDrawList&)>& shot) {
  TextRenderer text;
  std::vector<std::vector<PixelDrawList>> frames(stills.shots.size(), std::vector<PixelDrawList>(stills.scenes.size()));
  for (size_t i = 0; i < stills.scenes.size(); ++i) {
    std::vector<double> instants;
    for (const StillOutput& s : stills.shots) instants.push_back(s.instants[i]);
    SceneRun run(stills.scenes[i], stills.camera, stills.surveys[i], nullptr, &text);
    run.drawListsAt(instants, stills.strobe,
                    [&](size_t k, DrawList list) { frames[k][i] = frameDrawList(stills, i, list, text); });
  }
  for (size_t k = 0; k < stills.shots.size(); ++k) shot(k, stillDrawList(stills, stills.shots[k], frames[k], text));
}

}  // namespace render::video
