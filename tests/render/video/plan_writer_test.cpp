// The plan written (plan_writer.cpp): exactly the paths the plan lists, in its order, and nothing
// else, so that `lecture --list` is what a lecture job writes by construction; stills in batches
// drawn as a plan of one still draws them. Needs GL (OSMesa) and ffmpeg, as the videos do.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "render/video/plan_writer.h"
#include "support/drawn_scene.h"

namespace fs = std::filesystem;
using render::video::FrameSize;
using render::video::RenderPlan;

namespace {

// a ball that bounces off a wall at t = 0.5, in two variants, with poll panels at the impacts
render::video::LoadVariant lesson() {
  const std::string yaml =
      drawn_scene::bounce("1",
                          "render: {title_card: 0.2, slow_motion: {factor: 2, window: 0.2}, panels: impacts}\n"
                          "variants:\n  slow: {}\n  fast: {bodies: [{name: ball, velocity: [2, 0]}]}\n");
  return [yaml](const std::string& variant) { return drawn_scene::load(yaml, variant, "lesson.yaml"); };
}

// a scratch directory, removed afterwards
struct Scratch {
  fs::path root = fs::temp_directory_path() / ("rigidreel-plan-writer-" + std::to_string(::getpid()));
  Scratch() { fs::remove_all(root); }
  ~Scratch() { fs::remove_all(root); }
};

// every file under `root` (a frames directory as its path and a '/')
std::set<std::string> written(const fs::path& root) {
  std::set<std::string> files;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(root)) {
    if (e.is_directory() && e.path().filename().string().ends_with("-frames")) files.insert(e.path().string() + "/");
    else if (e.is_regular_file() && !e.path().parent_path().filename().string().ends_with("-frames"))
      files.insert(e.path().string());
  }
  return files;
}

std::vector<std::string> write(const RenderPlan& plan) {
  std::vector<std::string> told;
  render::video::writePlan(plan, true, [&](const std::string& path) { told.push_back(path); });
  return told;
}

std::string bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("a lecture job writes exactly the paths its plan lists, in their order") {
  Scratch scratch;
  const RenderPlan plan = render::video::planLecture(
      lesson(), {.root = scratch.root.string(), .file = "lesson.yaml", .size = FrameSize{64, 36}, .fps = 5});
  const std::vector<std::string> paths = plan.paths();
  REQUIRE(paths.size() == 5);  // two videos, two posters, one panel at the first impact
  CHECK(write(plan) == paths);
  CHECK(written(scratch.root) == std::set<std::string>(paths.begin(), paths.end()));
}

TEST_CASE("render with --frames: the frames directory is listed and written last, after its poster") {
  Scratch scratch;
  const RenderPlan plan = render::video::planVideos(
      lesson(), {.root = scratch.root.string(), .variant = "fast", .size = FrameSize{64, 36}, .fps = 5, .frames = true});
  const std::vector<std::string> paths = plan.paths();
  REQUIRE(paths.size() == 3);
  CHECK(paths[2].ends_with("lesson-fast-frames/"));
  CHECK(write(plan) == paths);
  CHECK(written(scratch.root) == std::set<std::string>(paths.begin(), paths.end()));
  long frames = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(paths[2])) frames += e.is_regular_file();
  CHECK(frames == plan.videos.front().frameCount);
}

TEST_CASE("stills beyond one batch are the pictures a plan of each alone draws, byte for byte") {
  Scratch scratch;
  // more shots than one run of each variant draws at a time (16), out of order
  std::vector<double> times;
  for (int i = 20; i >= 0; --i) times.push_back(0.05 * i);
  const RenderPlan plan = render::video::planStills(lesson(), {.root = (scratch.root / "all").string(),
                                                               .file = "lesson.yaml",
                                                               .times = times,
                                                               .panels = true,
                                                               .size = FrameSize{64, 36}});
  CHECK(write(plan) == plan.paths());
  for (size_t shot : {size_t{0}, size_t{3}, size_t{17}, size_t{20}}) {
    CAPTURE(times[shot]);
    const RenderPlan alone = render::video::planStills(lesson(), {.root = (scratch.root / "alone").string(),
                                                                  .file = "lesson.yaml",
                                                                  .times = {times[shot]},
                                                                  .panels = true,
                                                                  .size = FrameSize{64, 36}});
    REQUIRE(write(alone).size() == 1);
    CHECK(bytes(alone.paths().front()) == bytes(plan.paths()[shot]));
  }
}
