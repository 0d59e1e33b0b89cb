// Loading an inline scene's render: block in the tests of its readers (render/scene/render_yaml.cpp and
// render_timing_yaml.cpp): the block read, or its SceneError checked for line and words.
#pragma once

#include <doctest/doctest.h>

#include <string>

#include "support/drawn_scene.h"

namespace render_block {

// one body on lines 1-2; the render: block starts on line 3
inline const std::string kBody = "bodies:\n  - {name: a, shape: {circle: 1}}\n";

inline render::scene::RenderDef renderOf(const std::string& block) { return drawn_scene::load(kBody + block).render; }

// loading the block must fail at `line` with a message containing `words`
inline void expectError(const std::string& block, int line, const std::string& words) {
  INFO("render block:\n", block);
  try {
    (void)renderOf(block);
    FAIL_CHECK("the scene loaded; expected a SceneError");
  } catch (const sim::yaml::SceneError& e) {
    INFO("what(): ", e.what());
    CHECK(e.line == line);
    CHECK(e.message.find(words) != std::string::npos);
  }
}

}  // namespace render_block
