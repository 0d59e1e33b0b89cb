// A pyramid as a scene lists it, row by row from the bottom: the layout that `stability:
// {parameter: pyramid_base}` grows or shrinks to another base (Box2D's pyramid benchmark).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sim/scene/scene_def.h"

namespace render::analysis {

struct PyramidRows {
  int base = 0;                                      // boxes in the bottom row
  sim::core::Vec2 origin = sim::core::Vec2::Zero();  // the bottom row's first box
  sim::core::Vec2 along = sim::core::Vec2::Zero();   // from one box of a row to the next
  sim::core::Vec2 up = sim::core::Vec2::Zero();      // from a row's first box to the next row's first
  std::size_t first = 0;                             // index of the bottom row's first box in the scene
};

// the scene's dynamic bodies read as a pyramid (base n, then n - 1, ... 1 boxes, each row's boxes
// equally spaced and each row shifted alike), or why they are not one
struct PyramidReading {
  std::optional<PyramidRows> rows;
  std::string problem;  // when rows is empty: which body breaks the pattern, and how
};
PyramidReading readPyramid(const std::vector<sim::scene::BodyDef>& bodies);

// the static bodies, then a pyramid of `base` boxes like the bottom row's first, spaced and shifted
// as `rows`, centred where the listed bottom row is, named b<row>_<place> from 1
std::vector<sim::scene::BodyDef> pyramidOfBase(const std::vector<sim::scene::BodyDef>& bodies, const PyramidRows& rows, int base);

}  // namespace render::analysis
