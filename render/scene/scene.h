// A scene as the renderer sees it: the model the simulator runs and how to draw it, both read from
// one file (MuJoCo's model beside its visual options).
#pragma once

#include "render/scene/render_def.h"
#include "sim/scene/scene_def.h"
#include "sim/yaml/scene_yaml.h"

namespace render::scene {

struct Scene {
  sim::scene::SceneDef model;
  RenderDef render;
  std::string file;  // the file it was read from, for messages
};

// the model and the look of the scene in `source`; `others` are keys of the file that other readers
// read (the analysis' stability:). Throws sim::yaml::SceneError at the fault's FILE:LINE:COL.
Scene readScene(const sim::yaml::SceneSource& source, const sim::yaml::OtherKeys& others = {});

}  // namespace render::scene
