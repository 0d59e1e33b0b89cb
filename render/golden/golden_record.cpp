#include "render/golden/golden_record.h"

#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "render/draw/png_io.h"
#include "render/jobs/atomic_file.h"
#include "render/jobs/json_writer.h"
#include "sim/yaml/scene_error.h"

#ifndef RIGIDREEL_VERSION
#define RIGIDREEL_VERSION "unknown"
#endif

namespace render::golden {
using render::jobs::formatNumber;
using render::jobs::JsonWriter;

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

std::string manifest(const GoldenRun& run, const RecordInfo& info) {
  std::ostringstream s;
  JsonWriter j(s);
  const GoldenDef& g = info.golden;
  j.beginObject();
  j.field("rigidreel_version", rigidreelVersion()).field("name", run.name);
  j.field("scene_file", info.sceneFile).field("scene_sha256", info.sceneSha256);
  j.field("renderer", run.renderer).field("renderer_version", run.rendererVersion);
  j.key("size").beginArray().value(static_cast<long>(g.width)).value(static_cast<long>(g.height)).endArray();
  j.key("tolerance").beginObject().field("position", g.tolerance.position).field("angle", g.tolerance.angle);
  j.field("velocity", g.tolerance.velocity)
      .field("draw_list", 1e-6)
      .field("pixel_tolerance", static_cast<long>(g.pixelTolerance));
  j.field("pixel_fraction", g.pixelFraction).endObject();
  j.key("checkpoints").beginArray();
  for (const Checkpoint& c : run.checkpoints) j.value(c.t);
  j.endArray();
  j.key("frames").beginArray();
  for (const GoldenFrame& f : run.frames)
    j.beginObject().field("t", f.t).field("png", f.name + ".png").field("draw_list", f.name + ".json").endObject();
  j.endArray().endObject();
  s << '\n';
  return s.str();
}

}  // namespace

std::string rigidreelVersion() { return RIGIDREEL_VERSION; }

void writeRecord(const GoldenRun& run, const RecordInfo& info, const std::string& dir) {
  fs::create_directories(dir);
  render::jobs::StagedDirectory folder((fs::path(dir) / run.name).string());
  const fs::path to = folder.path();
  writeText(to / "manifest.json", manifest(run, info));
  std::ostringstream states;
  states << "t,state_hash\n";
  for (const Checkpoint& c : run.checkpoints) states << formatNumber(c.t) << ',' << hexHash(c.hash) << '\n';
  writeText(to / "states.csv", states.str());
  std::ostringstream trace;
  trace << kTraceHeader << '\n';
  for (const Checkpoint& c : run.checkpoints)
    for (size_t b = 0; b < c.bodies.size(); ++b) {
      const TraceSample& s = c.bodies[b];
      trace << formatNumber(c.t) << ',' << run.bodies[b] << ',' << formatNumber(s.x) << ',' << formatNumber(s.y) << ','
            << formatNumber(s.angle) << ',' << formatNumber(s.vx) << ',' << formatNumber(s.vy) << ',' << formatNumber(s.omega)
            << ',' << formatNumber(s.kineticEnergy) << '\n';
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

GoldenRecord readRecord(const std::string& folder, const sim::scene::SceneDef& def) {
  GoldenRecord r;
  r.folder = folder;
  const std::string manifestPath = (fs::path(folder) / "manifest.json").string();
  try {
    const YAML::Node m = YAML::LoadFile(manifestPath);
    r.version = m["rigidreel_version"].as<std::string>();
    r.sceneFile = m["scene_file"].as<std::string>();
    r.sceneSha256 = m["scene_sha256"].as<std::string>();
    r.renderer = m["renderer"].as<std::string>();
    r.rendererVersion = m["renderer_version"].as<std::string>();
    r.golden.width = m["size"][0].as<int>();
    r.golden.height = m["size"][1].as<int>();
    const YAML::Node t = m["tolerance"];
    r.golden.tolerance = {t["position"].as<double>(), t["angle"].as<double>(), t["velocity"].as<double>()};
    r.golden.pixelTolerance = t["pixel_tolerance"].as<int>();
    r.golden.pixelFraction = t["pixel_fraction"].as<double>();
    for (const YAML::Node& c : m["checkpoints"]) r.times.checkpoints.push_back(c.as<double>());
    for (const YAML::Node& f : m["frames"]) {
      r.times.frames.push_back(f["t"].as<double>());
      r.frameNames.push_back(frameName(r.times.frames.back()));
    }
  } catch (const YAML::Exception& e) {
    throw sim::yaml::SceneError(manifestPath, e.mark.line + 1, e.mark.column + 1,
                                "not a manifest that `rigidreel golden record` wrote (" + e.msg + "); record it again");
  }
  // the hashes, one line per checkpoint
  const std::string statesPath = (fs::path(folder) / "states.csv").string();
  std::ifstream states(statesPath);
  std::string line;
  int number = 0;
  while (std::getline(states, line)) {
    if (++number == 1 || line.empty()) continue;
    const size_t comma = line.find(',');
    try {
      r.hashes.push_back(std::stoull(line.substr(comma + 1), nullptr, 16));
    } catch (const std::exception&) {
      throw sim::yaml::SceneError(statesPath, number, 1, "expected t,state_hash; record it again");
    }
  }
  if (r.hashes.size() != r.times.checkpoints.size())
    throw sim::yaml::SceneError(statesPath, number, 1,
                                "has " + std::to_string(r.hashes.size()) + " hashes for " +
                                    std::to_string(r.times.checkpoints.size()) + " checkpoints; record it again");
  r.trace = readTrace((fs::path(folder) / "trace.csv").string(), def).bodies;
  return r;
}

}  // namespace render::golden
