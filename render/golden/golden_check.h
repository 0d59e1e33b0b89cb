// A scene variant checked against its golden record, level by level (design.md's three levels): the
// state (hashes; where they differ, the largest position, angle and velocity error against the
// recorded trace, within the golden: tolerances), the draw list of each frame, and its pixels. A
// failure at one level and not the others says where to look: the physics, what is shown, or the
// rasterizer alone.
#pragma once

#include <string>
#include <vector>

#include "render/draw/image.h"
#include "render/golden/golden_record.h"
#include "render/golden/golden_run.h"

namespace render::golden {

enum class Level { State, DrawList, Pixels };
const char* levelName(Level level);  // "state", "draw_list", "pixels"

// a frame that differs in pixels, for the report
struct FrameDiff {
  std::string name;  // frame-t<T>
  double t = 0.0;
  std::string expectedPng;  // the record's
  render::draw::Image actual, diff;
  std::string message;
};

struct LevelResult {
  Level level = Level::State;
  enum class Status { Ok, Failed, Skipped } status = Status::Ok;
  std::string message;            // what differs and by how much, or why skipped; a note when ok
  std::vector<FrameDiff> frames;  // pixels only
  bool failed() const { return status == Status::Failed; }
};

struct CaseResult {
  std::string name;                 // <scene>[-<variant>]
  std::string file;                 // the scene file
  std::vector<LevelResult> levels;  // state, draw_list, pixels
  std::vector<std::string> warnings;
  bool failed() const;
};

// `run` (made at the record's times) against `record`; with `strict` the pixels are compared even when
// the record's renderer is another one than the run's
CaseResult checkRun(const GoldenRun& run, const GoldenRecord& record, bool strict);

}  // namespace render::golden
