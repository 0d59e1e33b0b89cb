// `rigidreel snapshot`: still frames of a scene at exact times or at its impacts, one PNG each, or
// with --panels every variant side by side in one labeled image (the poll slide): the options
// checked, the plan made, the plan written.
#include <cmath>
#include <iostream>
#include <sstream>

#include "render/cli/commands.h"
#include "render/cli/decimal_text.h"
#include "render/cli/output.h"
#include "render/cli/overlay_option.h"
#include "render/cli/scene_options.h"
#include "render/cli/space3d.h"
#include "render/cli/verbosity.h"
#include "render/jobs/interrupt.h"
#include "render/video/output_names.h"
#include "render/video/plan_writer.h"

namespace render::cli {
using namespace render::trace;
using namespace render::video;
using namespace render::jobs;

namespace {

struct SnapshotCommand : SceneOptions, Verbosity {
  std::string at;  // "T1,T2,..."
  bool impacts = false;
  bool panels = false;
  std::optional<int> strobe;
  std::string output = "out";
  std::string size;
  std::string trace;
  std::string overlay;    // another simulator's trace, drawn over ours
  bool drawList = false;  // each PNG's draw list in its pixels beside it
};

// "0.5,1,2.25" → {0.5, 1, 2.25}; throws UsageError
std::vector<double> parseTimes(const std::string& text) {
  std::vector<double> times;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const std::optional<double> t = decimalText(item);
    if (!t) throw UsageError("--at: expected times in seconds separated by commas, e.g. 0.5,1.25; got '" + text + "'");
    times.push_back(*t);
  }
  if (times.empty()) throw UsageError("--at: give at least one time");
  return times;
}

// the plan's request, each value checked (UsageError)
StillRequest request(const SnapshotCommand& o) {
  StillRequest r{.root = o.output,
                 .file = o.scene,
                 .variant = o.variant,
                 .times = {},
                 .impacts = o.impacts,
                 .panels = o.panels,
                 .strobe = o.strobe,
                 .size = {},
                 .drawList = o.drawList};
  if (!o.at.empty()) r.times = parseTimes(o.at);
  if (r.times.empty() == !o.impacts) throw UsageError("give the times with --at T1,T2,... or ask for --impacts (one of them)");
  if (o.panels && !o.variant.empty()) throw UsageError("--panels shows every variant side by side; leave out --variant");
  if (o.strobe && (*o.strobe < 0 || *o.strobe > 100)) throw UsageError("--strobe: give a number of ghosts from 0 to 100");
  if (!o.size.empty()) r.size = parseSize(o.size);
  return r;
}

int snapshot(const SnapshotCommand& o) {
  // a trace written over what the run reads would destroy it before it is read whole
  refuseInputAsOutput(o.trace, o.scene, "--trace");
  refuseInputAsOutput(o.trace, o.overlay, "--trace", "the --overlay trace");
  // each path as it is written (not with -q); -v adds the progress bar and the summary
  const auto print = [&o](const std::string& path) {
    if (!o.quiet) std::cout << path << '\n';
  };
  if (!o.overlay.empty() && o.is3d()) throw UsageError("--overlay: a trace is drawn over 2D scenes only");
  if (o.is3d()) try {
      const RenderPlan3d plan = planStills3d(o.variantLoader3d(), request(o));
      traced<TraceWriter3d>(o.trace, plan, [&](TraceWriter3d* trace) { writePlan3d(plan, !o.verbose, print, trace); });
      return kExitOk;
    } catch (const VariantDiverged3d& d) {
      std::cerr << divergedMessage(o.scene, d.model, d) << '\n';
      return kExitFailure;
    }
  try {
    const RenderPlan plan = planStills(withOverlay(o.variantLoader(), o.overlay), request(o));
    traced<TraceWriter>(o.trace, plan, [&](TraceWriter* trace) { writePlan(plan, !o.verbose, print, trace); });
  } catch (const sim::core::Diverged& d) {
    std::cerr << o.scene << ": the simulation diverged at t = " << timeForName(d.time)
              << "; try a smaller step (--dt) or another integrator (--integrator rk4)\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void addSnapshotCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<SnapshotCommand>();
  CLI::App* cmd = app.add_subcommand("snapshot", "still frames of a scene as PNG under out/<scene>/");
  cmd->add_option("scene", o->scene, "the scene file (YAML)")->required();
  o->SceneOptions::addTo(*cmd);
  cmd->add_option("--at", o->at, "times in seconds, separated by commas: one PNG each");
  cmd->add_flag("--impacts", o->impacts, "one PNG at each impact the collision response resolves");
  cmd->add_flag("--panels", o->panels, "every variant side by side in one labeled image");
  cmd->add_option("--strobe", o->strobe, "draw this many earlier poses, fading, behind the present one");
  cmd->add_option("-o,--output", o->output, "the output directory (default: out)");
  cmd->add_option("--size", o->size,
                  "frame size WIDTHxHEIGHT in pixels, even (default: the scene's, 1280x720); with --panels, the whole sheet's "
                  "(default 1920x1080)");
  o->Verbosity::addTo(*cmd, "print nothing (not each file's path)", "also a progress bar and a summary, as render shows them");
  cmd->add_option("--trace", o->trace, "also write every step of the pictures' run to this CSV file (as simulate --trace)");
  cmd->add_option("--overlay", o->overlay, "another simulator's trace (CSV, as --trace writes): its bodies dashed over ours");
  cmd->add_flag("--draw-list", o->drawList,
                "beside each PNG, its draw list in pixels as JSON (<png name>.json): every call, each text's box, the panel");
  // Ctrl-C and SIGTERM end a snapshot as they end a render: exit 130, no half-written PNG
  cmd->callback([o, &exitCode] { exitCode = runInterruptible("snapshot " + o->scene, [&] { return snapshot(*o); }); });
}

}  // namespace render::cli
