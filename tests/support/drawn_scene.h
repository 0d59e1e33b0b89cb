// Inline scenes for the renderer's tests, read as the command line reads a file: the model and how
// to draw it (stability:, the analysis' key, is accepted and left alone).
#pragma once

#include <string>

#include "render/scene/scene.h"
#include "sim/yaml/scene_source.h"

namespace drawn_scene {

inline render::scene::Scene load(const std::string& yaml, const std::string& variant = "",
                                 const std::string& file = "inline.yaml") {
  return render::scene::readScene(sim::yaml::sceneSourceText(yaml, file, variant), {{"stability", "golden"}, {}});
}

inline render::scene::Scene loadFile(const std::string& path, const std::string& variant = "") {
  return render::scene::readScene(sim::yaml::readSceneSource(path, variant), {{"stability", "golden"}, {}});
}

// a scene named "lesson" of `duration` s in which a ball (radius 0.25 at the origin, 1 m/s to the
// right) bounces off a static wall at t = 0.5 (the event method, c_r = 1), on lines 1-7; `rest` (a
// render: block, variants) from line 8 on
inline std::string bounce(const std::string& duration, const std::string& rest) {
  return "name: lesson\nduration: " + duration +
         "\nworld: {restitution: 1}\nsim: {collisions: event}\nbodies:\n"
         "  - {name: ball, shape: {circle: 0.25}, position: [0, 0], velocity: [1, 0]}\n"
         "  - {name: wall, shape: {box: [0.2, 2]}, position: [0.85, 0], static: true}\n" +
         rest;
}

}  // namespace drawn_scene
