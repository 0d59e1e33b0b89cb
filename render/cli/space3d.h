// The command line's 3D path: each subcommand opens its scene file once (OpenScene) and hands a 3D scene
// (dimensions: 3) to these; the 2D path stays as it is.
#pragma once

#include <optional>
#include <string>

#include "render/cli/check_tally.h"
#include "render/cli/method_lists.h"
#include "render/cli/output.h"
#include "render/cli/scene_options.h"
#include "render/cli/verbosity.h"
#include "render/video/render_plan.h"
#include "sim/world3d/world.h"

namespace render::cli {

// `simulate`: the state at `until` (the duration by default) as text or JSON, every step to a CSV
// trace; kExitOk, or kExitFailure when the simulation diverged
int simulate3d(const SceneOptions& options, std::optional<double> until, bool json, const std::string& trace);
// `check` of one file: every variant's model described and its expect entries compared, each
// variant tallied with what failed in it. Throws sim::yaml::SceneError, sim::core::Diverged
void check3d(const OpenScene& scene, const Verbosity& say, CheckTally& tally);
// `sweep` and `stability`
// (`verbose`: the CSV printed after the table)
int sweep3d(const SceneOptions& scene, const MethodLists& methods, const std::string& dt, int repeat, const std::string& outDir,
            bool verbose);
int stability3d(const SceneOptions& scene, const MethodLists& methods, const std::string& outDir, bool verbose);
// (`render`, `snapshot` and `lecture` make a 3D scene's plan with render_plan.h and write it with
// plan_writer.h, as for 2D)

// whether a body of a 2D or a 3D scene is static (a 3D scene's static surfaces are its planes, not bodies)
inline bool isStaticBody(const sim::scene::BodyDef& b) { return b.isStatic; }
inline bool isStaticBody(const sim::scene3d::BodyDef&) { return false; }

// "the simulation diverged at t = …: body '…' has a non-finite state; try …", for standard error
std::string divergedMessage(const std::string& file, const sim::scene3d::SceneDef& def, const sim::core::Diverged& d);
// why a named `event` stopped: "'die' and 'floor' at t = 0.61: a contact too slow to part persists
// (...); the event method resolves isolated impacts only: use 'collisions: sequential' or 'auto'"
std::string contactPersistsMessage(const sim::scene3d::SceneDef& def, const sim::world3d::ContactPersists& p);
// the scene's world, started: `auto` resolved; bodies that overlap where the event method cannot
// start are a sim::yaml::SceneError at the body's line
sim::world3d::World startWorld3d(const sim::scene3d::SceneDef& def, const std::string& file);

}  // namespace render::cli
