// A 3D scene as the renderer sees it: the model the 3D world runs and how to draw it, read from one
// file: the render: keys every scene shares, and the 3D ones.
#pragma once

#include "render/draw/style.h"
#include "render/scene/render_def.h"
#include "render/scene3d/render_def.h"
#include "sim/scene3d/scene_def.h"
#include "sim/yaml3d/scene_yaml.h"

namespace render::scene3d {

struct Scene {
  sim::scene3d::SceneDef model;
  render::scene::RenderDef render;  // the keys 2D and 3D scenes share (the 2D-only ones stay at their defaults)
  Render3dDef space;                // the 3D keys
};

// the model and the look of the 3D scene in `source`; `others` are keys other readers read (the
// analysis' stability:). Throws sim::yaml::SceneError at the fault's FILE:LINE:COL.
Scene readScene(const sim::yaml::SceneSource& source, const sim::yaml::OtherKeys& others = {});

// the style of its frames `frameHeight` pixels high (render::scene::makeStyle)
draw::Style makeStyle(const Scene& scene, int frameHeight);

}  // namespace render::scene3d
