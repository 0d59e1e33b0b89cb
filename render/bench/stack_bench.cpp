// rigidreel_stack_bench (`make bench`): the same stack layouts (stack_layouts.h) run through
// rigidreel's stack solvers (`--method`, repeatable) and, where Debian's libbox2d-dev was found at
// build time, through Box2D 2.4 with the same settings, in one run, and measured the same way: the
// top box's displacement and drop, the bulge |x − rest x|, the fastest body at the end and the worst of both
// over the second half of the timed steps, and the wall and processor time per step. Timings are
// never asserted; ratios are taken within one run, since the machines are shared and noisy.
//
// Which steps are timed: a layout is timed in the state its name promises. A touching layout
// stands from the start, so its first `--steps` steps are timed (after building). A dropped layout
// first falls into place: `--settle` seconds (3 s) are simulated untimed, then the next `--steps`
// steps are timed. Every engine is timed over exactly the same steps, and the measures are taken at
// the end of the timed steps. The output's `timed steps` column and the CSV's first_timed_step and
// last_timed_step say which (steps counted from 1 at the start of the simulation).
//
// CSV (`--csv FILE`, written whole when the run ends, under a temporary name then renamed; `make
// bench` writes render/bench/results/stacks.csv): `#` lines naming the command, the machine, the date
// and the commit (bench_csv.h), a header row, then one row per layout and engine. The columns are
// described in render/bench/README.md.
//
// rigidreel is reached only through scene definitions and World's public members (bodies,
// advanceTo), so the program does not depend on how World is organised inside.
//
// Box2D 2.4 rounds every polygon by b2_polygonRadius (1 cm): a box made with SetAsBox(h, h) is
// 2 cm wider than 2h. `--box2d-skin outer` (the default) shrinks the core by that radius so the
// rounded box is as wide as ours and the touching layout touches in both engines; `core` makes
// the boxes as Box2D's testbed does (its touching layout then starts 2 cm deep at every contact).
// The arch's stones are polygons of their own, inset the same way. `--ours-skin core` grows ours by
// the same 1 cm, so that both engines run the outline of Box2D's testbed shapes (ours with sharp
// corners); Box2D's arch sags much less with its own skin (about 0.37 m against 0.46 m with stones
// as large as ours, medians over nudged gravity), so a comparison is made with the same skin on
// both sides.
// Box2D's tolerances are compiled into the library; rigidreel's match them (sim/core/settings.h:
// linear slop 0.5 cm, Baumgarte 0.2, largest correction 0.2 m, restitution threshold 1 m/s).
#if RIGIDREEL_HAVE_BOX2D
#include <box2d/box2d.h>
#endif

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bench_csv.h"
#include "stack_layouts.h"
#include "sim/core/settings.h"
#include "sim/scene/scene_build.h"

namespace {

// Box2D 2.4's b2_polygonRadius (2 × b2_linearSlop), m: the rounding of every Box2D polygon
constexpr double kBox2dPolygonRadius = 0.01;

struct RunOptions {
  int steps = 600;               // timed steps
  double settleSeconds = 3.0;    // dropped layouts: simulated untimed before the timed steps
  int every = 0;                 // print the measures every this many steps (0: only at the end)
  int sample = 10;               // over the second half, measure every this many steps (untimed)
  bool box2dOuterSkin = true;    // Box2D boxes as wide as ours (see the top of the file)
  bool box2dContinuous = false;  // Box2D's time of impact against static bodies (rigidreel has none)
  double ourGrowth = 0.0;        // every shape of ours grown by this, m (--ours-skin core: Box2D's polygon radius)
  // rigidreel's soft_step: substeps per step and contact stiffness, as a scene's sim: {substeps,
  // contact_hertz} (the stiffness capped at a quarter of the substep rate)
  int substeps = sim::core::settings::kSubsteps;
  double contactHertz = sim::core::settings::kContactHertz;
  int threads = 1;            // soft_step's sim: threads
  int simdWidth = 8;          // soft_step's widest SIMD: 8 (AVX-512), 4 (AVX2) or 1, where the processor has it
  int contactsPerThread = 0;  // soft_step: the contacts a step needs per thread past the first to share it (0: settings.h's)
};

// one engine holding one layout: step it, read the boxes back (in layout order)
class StackRun {
 public:
  virtual ~StackRun() = default;
  virtual void advance(int steps) = 0;  // throws on divergence
  virtual std::vector<bench::BodyEnd> ends() const = 0;
};

struct RunResult {
  bench::StackMetrics metrics;  // at the end
  double worstTop = 0.0;        // the largest top displacement over the second half
  double worstSpeed = 0.0;      // the fastest body over the second half
  double msPerStep = 0.0;       // wall time
  double cpuMsPerStep = 0.0;    // this thread's processor time: what a busy shared machine changes least
  int settleSteps = 0;          // untimed steps before the timed ones
  bool diverged = false;
  int threads = 1;  // ours: soft_step's threads
};

// untimed steps before the timing: a dropped layout settles first, a touching one stands already
int settleStepsOf(const bench::StackLayout& layout, const bench::StackSettings& s, const RunOptions& o) {
  return layout.dropped ? static_cast<int>(std::lround(o.settleSeconds / s.dt)) : 0;
}

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// settle untimed, then run `steps` steps timing only the stepping; the second half of the timed
// steps is sampled (untimed) for its worst values
RunResult run(StackRun& engine, const char* name, const bench::StackLayout& layout, int settleSteps, const RunOptions& o) {
  using Clock = std::chrono::steady_clock;
  RunResult r;
  r.settleSteps = settleSteps;
  double seconds = 0.0, cpuSeconds = 0.0;
  const int half = o.steps / 2;
  try {
    if (settleSteps > 0) engine.advance(settleSteps);
    for (int done = 0; done < o.steps;) {
      int next = o.steps;
      if (o.every > 0) next = std::min(next, (done / o.every + 1) * o.every);
      if (done >= half) next = std::min(next, done + o.sample);
      else next = std::min(next, half);
      const auto start = Clock::now();
      const double cpuStart = threadCpuSeconds();
      engine.advance(next - done);
      cpuSeconds += threadCpuSeconds() - cpuStart;
      seconds += std::chrono::duration<double>(Clock::now() - start).count();
      done = next;
      const std::vector<bench::BodyEnd> end = engine.ends();
      const bench::StackMetrics m = bench::measure(layout, end);
      if (done >= half)
        r.worstTop = std::max(r.worstTop, m.topDisplacement), r.worstSpeed = std::max(r.worstSpeed, m.fastestSpeed);
      if (o.every > 0 && done % o.every == 0)
        std::printf("  %-7s step %4d: top %.4f m (dropped %.4f m), max |x - rest x| %.4f m, fastest %.4f m/s, moved %d\n", name,
                    settleSteps + done, m.topDisplacement, m.topDrop, m.maxOffRestX, m.fastestSpeed, m.moved);
    }
  } catch (const std::exception&) {
    r.diverged = true;
  }
  const std::vector<bench::BodyEnd> end = engine.ends();
  r.metrics = bench::measure(layout, end);
  for (const bench::BodyEnd& e : end) r.diverged |= !std::isfinite(e.x) || !std::isfinite(e.y);
  r.msPerStep = 1000.0 * seconds / o.steps;
  r.cpuMsPerStep = 1000.0 * cpuSeconds / o.steps;
  return r;
}

// --- rigidreel, through a scene definition and World's public members ---

sim::scene::SceneDef sceneOf(const bench::StackLayout& layout, const bench::StackSettings& s, const RunOptions& o,
                             sim::core::CollisionMethod method, sim::world::Precision precision, double recycle) {
  sim::scene::SceneDef def;
  def.name = layout.name;
  def.gravity = {0.0, s.gravity};
  def.dt = s.dt;
  def.duration = 1e9;
  def.friction = s.friction;
  def.restitution = s.restitution;
  def.collisions = method;
  def.velocityIterations = s.velocityIterations;
  def.positionIterations = s.positionIterations;
  def.substeps = o.substeps;
  def.contactHertz = o.contactHertz;
  def.threads = o.threads;
  def.precision = precision;
  def.recycleDistance = recycle;
  sim::scene::BodyDef ground;
  ground.name = "ground";
  ground.shape = layout.halfPlane ? sim::core::makePlane({0.0, 1.0})
                                  : sim::core::makeBox(2.0 * (layout.groundHalfWidth + o.ourGrowth), 1.0 + 2.0 * o.ourGrowth);
  ground.position =
      layout.halfPlane ? sim::core::Vec2(layout.groundCenterX, o.ourGrowth) : sim::core::Vec2(layout.groundCenterX, -0.5);
  ground.isStatic = true;
  def.bodies.push_back(ground);
  for (size_t i = 0; i < layout.boxes.size(); ++i) {
    sim::scene::BodyDef b;
    b.name = "box" + std::to_string(i);
    const std::vector<bench::Point>& outline = layout.boxes[i].polygon;
    if (outline.empty()) {
      b.shape = sim::core::makeBox(layout.boxSize + 2.0 * o.ourGrowth, layout.boxSize + 2.0 * o.ourGrowth);
    } else {
      std::vector<sim::core::Vec2> vertices;
      for (const bench::Point& p : bench::offsetPolygon(outline, o.ourGrowth)) vertices.push_back({p[0], p[1]});
      b.shape = sim::core::makePolygon(vertices);
    }
    b.density = s.density * layout.boxes[i].density;
    b.position = {layout.boxes[i].x, layout.boxes[i].y};
    def.bodies.push_back(b);
  }
  return def;
}

// a built world solved with at most o.simdWidth lanes and shared by threads from o.contactsPerThread
// contacts: the bench's to choose, not a scene's
sim::world::World withSolveOptions(sim::world::World built, const RunOptions& o) {
  sim::world::WorldDef def = built.def();
  def.simdWidth = o.simdWidth;
  def.contactsPerThread = o.contactsPerThread;
  return sim::world::World(std::move(def), std::move(built.bodies));
}

class OurRun : public StackRun {
 public:
  OurRun(const bench::StackLayout& layout, const bench::StackSettings& s, const RunOptions& o, sim::core::CollisionMethod method,
         sim::world::Precision precision, double recycle = 0.0)
      : world_(withSolveOptions(sim::scene::buildWorld(sceneOf(layout, s, o, method, precision, recycle)), o)), dt_(s.dt) {
    world_.start();
  }
  void advance(int steps) override {
    steps_ += steps;
    world_.advanceTo(steps_ * dt_);
  }
  std::vector<bench::BodyEnd> ends() const override {
    std::vector<bench::BodyEnd> end;
    for (size_t i = 1; i < world_.bodies.size(); ++i) {  // body 0 is the ground
      const sim::core::Body& b = world_.bodies[i];
      end.push_back({b.x.x(), b.x.y(), b.v.x(), b.v.y(), b.omega});
    }
    return end;
  }
  const sim::world::World& world() const { return world_; }
  // the deepest overlap of any two bodies now, m, from a fresh collision of every pair (recycled
  // manifolds carry their separations; this measures where the bodies are)
  double deepestOverlap() const {
    double deepest = 0.0;
    for (const sim::world::Contact& c : world_.findContacts(sim::core::settings::kContactMargin))
      for (int k = 0; k < c.manifold.count; ++k) deepest = std::min(deepest, c.manifold.points[k].separation);
    return -deepest;
  }

 private:
  sim::world::World world_;
  double dt_;
  long steps_ = 0;
};

// --- Box2D 2.4 ---
#if RIGIDREEL_HAVE_BOX2D

class Box2dRun : public StackRun {
 public:
  Box2dRun(const bench::StackLayout& layout, const bench::StackSettings& s, const RunOptions& o)
      : world_(b2Vec2(0.0f, static_cast<float>(s.gravity))), settings_(s) {
    world_.SetAllowSleeping(false);
    world_.SetContinuousPhysics(o.box2dContinuous);
    // the rounding radius every Box2D polygon carries; taken off the core so the outer box is ours
    const float skin = o.box2dOuterSkin ? b2_polygonRadius : 0.0f;

    b2BodyDef groundDef;
    groundDef.position.Set(static_cast<float>(layout.groundCenterX), -0.5f);
    b2Body* ground = world_.CreateBody(&groundDef);
    b2PolygonShape groundShape;
    groundShape.SetAsBox(static_cast<float>(layout.groundHalfWidth) - skin, 0.5f - skin);
    b2FixtureDef groundFixture;
    groundFixture.shape = &groundShape;
    groundFixture.friction = static_cast<float>(s.friction);
    groundFixture.restitution = static_cast<float>(s.restitution);
    ground->CreateFixture(&groundFixture);

    const float half = 0.5f * static_cast<float>(layout.boxSize);
    b2PolygonShape boxShape;
    boxShape.SetAsBox(half - skin, half - skin);
    b2FixtureDef boxFixture;
    boxFixture.shape = &boxShape;
    boxFixture.density = static_cast<float>(s.density);
    boxFixture.friction = static_cast<float>(s.friction);
    boxFixture.restitution = static_cast<float>(s.restitution);
    // bodies made in the same order as rigidreel's (bottom row first): Box2D's islands, and so the
    // order its solver visits contacts in, follow creation order
    for (const bench::BoxPlacement& p : layout.boxes) {
      b2BodyDef bd;
      bd.type = b2_dynamicBody;
      bd.position.Set(static_cast<float>(p.x), static_cast<float>(p.y));
      b2Body* body = world_.CreateBody(&bd);
      // a polygon of the layout's own (the arch's stones): its core, rounded by the skin
      b2PolygonShape outline;
      b2FixtureDef fixture = boxFixture;
      fixture.density *= static_cast<float>(p.density);
      if (!p.polygon.empty()) {
        std::vector<b2Vec2> core;
        for (const bench::Point& v : bench::offsetPolygon(p.polygon, -skin))
          core.emplace_back(static_cast<float>(v[0]), static_cast<float>(v[1]));
        outline.Set(core.data(), static_cast<int32>(core.size()));
        fixture.shape = &outline;
      }
      body->CreateFixture(&fixture);
      boxes_.push_back(body);
    }
  }
  void advance(int steps) override {
    for (int k = 0; k < steps; ++k)
      world_.Step(static_cast<float>(settings_.dt), settings_.velocityIterations, settings_.positionIterations);
  }
  std::vector<bench::BodyEnd> ends() const override {
    std::vector<bench::BodyEnd> end;
    for (const b2Body* b : boxes_) {
      const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity();
      end.push_back({p.x, p.y, v.x, v.y, b->GetAngularVelocity()});
    }
    return end;
  }

 private:
  b2World world_;
  bench::StackSettings settings_;
  std::vector<b2Body*> boxes_;
};
#endif

// --- Box2D v3 (`--box2d3 DIR`): its own headless program, b3_pyramid, built from
// ../shared/peers/box2d-v3/build.sh DIR: Box2D v3's large_pyramid scene (the packed layout of
// stack_layouts.h, friction 0.6, one thread, sleeping off) at the same substeps. It reports its processor time per step, the top
// box's displacement and the fastest body; the other measures are not known (nan) ---

std::optional<RunResult> runBox2d3(const std::string& dir, int base, const RunOptions& o) {
  const std::string command =
      "'" + dir + "/b3_pyramid' " + std::to_string(base) + " " + std::to_string(o.steps) + " " + std::to_string(o.substeps);
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return std::nullopt;
  double ms = 0.0, top = 0.0, fastest = 0.0;
  const int read = std::fscanf(pipe, "ms_per_step %lf top_moved %lf fastest %lf", &ms, &top, &fastest);
  if (pclose(pipe) != 0 || read != 3) return std::nullopt;
  const double nan = std::nan("");
  RunResult r;
  // what b3_pyramid prints: the top box's displacement and the fastest body; the rest unmeasured
  r.metrics.topDisplacement = top;
  r.metrics.topDrop = r.metrics.maxOffRestX = r.metrics.fastestSpin = nan;
  r.metrics.fastestSpeed = fastest;
  r.metrics.moved = -1;
  r.worstTop = r.worstSpeed = nan;
  r.msPerStep = nan;
  r.cpuMsPerStep = ms;
  return r;
}

// a CSV cell: empty where the engine does not measure it (NaN; b3_pyramid's unmeasured values)
std::string cell(double x) {
  if (!std::isfinite(x)) return "";
  std::ostringstream s;
  s << x;
  return s.str();
}

// "pyramid:100:touching", "pyramid:20:dropped", "pyramid:100:packed", "pyramid:100:packed:plane" (ours
// on a half-plane), "stack:10"
std::optional<bench::StackLayout> parseLayout(const std::string& spec) {
  std::vector<std::string> part;
  std::stringstream in(spec);
  for (std::string p; std::getline(in, p, ':');) part.push_back(p);
  try {
    const bool onPlane = part.size() == 4 && part[3] == "plane";
    if ((part.size() == 3 || onPlane) && part[0] == "pyramid" &&
        (part[2] == "touching" || part[2] == "dropped" || part[2] == "packed")) {
      bench::StackLayout l = bench::pyramid(std::stoi(part[1]), part[2] == "dropped", part[2] == "packed");
      l.halfPlane = onPlane;
      if (onPlane) l.name += "-plane";
      return l;
    }
    if (part.size() == 2 && part[0] == "stack") return bench::stack(std::stoi(part[1]));
    if (part.size() == 3 && part[0] == "stack") return bench::stack(std::stoi(part[1]), std::stod(part[2]));
    if (part.size() == 1 && part[0] == "arch") return bench::arch();
  } catch (const std::exception&) {}
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rigidreel's stack solvers against Box2D 2.4 on the same stack layouts, at Box2D's benchmark settings"};
  std::vector<std::string> layoutSpecs{
      "pyramid:20:touching", "pyramid:20:dropped", "pyramid:20:packed",        "pyramid:100:touching",
      "pyramid:100:dropped", "pyramid:100:packed", "pyramid:100:packed:plane", "arch"};
  std::vector<std::string> methods{"sequential"};
  std::string engine = "both", skin = "outer", csvPath, box2d3Dir;
  bench::StackSettings settings;
  RunOptions options;
  app.add_option("--layout", layoutSpecs,
                 "pyramid:BASE:touching, pyramid:BASE:dropped, pyramid:BASE:packed (Box2D v3's large_pyramid), any of them with "
                 ":plane (ours on a half-plane floor, the peers on their ground box), stack:HEIGHT, "
                 "stack:HEIGHT:RATIO (the top box RATIO times as dense) or arch (repeatable)");
  app.add_option("--method", methods, "rigidreel's collision method (repeatable): sequential, soft_step, ...");
  app.add_option("--engine", engine, "both, ours or box2d")->check(CLI::IsMember({"both", "ours", "box2d"}));
  app.add_option("--steps", options.steps, "timed steps of dt (600: 10 s)")->check(CLI::PositiveNumber);
  app.add_option("--settle", options.settleSeconds, "dropped layouts: seconds simulated untimed before the timed steps")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--dt", settings.dt, "time step, s");
  app.add_option("--gravity", settings.gravity, "gravity along y, m/s² (Box2D's benchmark: -10)");
  app.add_option("--iterations", settings.velocityIterations, "velocity iterations")->check(CLI::Range(1, 1000));
  app.add_option("--position-iterations", settings.positionIterations, "position iterations")->check(CLI::Range(0, 1000));
  app.add_option("--friction", settings.friction, "Coulomb friction of every box and the ground");
  app.add_option("--substeps", options.substeps, "rigidreel's soft_step: substeps per step")->check(CLI::Range(1, 1000));
  std::vector<int> threadCounts{1};
  app.add_option("--threads", threadCounts,
                 "rigidreel's soft_step: threads sharing each set of contacts (repeatable: a row each; compare their "
                 "ms/step, wall time)")
      ->check(CLI::Range(1, sim::core::settings::kMaxThreads));
  app.add_option(
         "--simd-width", options.simdWidth,
         "rigidreel's soft_step: the widest SIMD, 8 AVX-512, 4 AVX2 or 1 none (the widest the processor has, at most this)")
      ->check(CLI::IsMember({1, 4, 8}));
  app.add_option("--contacts-per-thread", options.contactsPerThread,
                 "rigidreel's soft_step: the contacts a step needs for each thread past the first before the threads "
                 "share it (default: sim/core/settings.h's kContactsPerThread; 1: always)")
      ->check(CLI::PositiveNumber);
  std::vector<std::string> recycles{"off"};
  app.add_option("--recycle", recycles, "soft_step's contact recycling (repeatable): off, on (sim: {recycle: true})")
      ->check(CLI::IsMember({"off", "on"}));
  std::vector<std::string> precisions{"double"};
  app.add_option("--precision", precisions,
                 "rigidreel's soft_step: double or float, the numbers of its contact solve (repeatable: a row each; "
                 "soft_step:float names the float rows)")
      ->check(CLI::IsMember({"double", "float"}));
  app.add_option("--contact-hertz", options.contactHertz,
                 "rigidreel's soft_step: contact stiffness, Hz (capped at a quarter of the substep rate)")
      ->check([](const std::string& text) {
        const double hz = std::strtod(text.c_str(), nullptr);
        return hz > 0.0 && std::isfinite(hz) ? std::string() : "the contact stiffness must be a positive finite number of Hz";
      });
  app.add_option("--every", options.every, "print the measures every N steps");
  app.add_option("--box2d-skin", skin, "outer: Box2D's rounded boxes as wide as ours; core: SetAsBox(0.5, 0.5)")
      ->check(CLI::IsMember({"outer", "core"}));
  std::string ourSkin = "outer";
  app.add_option("--ours-skin", ourSkin,
                 "outer: ours as the layout gives them; core: grown by Box2D's polygon radius (1 cm), the outline of "
                 "Box2D's testbed shapes (--box2d-skin core), corners sharp")
      ->check(CLI::IsMember({"outer", "core"}));
  app.add_flag("--box2d-continuous", options.box2dContinuous, "Box2D's continuous collision on (off: as rigidreel)");
  app.add_option("--box2d3", box2d3Dir,
                 "a folder holding Box2D v3's b3_pyramid (../shared/peers/box2d-v3/build.sh DIR): its column on the "
                 "packed pyramids, the scene it builds");
  app.add_option("--csv", csvPath,
                 "write one row per layout and engine to this file, after comment lines naming the command, machine, "
                 "date and commit (written whole when the run ends)");
  CLI11_PARSE(app, argc, argv);
  options.box2dOuterSkin = skin == "outer";
  options.ourGrowth = ourSkin == "core" ? kBox2dPolygonRadius : 0.0;
  std::vector<sim::core::CollisionMethod> ourMethods;
  for (const std::string& name : methods) {
    const std::optional<sim::core::CollisionMethod> m = sim::core::collisionMethodFromName(name);
    if (!m || *m == sim::core::CollisionMethod::Auto) {
      std::cerr << "--method: unknown collision method '" << name << "'\n";
      return 2;
    }
    ourMethods.push_back(*m);
  }
#if RIGIDREEL_HAVE_BOX2D
  const bool box2d = engine != "ours";
  std::printf("Box2D %d.%d.%d (b2_version), skin %s, continuous %s, sleeping off\n", b2_version.major, b2_version.minor,
              b2_version.revision, skin.c_str(), options.box2dContinuous ? "on" : "off");
#else
  [[maybe_unused]] const bool box2d = false;
  std::printf("Box2D: not built in (install Debian's libbox2d-dev and reconfigure; `make bench` does)\n");
#endif
  if (engine == "box2d") ourMethods.clear();

  // the CSV's rows, kept until the run ends and then written whole
  const std::string preamble = bench::csvPreamble(argc, argv);
  std::ostringstream csv;
  csv << "layout,boxes,engine,method,precision,recycle,threads,substeps,contact_hertz,velocity_iterations,"
         "position_iterations,gravity,skin,settle_steps,first_timed_step,last_timed_step,ms_per_step,cpu_ms_per_step,"
         "cpu_ratio_to_box2d,cpu_ratio_to_box2d_v3,wall_ratio_to_box2d_v3,top_displacement_m,top_drop_m,max_off_rest_x_m,"
         "fastest_m_per_s,fastest_rad_per_s,moved,worst_top_second_half_m,worst_fastest_second_half_m_per_s,diverged\n";
  const int mostThreads = *std::max_element(threadCounts.begin(), threadCounts.end());
  std::printf("gravity %g, dt %.6g, %d velocity and %d position iterations, friction %g, restitution %g\n", settings.gravity,
              settings.dt, settings.velocityIterations, settings.positionIterations, settings.friction, settings.restitution);
  std::printf("soft_step: %d substeps, contacts at %g Hz (at most a quarter of the substep rate)\n", options.substeps,
              options.contactHertz);
  // the stepping thread's processor time includes its waits for the others at each set
  if (mostThreads > 1)
    std::printf("rows :Nt ran on N threads: compare their ms/step (wall), not cpu ms (the stepping thread's alone)\n");
  const int dropSettle = static_cast<int>(std::lround(options.settleSeconds / settings.dt));
  std::printf(
      "timed: %d steps after building; touching layouts steps 1-%d (standing from the start), dropped ones "
      "steps %d-%d (after %d untimed steps, %g s, to settle); every engine over the same steps\n",
      options.steps, options.steps, dropSettle + 1, dropSettle + options.steps, dropSettle, options.settleSeconds);
  // at the end of the timed steps, and the worst over their second half, sampled every 10 steps
  std::printf("%-22s %-15s %6s %11s %9s %9s %9s %9s %13s %11s %9s %6s %12s %12s %9s %7s\n", "layout", "engine", "boxes",
              "timed steps", "ms/step", "cpu ms", "top m", "drop m", "|x-rest x| m", "fastest m/s", "|w| rad/s", "moved",
              "worst top m", "worst m/s", "/box2d", "/v3");
  int status = 0;
  for (const std::string& spec : layoutSpecs) {
    const std::optional<bench::StackLayout> layout = parseLayout(spec);
    if (!layout) {
      std::cerr << "unknown layout '" << spec << "'\n";
      return 2;
    }
    // Box2D first, so that each of ours prints its ratio to it
    std::optional<RunResult> peer, peer3;
    const int settleSteps = settleStepsOf(*layout, settings, options);
    auto row = [&](const std::string& name, const RunResult& r) {
      const bench::StackMetrics& m = r.metrics;
      char ratio[32] = "", ratio3[32] = "", timed[32];
      if (peer && &r != &*peer) std::snprintf(ratio, sizeof ratio, "%.2f", r.cpuMsPerStep / peer->cpuMsPerStep);
      // (on several threads, wall time against v3's one: the stepping thread's processor time leaves the others out)
      if (peer3 && &r != &*peer3)
        std::snprintf(ratio3, sizeof ratio3, r.threads > 1 ? "%.2fw" : "%.2f",
                      r.threads > 1 ? r.msPerStep / peer3->cpuMsPerStep : r.cpuMsPerStep / peer3->cpuMsPerStep);
      std::snprintf(timed, sizeof timed, "%d-%d", r.settleSteps + 1, r.settleSteps + options.steps);
      std::printf("%-22s %-15s %6zu %11s %9.3f %9.3f %9.4f %9.4f %13.4f %11.4f %9.4f %6d %12.4f %12.4f %9s %7s%s\n",
                  layout->name.c_str(), name.c_str(), layout->boxes.size(), timed, r.msPerStep, r.cpuMsPerStep, m.topDisplacement,
                  m.topDrop, m.maxOffRestX, m.fastestSpeed, m.fastestSpin, m.moved, r.worstTop, r.worstSpeed, ratio, ratio3,
                  r.diverged ? "  DIVERGED" : "");
      // the CSV's row: what ran, at which settings, which steps were timed, then the measures
      const bool ours = name.rfind("box2d", 0) != 0;
      const bool soft = name.rfind("soft_step", 0) == 0;
      csv << layout->name << ',' << layout->boxes.size() << ','
          << (name == "box2d" ? "box2d-2.4"
              : ours          ? "rigidreel"
                              : name)
          << ',' << (ours ? name.substr(0, name.find(':')) : "") << ','
          << (!ours                                      ? ""
              : name.find(":float") != std::string::npos ? "float"
                                                         : "double")
          << ','
          << (name.find(":recycle") != std::string::npos ? "on"
              : soft                                     ? "off"
                                                         : "")
          << ',' << (ours ? std::to_string(r.threads) : "") << ',';
      // the soft_step settings on soft_step's rows (and v3's substeps); the iterations on sequential's
      // and Box2D 2.4's
      const bool v3 = name == "box2d-v3";
      if (soft || v3) csv << options.substeps;
      csv << ',';
      if (soft) csv << options.contactHertz;
      csv << ',';
      if (!v3 && !soft) csv << settings.velocityIterations << ',' << settings.positionIterations;
      else csv << ',';
      csv << ',' << settings.gravity << ','
          << (name == "box2d" ? skin
              : ours          ? ourSkin
                              : "")
          << ',' << r.settleSteps << ',' << r.settleSteps + 1 << ',' << r.settleSteps + options.steps << ',' << cell(r.msPerStep)
          << ',' << cell(r.cpuMsPerStep) << ',';
      if (peer && &r != &*peer) csv << r.cpuMsPerStep / peer->cpuMsPerStep;
      csv << ',';
      if (peer3 && &r != &*peer3) csv << r.cpuMsPerStep / peer3->cpuMsPerStep;
      csv << ',';
      // wall time against v3's one thread (its processor time: one thread, nothing to wait for)
      if (peer3 && &r != &*peer3) csv << r.msPerStep / peer3->cpuMsPerStep;
      csv << ',' << cell(m.topDisplacement) << ',' << cell(m.topDrop) << ',' << cell(m.maxOffRestX) << ',' << cell(m.fastestSpeed)
          << ',' << cell(m.fastestSpin) << ',' << (m.moved >= 0 ? std::to_string(m.moved) : "") << ',' << cell(r.worstTop) << ','
          << cell(r.worstSpeed) << ',' << r.diverged << '\n';
      std::fflush(stdout);
      status |= r.diverged;
    };
#if RIGIDREEL_HAVE_BOX2D
    if (box2d) {
      Box2dRun e(*layout, settings, options);
      peer = run(e, "box2d", *layout, settleSteps, options);
      row("box2d", *peer);
    }
#endif
    // Box2D v3 on the packed pyramids only: the scene its program builds (its rows touch sideways;
    // the touching layout's do not, so its time and top there would be another scene's)
    if (!box2d3Dir.empty() && layout->name.find("-packed") != std::string::npos) {
      peer3 = runBox2d3(box2d3Dir, std::stoi(spec.substr(8)), options);
      if (peer3) row("box2d-v3", *peer3);
      else std::fprintf(stderr, "--box2d3: %s/b3_pyramid did not run\n", box2d3Dir.c_str());
    }
    // soft_step once per --precision and --recycle, the others in doubles
    for (sim::core::CollisionMethod method : ourMethods)
      for (const std::string& precision : precisions)
        for (const std::string& recycle : recycles)
          for (int threads : threadCounts) {
            const bool soft = method == sim::core::CollisionMethod::SoftStep;
            if (!soft && (precision != precisions.front() || recycle != recycles.front() || threads != threadCounts.front()))
              continue;
            RunOptions withThreads = options;
            withThreads.threads = soft ? threads : 1;
            const sim::world::Precision p = soft ? *sim::world::precisionFromName(precision) : sim::world::Precision::Double;
            const bool recycled = soft && recycle == "on";
            // appended piece by piece: g++ 12 warns of overlapping copies in ":" + std::to_string(...)
            // (GCC bug 105329, a false positive)
            std::string name(sim::core::collisionMethodName(method));
            if (p == sim::world::Precision::Float) name += ":float";
            if (recycled) name += ":recycle";
            if (withThreads.threads > 1) name += ':' + std::to_string(withThreads.threads) + 't';
            OurRun e(*layout, settings, withThreads, method, p, recycled ? sim::core::settings::kRecycleDistance : 0.0);
            RunResult result = run(e, name.c_str(), *layout, settleSteps, withThreads);
            result.threads = withThreads.threads;
            row(name, result);
            // what recycling kept (the touching pairs of the last step that were not collided again), and
            // the deepest overlap at the end beside the run without it
            if (soft && recycles.size() > 1)
              std::printf("%-22s %-15s deepest overlap %.5f m at the end; recycled %ld of %zu contacts in the last step\n", "",
                          "", e.deepestOverlap(), e.world().recycledContacts(), e.world().contacts.size());
          }
  }
  std::printf(
      "/box2d: processor time per step against Box2D 2.4's in this run; /v3: against Box2D v3's (--box2d3), \"w\": our wall "
      "time on several threads against v3's one\n");
  if (!csvPath.empty() && !bench::writeCsv(csvPath, preamble + csv.str())) return 1;
  return status;
}
