// A golden record's manifest (record_manifest.cpp): what golden record writes reads back the same,
// and every value of one written by hand is checked at its line and column, before a run could use
// it (a checkpoint of 1e300 ran until killed).
#include "render/golden/record_manifest.h"

#include <doctest/doctest.h>

#include <string>

#include "support/scene_error_check.h"

using namespace render::golden;

namespace {

// a run of two checkpoints and one frame at the second
GoldenRun twoCheckpoints() {
  GoldenRun run;
  run.name = "pend";
  run.renderer = "llvmpipe";
  run.rendererVersion = "4.5";
  run.checkpoints = {{0.5, 1, {}}, {1.0, 2, {}}};
  GoldenFrame frame;
  frame.t = 1.0;
  frame.name = "frame-t1";
  run.frames.push_back(frame);
  return run;
}

const auto load = [](const std::string& text, const std::string& file, const std::string&) {
  return manifestText(text, file, 1.0);
};

// the manifest with `from` replaced by `to`
std::string edited(const std::string& from, const std::string& to) {
  RecordInfo info{"pend.yaml", "abc", {}};
  std::string text = manifestJson(twoCheckpoints(), info);
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("what golden record writes reads back") {
  RecordInfo info{"pend.yaml", "abc", {}};
  info.golden.width = 320;
  info.golden.height = 180;
  const RecordManifest m = manifestText(manifestJson(twoCheckpoints(), info), "manifest.json", 1.0);
  CHECK(m.name == "pend");
  CHECK(m.sceneFile == "pend.yaml");
  CHECK(m.renderer == "llvmpipe");
  CHECK(m.golden.width == 320);
  CHECK(m.golden.height == 180);
  CHECK(m.times.checkpoints == std::vector<double>{0.5, 1.0});
  CHECK(m.times.frames == std::vector<double>{1.0});
  CHECK(m.frameNames == std::vector<std::string>{"frame-t1"});
}

TEST_CASE("values out of their range are refused where they stand") {
  using scene_errors::expectSceneError;
  expectSceneError(load, "manifest.json", edited("\"checkpoints\":[0.5,1]", "\"checkpoints\":[0.5,1e300]"), 1, 0,
                   {"'checkpoints' is 1e+300, outside 0 to 1", "record it again"});
  expectSceneError(load, "manifest.json", edited("\"checkpoints\":[0.5,1]", "\"checkpoints\":[-5,1]"), 1, 0, {"outside 0 to 1"});
  expectSceneError(load, "manifest.json", edited("\"checkpoints\":[0.5,1]", "\"checkpoints\":[1,0.5]"), 1, 0, {"must ascend"});
  expectSceneError(load, "manifest.json", edited("\"size\":[640,360]", "\"size\":[100000,100000]"), 1, 0,
                   {"'size' is 100000, outside 16 to 8192"});
  expectSceneError(load, "manifest.json", edited("\"pixel_tolerance\":24", "\"pixel_tolerance\":2.5"), 1, 0, {"whole number"});
  expectSceneError(load, "manifest.json", edited("\"png\":\"frame-t1.png\"", "\"png\":\"../x.png\""), 1, 0,
                   {"'png' must name a file frame-t"});
  expectSceneError(load, "manifest.json", edited("{\"t\":1,", "{\"t\":0.75,"), 1, 0, {"at none of the checkpoints"});
  expectSceneError(load, "manifest.json", edited("\"renderer\":\"llvmpipe\",", ""), 1, 0, {"'renderer' is missing"});
  expectSceneError(load, "manifest.json", "[1, 2]", 1, 1, {"not a manifest"});
  expectSceneError(load, "manifest.json", "{\"a\": ", 1, 0, {"not a manifest"});
}
