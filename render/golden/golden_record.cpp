#include "render/golden/golden_record.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "render/draw/png_io.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/bounded_read.h"
#include "render/jobs/csv_field.h"
#include "render/jobs/exit_status.h"
#include "render/jobs/json_writer.h"
#include "render/jobs/read_limits.h"
#include "render/jobs/regular_file.h"
#include "sim/yaml/path_name.h"
#include "sim/yaml/scene_error.h"

#ifndef RIGIDREEL_VERSION
#define RIGIDREEL_VERSION "unknown"
#endif

namespace render::golden {
using namespace render::trace;
using render::jobs::formatNumber;

namespace fs = std::filesystem;

namespace {

std::string hexHash(unsigned long long h) {
  char s[24];
  std::snprintf(s, sizeof s, "%016llx", h);
  return s;
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

// what every file of a record says when it cannot be read back
constexpr const char* kRecordAgain = "record it again (rigidreel golden record)";

}  // namespace

std::string rigidreelVersion() { return RIGIDREEL_VERSION; }

void writeRecord(const GoldenRun& run, const RecordInfo& info, const std::string& dir) {
  fs::create_directories(dir);
  render::jobs::StagedDirectory folder((fs::path(dir) / run.name).string(), "golden record");
  const fs::path to = folder.path();
  writeText(to / "manifest.json", manifestJson(run, info));
  std::ostringstream states;
  states << "t,state_hash\n";
  for (const Checkpoint& c : run.checkpoints) states << formatNumber(c.t) << ',' << hexHash(c.hash) << '\n';
  writeText(to / "states.csv", states.str());
  std::ostringstream trace;
  trace << (run.threeD ? kTraceHeader3d : kTraceHeader) << '\n';
  for (const Checkpoint& c : run.checkpoints)
    for (size_t b = 0; b < c.bodies.size(); ++b) {
      const TraceSample& s = c.bodies[b];
      trace << formatNumber(c.t) << ',' << render::jobs::csvField(run.bodies[b]);
      // the columns of simulate --trace, 2D or 3D
      const std::vector<double> columns =
          run.threeD ? std::vector<double>{s.x, s.y, s.z, s.qw, s.qx, s.qy, s.qz, s.vx, s.vy, s.vz, s.wx, s.wy, s.omega}
                     : std::vector<double>{s.x, s.y, s.angle, s.vx, s.vy, s.omega};
      for (double x : columns) trace << ',' << formatNumber(x);
      trace << ',' << formatNumber(s.kineticEnergy) << '\n';
    }
  writeText(to / "trace.csv", trace.str());
  for (const GoldenFrame& f : run.frames) {
    std::ostringstream json;
    writeDrawnFrame(json, f.drawn);
    writeText(to / (f.name + ".json"), json.str());
    if (!f.image.rgba.empty()) render::draw::writePng(f.image, (to / (f.name + ".png")).string());
  }
  folder.commit();
}

namespace {

// the record of a 2D or a 3D scene (readTrace reads its columns)
template <class Def>
GoldenRecord readRecordOf(const std::string& folder, const Def& def) {
  using render::jobs::kMaxRecordFileBytes;
  using render::jobs::readBounded;
  const auto path = [&](const std::string& file) { return (fs::path(folder) / file).string(); };
  GoldenRecord r;
  const std::string manifestPath = path("manifest.json");
  static_cast<RecordManifest&>(r) =
      manifestText(readBounded(manifestPath, kMaxRecordFileBytes, "golden manifest", kRecordAgain), manifestPath, def.duration);
  r.folder = folder;
  // the hashes, one line per checkpoint, at its time
  const std::string statesPath = path("states.csv");
  const std::string states = readBounded(statesPath, kMaxRecordFileBytes, "golden states file", kRecordAgain);
  std::istringstream lines(states);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    if (++number == 1 || line.empty()) continue;
    const auto fail = [&](const std::string& message) {
      throw sim::yaml::SceneError(statesPath, number, 1, message + "; " + kRecordAgain);
    };
    const size_t comma = line.find(',');
    if (comma == std::string::npos || line.size() - comma - 1 != 16 ||
        line.find_first_not_of("0123456789abcdef", comma + 1) != std::string::npos)
      fail("expected t,state_hash (16 hex digits)");
    const size_t i = r.hashes.size();
    double t = 0.0;
    const auto [end, error] = std::from_chars(line.data(), line.data() + comma, t);
    if (i >= r.times.checkpoints.size() || error != std::errc() || end != line.data() + comma || t != r.times.checkpoints[i])
      fail("expected the hash at the manifest's checkpoint " + std::to_string(i + 1) +
           (i < r.times.checkpoints.size() ? " (t = " + formatNumber(r.times.checkpoints[i]) + ")" : " (there are no more)"));
    r.hashes.push_back(std::stoull(line.substr(comma + 1), nullptr, 16));
  }
  if (r.hashes.size() != r.times.checkpoints.size())
    throw sim::yaml::SceneError(statesPath, number, 1,
                                "has " + std::to_string(r.hashes.size()) + " hashes for " +
                                    std::to_string(r.times.checkpoints.size()) + " checkpoints; " + kRecordAgain);
  // every body's row at every checkpoint: the state level compares them all
  const std::string tracePath = path("trace.csv");
  const Trace trace = readTrace(tracePath, def);
  for (size_t b = 0; b < trace.bodies.size(); ++b) {
    const std::vector<TraceSample>& samples = trace.bodies[b];
    for (size_t i = 0; i < r.times.checkpoints.size(); ++i)
      if (i >= samples.size() || samples[i].t != r.times.checkpoints[i])
        throw sim::yaml::SceneError(tracePath, i < samples.size() ? samples[i].line : 0, 1,
                                    "has no row of body '" + sim::yaml::shownName(def.bodies[b].name) +
                                        "' at checkpoint t = " + formatNumber(r.times.checkpoints[i]) + "; " + kRecordAgain);
    if (samples.size() > r.times.checkpoints.size())
      throw sim::yaml::SceneError(
          tracePath, samples[r.times.checkpoints.size()].line, 1,
          "has more rows of body '" + sim::yaml::shownName(def.bodies[b].name) + "' than checkpoints; " + kRecordAgain);
  }
  r.trace = trace.bodies;
  // each frame's files, there before anything runs
  for (const std::string& name : r.frameNames)
    for (const char* ending : {".json", ".png"}) {
      const std::string file = path(name + ending);
      if (const std::string kind = render::jobs::notRegularFile(file); !kind.empty() || !fs::exists(file))
        throw render::jobs::UsageError(file + ": " + (kind.empty() ? "missing" : kind) + " (" + manifestPath + " names it); " +
                                       kRecordAgain);
    }
  return r;
}

}  // namespace

GoldenRecord readRecord(const std::string& folder, const sim::scene::SceneDef& def) { return readRecordOf(folder, def); }
GoldenRecord readRecord(const std::string& folder, const sim::scene3d::SceneDef& def) { return readRecordOf(folder, def); }

}  // namespace render::golden
