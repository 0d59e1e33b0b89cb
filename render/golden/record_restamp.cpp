#include "render/golden/record_restamp.h"

#include <filesystem>

#include "render/jobs/atomic_file.h"

namespace render::golden {

void restampRecord(const GoldenRecord& record, const RecordInfo& info) {
  // the run the manifest describes, rebuilt from what the record holds (manifestJson reads these alone)
  GoldenRun run;
  run.name = record.name;
  run.renderer = record.renderer, run.rendererVersion = record.rendererVersion;
  for (double t : record.times.checkpoints) run.checkpoints.push_back({t, 0, {}});
  for (size_t i = 0; i < record.times.frames.size(); ++i)
    run.frames.push_back({record.times.frames[i], record.frameNames[i], {}, {}});
  render::jobs::AtomicFile file((std::filesystem::path(record.folder) / "manifest.json").string());
  file.stream() << manifestJson(run, info);
  file.commit();
}

}  // namespace render::golden
