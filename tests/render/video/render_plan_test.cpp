// The render plan as a pure function (render_plan.cpp): what `render`, `snapshot` and `lecture`
// will write, and how, decided from the scenes and the request alone: the paths, the instants (--at
// times, each variant's impacts, the panels' default), one camera for all panels, the time map with
// a title card and slow motion, each variant surveyed once, and the errors with their messages.
#include <doctest/doctest.h>

#include <map>

#include "render/frame/caption.h"
#include "render/frame/quantity_text.h"
#include "render/frame/scene_run.h"
#include "render/jobs/exit_status.h"
#include "render/scene/scene_style.h"
#include "render/video/output_names.h"
#include "render/video/render_plan.h"
#include "render/scene3d/scene.h"
#include "sim/scene/scene_build.h"
#include "sim/yaml/scene_error.h"
#include "sim/yaml/scene_source.h"
#include "support/drawn_scene.h"

using namespace render::video;

namespace {

const std::string kPoll = std::string(RIGIDREEL_SOURCE_DIR) + "/scenes/poll_bar_impulse.yaml";        // center, end
const std::string kThree = std::string(RIGIDREEL_SOURCE_DIR) + "/scenes/three_collisions_poll.yaml";  // A, B, C

// a file's variants as the command line reads them, counting the reads
struct Loader {
  std::string file;
  std::map<std::string, int> reads;
  render::video::LoadVariant operator()() {
    return [this](const std::string& variant) {
      ++reads[variant];
      return drawn_scene::loadFile(file, variant);
    };
  }
};

// a ball that hits a wall at t = 0.5, and a variant that runs half as long
const std::string kLesson =
    drawn_scene::bounce("2",
                        "render: {title_card: 1, slow_motion: {factor: 4, window: 0.2}, size: [320, 180]}\n"
                        "variants:\n  long: {}\n  brief: {duration: 1}\n");

render::video::LoadVariant lesson(const std::string& yaml = kLesson) {
  return [yaml](const std::string& variant) { return drawn_scene::load(yaml, variant, "lesson.yaml"); };
}

// a 3D box spun about two of its axes, at 4 and 2 rad/s, 1 s and 0.5 s long, with poll panels at 0.25 s
const char* const kSpin = R"(name: spin
dimensions: 3
duration: 1
sim: {integrator: splitting, dt: 0.01}
bodies:
  - {name: box, shape: {box: [0.1, 0.4, 0.8]}, angular_velocity: [0, 0, 4]}
render: {size: [160, 90], panels: [0.25]}
variants:
  fast: {}
  slow: {duration: 0.5, bodies: [{name: box, angular_velocity: [0, 2, 0]}]}
)";

render::video::LoadVariant3d spin(std::map<std::string, int>* reads = nullptr) {
  return [reads](const std::string& variant) {
    if (reads) ++(*reads)[variant];
    return render::scene3d::readScene(sim::yaml::sceneSourceText(kSpin, "spin.yaml", variant));
  };
}

std::string usageError(const std::function<void()>& plan) {
  try {
    plan();
  } catch (const render::jobs::UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("render: each variant's video and poster, named under <root>/<scene>/") {
  Loader poll{kPoll, {}};
  const RenderPlan plan = render::video::planVideos(poll(), {.root = "o", .allVariants = true});
  CHECK(plan.paths() == std::vector<std::string>{
                            "o/poll_bar_impulse/poll_bar_impulse-center.mp4", "o/poll_bar_impulse/poll_bar_impulse-center.png",
                            "o/poll_bar_impulse/poll_bar_impulse-end.mp4", "o/poll_bar_impulse/poll_bar_impulse-end.png"});
  // the base scene for the names of its variants, then each variant once
  CHECK(poll.reads == std::map<std::string, int>{{"", 1}, {"center", 1}, {"end", 1}});

  Loader one{kPoll, {}};
  const RenderPlan webm = render::video::planVideos(
      one(),
      {.variant = "end", .size = FrameSize{160, 90}, .fps = 5, .format = render::video::VideoFormat::Webm, .frames = true});
  CHECK(webm.paths() == std::vector<std::string>{"out/poll_bar_impulse/poll_bar_impulse-end.webm",
                                                 "out/poll_bar_impulse/poll_bar_impulse-end.png",
                                                 "out/poll_bar_impulse/poll_bar_impulse-end-frames/"});
  CHECK(one.reads == std::map<std::string, int>{{"end", 1}});
  const render::video::VideoOutput& video = webm.videos.front();
  CHECK(video.width == 160);
  CHECK(video.height == 90);
  CHECK(video.fps == 5.0);
  CHECK(video.frameCount == 10);  // 2 s at 5 fps
  CHECK(video.duration == 2.0);
}

TEST_CASE("render: the time map with the title card and slow motion around each variant's own impacts") {
  const RenderPlan plan = render::video::planVideos(lesson(), {.allVariants = true, .fps = 10, .duration = {}});
  REQUIRE(plan.videos.size() == 2);
  for (const render::video::VideoOutput& video : plan.videos) {
    const render::video::PlannedVariant& v = plan.variants[video.variant];
    CAPTURE(v.scene.model.variant);
    // the ball's surface meets the wall's at x = 0.5: one impact at t = 0.5, slowed 4 times over 0.2 s
    REQUIRE(v.survey.impactTimes.size() == 1);
    CHECK(v.survey.impactTimes[0] == doctest::Approx(0.5));
    CHECK(video.timeMap.windows().size() == 1);
    CHECK(video.timeMap.videoLength() == doctest::Approx(1.0 + v.scene.model.duration + 3 * 0.2));
    CHECK(video.frameCount == video.timeMap.frameCount(10.0));
    CHECK(video.timeMap.inTitleCard(0.5));
    CHECK(video.timeMap.simTime(1.25) == doctest::Approx(0.25));
    CHECK(video.timeMap.factorAt(0.5) == 4.0);
    // the poster at the end of the run, in simulation time (the scene asks no question)
    CHECK(video.duration == v.scene.model.duration);
    CHECK(video.posterTime == video.duration);
  }
  // --duration sets every video's run, and the survey's
  const RenderPlan shorter = render::video::planVideos(lesson(), {.variant = "long", .duration = 0.3});
  CHECK(shorter.videos.front().duration == 0.3);
  CHECK(shorter.variants.front().survey.impactTimes.empty());
  CHECK(shorter.videos.front().timeMap.videoLength() == doctest::Approx(1.3));
}

namespace {

// the steps a video's run takes for its frames and poster, drawn as the recorder draws them (draw
// lists: the same states, without GL)
long drawingSteps(const RenderPlan& plan, const render::video::VideoOutput& video) {
  const render::video::PlannedVariant& v = plan.variants[video.variant];
  render::frame::SceneRun run(v.scene, video.camera, v.survey);
  run.endAt(video.duration);
  for (long k = 0; k < video.frameCount; ++k) {
    const double u = static_cast<double>(k) / video.fps;
    if (!video.timeMap.inTitleCard(u) && !video.timeMap.inAnswerCard(u)) run.drawListAt(video.timeMap.simTime(u));
  }
  run.drawListAt(video.posterTime);
  return run.stepsTaken();
}

// the steps `simulate` takes over the scene
long simulateSteps(const render::video::PlannedVariant& v) {
  sim::world::World world = sim::scene::buildWorld(v.scene.model);
  world.advanceTo(v.scene.model.duration);
  return world.steps;
}

}  // namespace

TEST_CASE("render: the scene is stepped once, by its survey; the frames and the poster go on from its states") {
  const RenderPlan plan =
      render::video::planVideos(lesson(drawn_scene::bounce("2", "render: {title_card: 1, size: [320, 180]}\n")), {.fps = 10});
  REQUIRE(plan.videos.size() == 1);
  const render::video::PlannedVariant& v = plan.variants.front();
  CHECK(v.survey.steps == simulateSteps(v));
  CHECK(v.survey.steps == 2000);
  REQUIRE(v.survey.kept);
  CHECK(v.survey.kept->states.size() == 20);  // 0.1, …, 2 s: the run starts at 0 anyway
  CHECK(drawingSteps(plan, plan.videos.front()) == 0);
  // slow motion around the impact: the frames inside its window (not known before the survey) step
  // from the kept state before them, the rest take no step
  const RenderPlan slowed = render::video::planVideos(lesson(), {.variant = "long", .fps = 10});
  const long steps = drawingSteps(slowed, slowed.videos.front());
  CHECK(steps > 0);
  CHECK(steps <= 200);  // at most the window's 0.2 s, at 1 ms steps
}

TEST_CASE("render: a poll's posters show the start, not the outcome the question asks about") {
  const std::string poll = kLesson + "question: Which way does the ball go after the wall?\n";
  const RenderPlan plan = render::video::planVideos(lesson(poll), {.variant = "long"});
  REQUIRE(plan.videos.size() == 1);
  CHECK(plan.videos.front().duration == 2.0);
  CHECK(plan.videos.front().posterTime == 0.0);
}

TEST_CASE("render: the camera is fitted over the variant's one survey, the poster's too") {
  const RenderPlan plan = render::video::planVideos(lesson(), {.variant = "brief"});
  const render::video::PlannedVariant& v = plan.variants.front();
  const render::frame::RunSurvey again = render::frame::surveyRun(v.scene);
  CHECK(v.survey.bounds.min == again.bounds.min);
  CHECK(v.survey.bounds.max == again.bounds.max);
  CHECK(v.survey.impactTimes == again.impactTimes);
  const render::draw::Camera camera = render::frame::cameraFor(v.scene, again);
  CHECK(plan.videos.front().camera.center() == camera.center());
  CHECK(plan.videos.front().camera.worldHeight() == camera.worldHeight());
}

TEST_CASE("snapshot: the same --at times for every variant, named by time and strobe") {
  Loader poll{kPoll, {}};
  const RenderPlan plan = render::video::planStills(
      poll(), {.file = kPoll, .variant = "end", .times = {0.5, 2}, .strobe = 4, .size = FrameSize{160, 90}});
  REQUIRE(plan.stills);
  CHECK(plan.paths() == std::vector<std::string>{"out/poll_bar_impulse/poll_bar_impulse-end-t0.5-strobe4.png",
                                                 "out/poll_bar_impulse/poll_bar_impulse-end-t2-strobe4.png"});
  CHECK(plan.stills->shots[0].instants == std::vector<double>{0.5});
  CHECK(plan.stills->shots[0].titles.empty());
  CHECK(plan.stills->strobe == 4);
  CHECK(plan.stills->width == 160);
  CHECK(plan.videos.empty());

  const RenderPlan panels = render::video::planStills(poll(), {.file = kPoll, .times = {1.5}, .panels = true});
  CHECK(panels.paths() == std::vector<std::string>{"out/poll_bar_impulse/poll_bar_impulse-panels-t1.5.png"});
  CHECK(panels.stills->shots[0].instants == std::vector<double>{1.5, 1.5});
  CHECK(panels.stills->shots[0].titles == std::vector<std::string>{"A: center", "B: end"});
}

TEST_CASE("snapshot --impacts: shot i is each variant at its own i-th impact, or its last") {
  const RenderPlan plan = render::video::planStills(Loader{kThree, {}}(), {.file = kThree, .impacts = true, .panels = true});
  REQUIRE(plan.stills);
  const std::vector<render::video::StillOutput>& shots = plan.stills->shots;
  size_t most = 0;
  for (const render::video::PlannedVariant& v : plan.variants) most = std::max(most, v.survey.impactTimes.size());
  REQUIRE(shots.size() == most);
  for (size_t shot = 0; shot < shots.size(); ++shot) {
    CHECK(shots[shot].path ==
          "out/three_collisions_poll/three_collisions_poll-panels-impact" + std::to_string(shot + 1) + ".png");
    for (size_t i = 0; i < plan.variants.size(); ++i) {
      const std::vector<double>& impacts = plan.variants[i].survey.impactTimes;
      CHECK(shots[shot].instants[i] == impacts[std::min(shot, impacts.size() - 1)]);
    }
  }
  // "A" needs no name after its letter; the time of the impact follows
  CHECK(shots[0].titles[0] == "A  (t = " + render::frame::timeToMs(shots[0].instants[0]) + " s)");

  const RenderPlan one = render::video::planStills(Loader{kThree, {}}(), {.file = kThree, .variant = "B", .impacts = true});
  const double t = one.variants.front().survey.impactTimes.front();
  CHECK(one.paths().front() ==
        "out/three_collisions_poll/three_collisions_poll-B-impact1-t" + render::video::timeForName(t) + ".png");
}

TEST_CASE("panels share one camera, fitted over every variant's run, and one scale for arrows and bars") {
  const RenderPlan plan = render::video::planStills(Loader{kThree, {}}(), {.file = kThree, .times = {2}, .panels = true});
  const render::video::Stills& stills = *plan.stills;
  const render::draw::Bounds view = stills.camera.view();
  double fastest = 0.0;
  for (const render::video::PlannedVariant& v : plan.variants) {
    CAPTURE(v.scene.model.variant);
    CHECK(view.min.x() <= v.survey.bounds.min.x());
    CHECK(view.min.y() <= v.survey.bounds.min.y());
    CHECK(view.max.x() >= v.survey.bounds.max.x());
    CHECK(view.max.y() >= v.survey.bounds.max.y());
    fastest = std::max(fastest, v.survey.maxSpeed);
  }
  for (const render::frame::RunSurvey& s : stills.surveys) CHECK(s.maxSpeed == fastest);
  // a variant's own still keeps its own scales
  const RenderPlan alone = render::video::planStills(Loader{kThree, {}}(), {.file = kThree, .variant = "B", .times = {2}});
  CHECK(alone.stills->surveys.front().maxSpeed == alone.variants.front().survey.maxSpeed);
}

TEST_CASE("snapshot errors, with the messages the command has always given") {
  CHECK(usageError([] {
          render::video::planStills(Loader{kPoll, {}}(), {.file = kPoll, .variant = "end", .times = {0.5, 7}});
        }) == "--at: 7 s is outside the scene's duration [0, 2]");
  CHECK(usageError([] {
          render::video::planStills(Loader{kPoll, {}}(), {.file = kPoll, .times = {-1}, .panels = true});
        }) == "--at: -1 s is outside the scene's duration [0, 2]");
  CHECK(usageError([] {
          render::video::planStills(Loader{kPoll, {}}(), {.file = kPoll, .variant = "end", .impacts = true});
        }) ==
        "--impacts: " + kPoll + " (variant end) has no impacts in its 2 s; nothing collides there (use --at to choose times)");
  // a time after the brief variant's end: every variant must reach it
  CHECK(usageError([] { render::video::planStills(lesson(), {.file = "lesson.yaml", .times = {1.5}, .panels = true}); }) ==
        "--at: 1.5 s is outside the scene's duration [0, 1]");
  const char* const single = "name: single\nbodies:\n  - {name: box, shape: {box: [1, 1]}}\n";
  CHECK(usageError([&] {
          render::video::planStills([&](const std::string& v) { return drawn_scene::load(single, v, "single.yaml"); },
                                    {.file = "single.yaml", .times = {0.5}, .panels = true});
        }) == "--panels: single.yaml has no variants to put side by side");
}

TEST_CASE("lecture: every variant's video and poster, then the panels, each variant read and surveyed once") {
  Loader three{kThree, {}};
  const RenderPlan plan =
      render::video::planLecture(three(), {.root = "pack", .file = kThree, .size = FrameSize{160, 90}, .fps = 10});
  CHECK(three.reads == std::map<std::string, int>{{"", 1}, {"A", 1}, {"B", 1}, {"C", 1}});
  CHECK(plan.scene == "three_collisions_poll");
  const std::vector<std::string> paths = plan.paths();
  REQUIRE(paths.size() == 7);  // three videos and posters, and the default panel at the duration
  CHECK(paths[0] == "pack/three_collisions_poll/three_collisions_poll-A.mp4");
  CHECK(paths[5] == "pack/three_collisions_poll/three_collisions_poll-C.png");
  CHECK(paths[6] == "pack/three_collisions_poll/three_collisions_poll-panels-t2.png");
  // the panels are drawn from the videos' surveys (at shared scales), not from runs of their own
  for (size_t i = 0; i < plan.variants.size(); ++i) {
    CHECK(plan.stills->surveys[i].impactTimes == plan.variants[i].survey.impactTimes);
    CHECK(plan.stills->surveys[i].bounds.max == plan.variants[i].survey.bounds.max);
  }
  CHECK(plan.videos.front().fps == 10.0);
  // --size sets the panel sheet too: three panels as 2 × 2 on 160 × 90
  CHECK(plan.stills->grid.sheetWidth == 160);
  CHECK(plan.stills->grid.sheetHeight == 90);
  CHECK(plan.stills->width == plan.stills->grid.frameWidth);
  CHECK(plan.stills->width < 80);
}

TEST_CASE("a three-variant panel sheet is 1920 × 1080 by default, 2 × 2, and every arrow lies inside its panel") {
  // the lecture's poll: velocity arrows, impact normals and impulses, a caption
  const std::string lecture = std::string(RIGIDREEL_SOURCE_DIR) + "/scenes/lecture/08_three_collisions_poll.yaml";
  const RenderPlan plan =
      render::video::planStills(Loader{lecture, {}}(), {.file = lecture, .times = {0, 0.8, 2}, .panels = true});
  const render::video::Stills& stills = *plan.stills;
  CHECK(stills.grid.sheetWidth == 1920);
  CHECK(stills.grid.sheetHeight == 1080);
  CHECK(stills.grid.columns == 2);
  CHECK(stills.grid.rows == 2);
  // text a 40th of the sheet at least, in the panels' frames and their titles
  CHECK(stills.grid.textSize >= 27);
  REQUIRE(stills.scenes.size() == 3);
  for (const render::scene::Scene& s : stills.scenes) {
    CHECK(s.render.width == stills.grid.frameWidth);
    CHECK(s.render.height == stills.grid.frameHeight);
    CHECK(render::scene::fontSizeFor(s.render, s.render.height) >= 27);
    CHECK(render::scene::lineWidthFor(s.render, s.render.height) == 3.0);
    // the caption once under the grid, not in each panel
    CHECK(render::frame::captionOf(s).empty());
  }
  CHECK(stills.caption == "Which block moves fastest, and which spins fastest?");
  // every arrow each panel draws at each shot inside the panel's frame: velocities, normals, impulses
  const render::draw::Bounds view = stills.camera.view();
  size_t arrows = 0;
  for (size_t v = 0; v < stills.scenes.size(); ++v) {
    std::vector<double> instants;
    for (const render::video::StillOutput& shot : stills.shots) instants.push_back(shot.instants[v]);
    render::frame::SceneRun run(stills.scenes[v], stills.camera, stills.surveys[v]);
    run.drawListsAt(instants, 0, [&](size_t shot, render::draw::DrawList list) {
      for (const render::draw::DrawList::Call& c : list.calls()) {
        if (c.kind != render::draw::DrawList::Kind::Arrow) continue;
        ++arrows;
        for (const sim::core::Vec2& p : c.points) {
          CAPTURE(v);
          CAPTURE(shot);
          CHECK(p.x() >= view.min.x());
          CHECK(p.x() <= view.max.x());
          CHECK(p.y() >= view.min.y());
          CHECK(p.y() <= view.max.y());
        }
      }
    });
  }
  CHECK(arrows >= 6);  // the velocity arrows at least, in each panel at each time after the start
}

TEST_CASE("panel titles: a variant's own render: {title}, else its key; never the answer") {
  const std::string yaml = drawn_scene::bounce("1",
                                               "answer: It bounces back.\nrender: {title: Lesson}\n"
                                               "variants:\n  slow: {render: {title: Slowly}}\n  fast: {}\n");
  const auto load = [&](const std::string& v) { return drawn_scene::load(yaml, v, "lesson.yaml"); };
  const RenderPlan plan = render::video::planStills(load, {.file = "lesson.yaml", .times = {0.5}, .panels = true});
  CHECK(plan.stills->shots[0].titles == std::vector<std::string>{"A: Slowly", "B: fast"});
}

TEST_CASE("panel titles: a variant's own title: first, never lettered twice; an impact's time to the millisecond") {
  const std::string yaml =
      drawn_scene::bounce("1",
                          "render: {title: Lesson}\n"
                          "variants:\n  slow: {title: \"A: slowly\", render: {title: Slowly}}\n"
                          "  fast: {title: \"fast, c_r = 1\", bodies: [{name: ball, velocity: [1.2345678, 0]}]}\n  C: {}\n");
  const auto load = [&](const std::string& v) { return drawn_scene::load(yaml, v, "lesson.yaml"); };
  const RenderPlan plan = render::video::planStills(load, {.file = "lesson.yaml", .times = {0.5}, .panels = true});
  CHECK(plan.stills->shots[0].titles == std::vector<std::string>{"A: slowly", "B: fast, c_r = 1", "C"});
  const RenderPlan impacts = render::video::planStills(load, {.file = "lesson.yaml", .impacts = true, .panels = true});
  // the fast ball meets the wall at (0.75 − 0.25) / 1.2345678 = 0.405000… s
  CHECK(impacts.stills->shots[0].titles[1] == "B: fast, c_r = 1  (t = 0.405 s)");
  CHECK(render::frame::timeToMs(0.5) == "0.5");
  CHECK(render::frame::timeToMs(0.7650771) == "0.765");
  CHECK(render::frame::timeToMs(-0.0001) == "0");
  CHECK(render::frame::timeToMs(2.0) == "2");
}

TEST_CASE("a sheet's grid shows the variants largest: a wide run stacked, a tall one side by side") {
  const auto sheet = [](const std::string& velocity) {
    const std::string yaml = "name: run\nduration: 1\nbodies:\n  - {name: ball, shape: {circle: 0.25}, velocity: " + velocity +
                             "}\nvariants:\n  a: {}\n  b: {}\n  c: {}\n";
    const auto load = [yaml](const std::string& v) { return drawn_scene::load(yaml, v, "run.yaml"); };
    return render::video::planStills(load, {.file = "run.yaml", .times = {0.5}, .panels = true}).stills->grid;
  };
  // a ball flying 20 m to the right: three panels one above the other, not 2 × 2
  CHECK(sheet("[20, 0]").columns == 1);
  CHECK(sheet("[20, 0]").rows == 3);
  // a ball falling 20 m: three side by side
  CHECK(sheet("[0, -20]").columns == 3);
  // a run half again as wide as tall keeps the usual 2 × 2
  CHECK(sheet("[3, 2]").columns == 2);
}

TEST_CASE("lecture panels: the default at the shortest variant's duration; impacts where every variant has one") {
  const RenderPlan plan = render::video::planLecture(lesson(), {.file = "lesson.yaml"});
  CHECK(plan.paths().back() == "out/lecture/lesson/lesson-panels-t1.png");
  CHECK(plan.stills->shots.front().instants == std::vector<double>{1, 1});

  // the base scene's panels: impacts, each variant with its impact at 0.5 s
  const RenderPlan impacts = render::video::planLecture(
      lesson(drawn_scene::bounce("2", "render: {panels: impacts}\nvariants:\n  long: {}\n  brief: {duration: 1}\n")),
      {.file = "lesson.yaml"});
  CHECK(impacts.paths().back() == "out/lecture/lesson/lesson-panels-impact1.png");

  // a variant that ends before its impact has none: refused at the panels line, before rendering
  try {
    render::video::planLecture(
        lesson(drawn_scene::bounce("2", "render: {panels: impacts}\nvariants:\n  long: {}\n  brief: {duration: 0.3}\n")),
        {.file = "lesson.yaml"});
    FAIL("no error");
  } catch (const sim::yaml::SceneError& e) {
    CHECK(e.line == 8);
    CHECK(e.message ==
          "'panels: impacts' needs an impact in every variant, and variant 'brief' has none; give panel times instead, e.g. [0, "
          "0.3]");
  }
}

TEST_CASE("3D scenes are planned as 2D ones: the same names, one survey per variant, panels at the shortest duration") {
  std::map<std::string, int> reads;
  const render::video::RenderPlan3d plan =
      render::video::planLecture3d(spin(&reads), {.root = "pack", .file = "spin.yaml", .fps = 10});
  CHECK(reads == std::map<std::string, int>{{"", 1}, {"fast", 1}, {"slow", 1}});
  CHECK(plan.paths() == std::vector<std::string>{"pack/spin/spin-fast.mp4", "pack/spin/spin-fast.png", "pack/spin/spin-slow.mp4",
                                                 "pack/spin/spin-slow.png", "pack/spin/spin-panels-t0.25.png"});
  // each video over its own variant's duration at 10 fps, no title card: 10 and 5 frames
  CHECK(plan.videos[0].frameCount == 10);
  CHECK(plan.videos[1].frameCount == 5);
  CHECK(plan.videos[1].duration == 0.5);
  // the panels: both variants at 0.25 s, titled by letter and name, with their scales shared
  REQUIRE(plan.stills);
  CHECK(plan.stills->shots.front().instants == std::vector<double>{0.25, 0.25});
  CHECK(plan.stills->shots.front().titles == std::vector<std::string>{"A: fast", "B: slow"});
  CHECK(plan.variants[1].survey.maxOmega == doctest::Approx(2.0));
  CHECK(plan.stills->surveys[1].maxOmega == doctest::Approx(4.0));

  // a snapshot of one variant at two times, and what 3D refuses
  const render::video::RenderPlan3d shots =
      render::video::planStills3d(spin(), {.root = "o", .file = "spin.yaml", .variant = "slow", .times = {0, 0.5}});
  CHECK(shots.paths() == std::vector<std::string>{"o/spin/spin-slow-t0.png", "o/spin/spin-slow-t0.5.png"});
  CHECK(usageError([] { render::video::planStills3d(spin(), {.file = "spin.yaml", .variant = "slow", .times = {0.75}}); }) ==
        "--at: 0.75 s is outside the scene's duration [0, 0.5]");
  // a free spinning body meets nothing: no impacts to show
  CHECK(usageError([] { render::video::planStills3d(spin(), {.file = "spin.yaml", .variant = "slow", .impacts = true}); }) ==
        "--impacts: spin.yaml (variant slow) has no impacts in its 0.5 s; nothing collides there (use --at to choose times)");
  CHECK(usageError([] { render::video::planStills3d(spin(), {.file = "spin.yaml", .times = {0}, .strobe = 2}); }) ==
        "--strobe: earlier poses are ghosted in 2D frames only");
}

TEST_CASE("a scene's videos share one camera, fitted over every variant's run, as its poll sheet does") {
  // 10b's: the isolated method's body passes through the wall, the event method's bounces back
  const std::string file = std::string(RIGIDREEL_SOURCE_DIR) + "/scenes/lecture/10b_tunneling.yaml";
  const RenderPlan plan = render::video::planLecture(Loader{file, {}}(), {.file = file});
  REQUIRE(plan.videos.size() == 2);
  const render::draw::Camera &a = plan.videos[0].camera, &b = plan.videos[1].camera;
  CHECK(a.center().x() == doctest::Approx(b.center().x()));
  CHECK(a.center().y() == doctest::Approx(b.center().y()));
  CHECK(a.worldHeight() == doctest::Approx(b.worldHeight()));
  // both bodies' runs in it: through the wall to x = 2.92, back to x = −3.02
  CHECK(a.view().min.x() < -3.02);
  CHECK(a.view().max.x() > 2.92);
  // one variant alone keeps its own
  const RenderPlan one = render::video::planVideos(Loader{file, {}}(), {.variant = "event"});
  CHECK(one.videos.front().camera.view().max.x() < 2.92);
}
