// What a lecture job leaves beside its outputs for the page: DIR/<scene>/page.json, the scene's
// title, description, closed-form checks, the files it wrote and how long it took. The page is
// built from these records (and from the files themselves), never from a job's memory, so that jobs
// run by GNU Parallel or a Slurm array, each writing only its own scene's folder, need nothing
// from each other.
#pragma once

#include <string>
#include <vector>

namespace render::page {

// the record's name in a scene's folder
inline constexpr const char* kRecordName = "page.json";

struct VideoRecord {
  std::string variant;  // "" for a scene without variants
  std::string video;    // file names in the scene's folder
  std::string poster;
  double fps = 0.0;
};

struct PanelRecord {
  std::string image;      // file name in the scene's folder
  std::string when;       // "t = 2.5 s", "impact 1"
  bool question = false;  // the poll's question: the scene before anything happens (t = 0)
  bool answer = false;    // the poll's answer: at or after the scene's `reveal` time (never by default)
};

// an `expect` entry's quantity with the value the run measured (as `rigidreel check` prints it)
struct CheckRecord {
  std::string variant;
  double time = 0.0;
  std::string quantity;
  std::vector<double> expected, actual;
  double error = 0.0, tolerance = 0.0;
  bool earlierRun = false;  // the expected value is an earlier run's, not a closed form (the entry's source:)
  bool passed() const { return error <= tolerance; }
};

struct SceneRecord {
  std::string scene;  // its name: the folder
  std::string file;   // the scene file it came from
  std::string title, description;
  std::string question, answer;  // the poll's (`question:`, `answer:`); the page folds the answer away
  double seconds = 0.0;          // the job's wall time
  int order = 0;                 // its place in the folder's order.txt (1, 2, ...), 0 when it has none
  std::vector<VideoRecord> videos;
  std::vector<PanelRecord> panels;
  std::vector<CheckRecord> checks;
};

// the record as JSON, written atomically to `path`; throws std::runtime_error when it cannot be
void writeSceneRecord(const SceneRecord& record, const std::string& path);
// the record in `path`; throws render::jobs::UsageError "PATH:LINE:COL: ..." for a malformed one
SceneRecord readSceneRecord(const std::string& path);

}  // namespace render::page
