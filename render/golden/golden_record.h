// A golden record on disk, one folder per scene variant, DIR/<scene>[-<variant>]/:
//
//   manifest.json   rigidreel's version, the scene file and its sha256, the renderer and its version
//                   as GL reports them, the frame size, the tolerances, the checkpoints and frames
//   states.csv      t,state_hash at each checkpoint (sim::world::stateHash, 16 hex digits)
//   trace.csv       the trace columns (trace_csv.h) at each checkpoint
//   frame-t<T>.json the draw list of each golden frame (draw_list_json.h)
//   frame-t<T>.png  each golden frame
//
// written into a staged folder and swapped into place whole (render/jobs/atomic_file.h).
#pragma once

#include <string>
#include <vector>

#include "render/golden/golden_def.h"
#include "render/golden/golden_run.h"
#include "render/golden/record_manifest.h"

namespace render::golden {

// rigidreel's version as the build names it
std::string rigidreelVersion();

// `run` written as DIR/<run.name>/, replacing what was there in one step; throws std::runtime_error
void writeRecord(const GoldenRun& run, const RecordInfo& info, const std::string& dir);

// a record read back (its draw lists and PNGs are read when compared): its manifest, and
struct GoldenRecord : RecordManifest {
  std::string folder;
  std::vector<unsigned long long> hashes;                      // by checkpoint
  std::vector<std::vector<render::trace::TraceSample>> trace;  // by the scene's body index, one sample per checkpoint
};

// the record in `folder` for the scene `def`, each file read through render/jobs/bounded_read.h: its
// manifest checked (record_manifest.h), a hash and every body's trace row at each checkpoint (a state
// level passed on missing rows would compare nothing), and each frame's draw list and PNG there.
// Throws sim::yaml::SceneError or render::jobs::UsageError naming the file at fault
GoldenRecord readRecord(const std::string& folder, const sim::scene::SceneDef& def);
// the same of a 3D scene's record, its trace in the 3D columns
GoldenRecord readRecord(const std::string& folder, const sim::scene3d::SceneDef& def);

}  // namespace render::golden
