#include "render/cli/lecture_job.h"

#include <iostream>

#include "render/cli/commands.h"
#include "render/cli/output.h"
#include "render/cli/snapshots.h"

namespace render::cli {

int runLectureJob(const LecturePlan& plan, const LectureOptions& options, const Wrote& wrote) {
  VideoOptions videos;
  videos.scene = plan.file;
  videos.output = options.output;
  videos.allVariants = true;
  videos.size = options.size;
  videos.fps = options.fps;
  // the lecture command reports per scene; the render's own progress and summary would interleave
  videos.quiet = true;
  if (const int status = renderVideos(videos, wrote); status != kExitOk) return status;

  const render::scene::PanelsDef& panels = plan.base.render.panels;
  if (panels.times.empty() && !panels.impacts) return kExitOk;
  SnapshotOptions stills;
  stills.scene = plan.file;
  stills.output = options.output;
  stills.size = options.size;
  stills.panels = true;
  stills.times = panels.times;
  stills.impacts = panels.impacts;
  try {
    writeSnapshots(stills, wrote);
  } catch (const sim::world::Diverged& d) {
    std::cerr << plan.file << ": the simulation diverged at t = " << timeForName(d.time)
              << "; try a smaller step (sim: {dt: ...}) or another integrator\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace render::cli
