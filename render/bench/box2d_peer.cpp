// rigidreel_box2d_peer: the same stack layouts (stack_layouts.h) run through rigidreel's World and
// through Box2D 2.4 (Debian's libbox2d-dev) with the same settings, in one run, and measured the
// same way: the top box's displacement, the bulge |x − rest x|, the fastest body at the end and the
// worst of both over the second half, and the wall and processor time per step. Timings are never
// asserted; ratios are taken within one run, since the machines are shared and noisy.
//
// rigidreel is reached only through scene definitions and World's public members (bodies,
// advanceTo), so the program does not depend on how World is organised inside.
//
// Box2D 2.4 rounds every polygon by b2_polygonRadius (1 cm): a box made with SetAsBox(h, h) is
// 2 cm wider than 2h. `--box2d-skin outer` (the default) shrinks the core by that radius so the
// rounded box is as wide as ours and the touching layout touches in both engines; `core` makes
// the boxes as Box2D's testbed does (its touching layout then starts 2 cm deep at every contact).
// Box2D's tolerances are compiled into the library; rigidreel's match them (sim/core/settings.h:
// linear slop 0.5 cm, Baumgarte 0.2, largest correction 0.2 m, restitution threshold 1 m/s).
#include <box2d/box2d.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "stack_layouts.h"
#include "sim/scene/scene_build.h"

namespace {

struct RunOptions {
  int steps = 600;
  int every = 0;                  // print the measures every this many steps (0: only at the end)
  int sample = 10;                // over the second half, measure every this many steps (untimed)
  bool box2dOuterSkin = true;     // Box2D boxes as wide as ours (see the top of the file)
  bool box2dContinuous = false;   // Box2D's time of impact against static bodies (rigidreel has none)
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
  bool diverged = false;
};

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// run `steps` steps, timing only the stepping; the second half is sampled for its worst values
RunResult run(StackRun& engine, const char* name, const bench::StackLayout& layout, const RunOptions& o) {
  using Clock = std::chrono::steady_clock;
  RunResult r;
  double seconds = 0.0, cpuSeconds = 0.0;
  const int half = o.steps / 2;
  try {
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
      if (done >= half) r.worstTop = std::max(r.worstTop, m.topDisplacement), r.worstSpeed = std::max(r.worstSpeed, m.fastestSpeed);
      if (o.every > 0 && done % o.every == 0)
        std::printf("  %-7s step %4d: top %.4f m, max |x - rest x| %.4f m, fastest %.4f m/s, moved %d\n", name, done,
                    m.topDisplacement, m.maxOffRestX, m.fastestSpeed, m.moved);
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

sim::scene::SceneDef sceneOf(const bench::StackLayout& layout, const bench::StackSettings& s) {
  sim::scene::SceneDef def;
  def.name = layout.name;
  def.gravity = {0.0, s.gravity};
  def.dt = s.dt;
  def.duration = 1e9;
  def.friction = s.friction;
  def.restitution = s.restitution;
  def.collisions = sim::world::CollisionMethod::Sequential;
  def.velocityIterations = s.velocityIterations;
  def.positionIterations = s.positionIterations;
  sim::scene::BodyDef ground;
  ground.name = "ground";
  ground.shape = sim::core::makeBox(2.0 * layout.groundHalfWidth, 1.0);
  ground.position = {layout.groundCenterX, -0.5};
  ground.isStatic = true;
  def.bodies.push_back(ground);
  for (size_t i = 0; i < layout.boxes.size(); ++i) {
    sim::scene::BodyDef b;
    b.name = "box" + std::to_string(i);
    b.shape = sim::core::makeBox(layout.boxSize, layout.boxSize);
    b.density = s.density;
    b.position = {layout.boxes[i].x, layout.boxes[i].y};
    def.bodies.push_back(b);
  }
  return def;
}

class OurRun : public StackRun {
 public:
  OurRun(const bench::StackLayout& layout, const bench::StackSettings& s)
      : world_(sim::scene::buildWorld(sceneOf(layout, s))), dt_(s.dt) {
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

 private:
  sim::world::World world_;
  double dt_;
  long steps_ = 0;
};

// --- Box2D 2.4 ---

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
      body->CreateFixture(&boxFixture);
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

// "pyramid:100:touching", "pyramid:20:dropped", "stack:10"
std::optional<bench::StackLayout> parseLayout(const std::string& spec) {
  std::vector<std::string> part;
  std::stringstream in(spec);
  for (std::string p; std::getline(in, p, ':');) part.push_back(p);
  try {
    if (part.size() == 3 && part[0] == "pyramid" && (part[2] == "touching" || part[2] == "dropped"))
      return bench::pyramid(std::stoi(part[1]), part[2] == "dropped");
    if (part.size() == 2 && part[0] == "stack") return bench::stack(std::stoi(part[1]));
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rigidreel against Box2D 2.4 on the same stack layouts, at Box2D's benchmark settings"};
  std::vector<std::string> layoutSpecs{"pyramid:20:touching", "pyramid:20:dropped", "pyramid:100:touching",
                                       "pyramid:100:dropped"};
  std::string engine = "both", skin = "outer", csvPath;
  bench::StackSettings settings;
  RunOptions options;
  app.add_option("--layout", layoutSpecs, "pyramid:BASE:touching, pyramid:BASE:dropped or stack:HEIGHT (repeatable)");
  app.add_option("--engine", engine, "both, ours or box2d")->check(CLI::IsMember({"both", "ours", "box2d"}));
  app.add_option("--steps", options.steps, "steps of dt (600: 10 s)")->check(CLI::PositiveNumber);
  app.add_option("--dt", settings.dt, "time step, s");
  app.add_option("--iterations", settings.velocityIterations, "velocity iterations")->check(CLI::Range(1, 1000));
  app.add_option("--position-iterations", settings.positionIterations, "position iterations")->check(CLI::Range(0, 1000));
  app.add_option("--friction", settings.friction, "Coulomb friction of every box and the ground");
  app.add_option("--every", options.every, "print the measures every N steps");
  app.add_option("--box2d-skin", skin, "outer: Box2D's rounded boxes as wide as ours; core: SetAsBox(0.5, 0.5)")
      ->check(CLI::IsMember({"outer", "core"}));
  app.add_flag("--box2d-continuous", options.box2dContinuous, "Box2D's continuous collision on (off: as rigidreel)");
  app.add_option("--csv", csvPath, "append one row per layout and engine to this file");
  CLI11_PARSE(app, argc, argv);
  options.box2dOuterSkin = skin == "outer";

  std::ofstream csv;
  if (!csvPath.empty()) {
    const bool fresh = !std::ifstream(csvPath).good();
    csv.open(csvPath, std::ios::app);
    if (fresh)
      csv << "layout,engine,boxes,steps,velocity_iterations,position_iterations,ms_per_step,top_displacement_m,"
             "max_off_rest_x_m,fastest_m_per_s,fastest_rad_per_s,moved,worst_top_second_half_m,"
             "worst_fastest_second_half_m_per_s,diverged,cpu_ms_per_step\n";
  }
  std::printf("gravity %g, dt %.6g, %d velocity and %d position iterations, friction %g, restitution %g, %d steps; "
              "Box2D (b2_version %d.%d.%d), skin %s, continuous %s, sleeping off\n",
              settings.gravity, settings.dt, settings.velocityIterations, settings.positionIterations, settings.friction,
              settings.restitution, options.steps, b2_version.major, b2_version.minor, b2_version.revision, skin.c_str(),
              options.box2dContinuous ? "on" : "off");
  // at the end (10 s at 600 steps), and the worst over the second half, sampled every 10 steps
  std::printf("%-22s %-6s %6s %9s %9s %9s %13s %11s %9s %6s %12s %12s\n", "layout", "engine", "boxes", "ms/step", "cpu ms", "top m",
              "|x-rest x| m", "fastest m/s", "|w| rad/s", "moved", "worst top m", "worst m/s");
  int status = 0;
  for (const std::string& spec : layoutSpecs) {
    const std::optional<bench::StackLayout> layout = parseLayout(spec);
    if (!layout) {
      std::cerr << "unknown layout '" << spec << "'\n";
      return 2;
    }
    std::optional<RunResult> ours, peer;
    auto row = [&](const char* name, const RunResult& r) {
      const bench::StackMetrics& m = r.metrics;
      std::printf("%-22s %-6s %6zu %9.3f %9.3f %9.4f %13.4f %11.4f %9.4f %6d %12.4f %12.4f%s\n", layout->name.c_str(), name,
                  layout->boxes.size(), r.msPerStep, r.cpuMsPerStep, m.topDisplacement, m.maxOffRestX, m.fastestSpeed, m.fastestSpin,
                  m.moved, r.worstTop, r.worstSpeed, r.diverged ? "  DIVERGED" : "");
      if (csv.is_open())
        csv << layout->name << ',' << name << ',' << layout->boxes.size() << ',' << options.steps << ','
            << settings.velocityIterations << ',' << settings.positionIterations << ',' << r.msPerStep << ','
            << m.topDisplacement << ',' << m.maxOffRestX << ',' << m.fastestSpeed << ',' << m.fastestSpin << ','
            << m.moved << ',' << r.worstTop << ',' << r.worstSpeed << ',' << r.diverged << ',' << r.cpuMsPerStep << '\n';
      std::fflush(stdout);
    };
    if (engine != "box2d") {
      OurRun e(*layout, settings);
      row("ours", *(ours = run(e, "ours", *layout, options)));
    }
    if (engine != "ours") {
      Box2dRun e(*layout, settings, options);
      row("box2d", *(peer = run(e, "box2d", *layout, options)));
    }
    if (ours && peer)
      std::printf("%-22s ratio  ours/box2d time per step %.2f (wall), %.2f (cpu)\n", layout->name.c_str(),
                  ours->msPerStep / peer->msPerStep, ours->cpuMsPerStep / peer->cpuMsPerStep);
    status |= (ours && ours->diverged) || (peer && peer->diverged);
  }
  return status;
}
