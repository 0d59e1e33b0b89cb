// A golden record's manifest.json: what the record was made from (rigidreel's version, the scene file
// and its sha256, the renderer as GL reports it), the frame size and tolerances, the checkpoints and
// the frames, each frame's PNG and draw list named:
//
//   {"rigidreel_version": "…", "name": "pend", "scene_file": "…", "scene_sha256": "…",
//    "renderer": "llvmpipe (…)", "renderer_version": "4.5 (…)", "size": [640, 360],
//    "tolerance": {"position": 1e-9, "angle": 1e-9, "velocity": 1e-9, "draw_list": 1e-6,
//                  "pixel_tolerance": 24, "pixel_fraction": 0.002},
//    "checkpoints": [0.5, 1], "frames": [{"t": 0.5, "png": "frame-t0.5.png", "draw_list": "frame-t0.5.json"}]}
//
// written by `golden record` and read back by `golden check`, every value checked where it stands
// (a checkpoint of 1e300 would run until killed, a size of 100000 × 100000 fail in the renderer).
#pragma once

#include <string>
#include <vector>

#include "render/golden/golden_def.h"
#include "render/golden/golden_run.h"

namespace render::golden {

// what a manifest says beside the run
struct RecordInfo {
  std::string sceneFile;  // as given
  std::string sceneSha256;
  GoldenDef golden;  // size and tolerances
};

// a manifest read back
struct RecordManifest {
  std::string version, name, sceneFile, sceneSha256, renderer, rendererVersion;
  GoldenDef golden;                     // its size and tolerances (`at` and `impacts` are not kept)
  GoldenTimes times;                    // the checkpoints, and the frames among them
  std::vector<std::string> frameNames;  // by frame: the base of its .png and .json
};

// the manifest of `run`, as JSON
std::string manifestJson(const GoldenRun& run, const RecordInfo& info);

// the manifest in `text` (`file` names it in messages) of a record of a scene `duration` s long;
// throws sim::yaml::SceneError at the FILE:LINE:COL of a value that is missing, of the wrong kind or
// out of its range (a checkpoint outside the run, a frame at no checkpoint, a frame size past the
// renderer's, a frame file outside the record's folder)
RecordManifest manifestText(const std::string& text, const std::string& file, double duration);

}  // namespace render::golden
