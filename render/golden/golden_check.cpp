#include "render/golden/golden_check.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "render/draw/image_compare.h"
#include "render/draw/png_io.h"
#include "render/golden/sample3d.h"
#include "render/jobs/bounded_read.h"
#include "render/jobs/json_writer.h"
#include "render/jobs/read_limits.h"

namespace render::golden {
using namespace render::trace;
using render::jobs::formatNumber;

namespace fs = std::filesystem;

namespace {

// the largest error of one quantity, where and when
struct Largest {
  double error = 0.0;
  double t = 0.0;
  std::string body;
  void add(double e, double time, const std::string& who) {
    if (e > error || (std::isnan(e) && !std::isnan(error))) error = e, t = time, body = who;
  }
};

LevelResult stateLevel(const GoldenRun& run, const GoldenRecord& record) {
  LevelResult r{Level::State, LevelResult::Status::Ok, {}, {}};
  size_t differing = 0;
  double first = -1.0;
  for (size_t i = 0; i < run.checkpoints.size() && i < record.hashes.size(); ++i)
    if (run.checkpoints[i].hash != record.hashes[i]) {
      if (!differing) first = run.checkpoints[i].t;
      ++differing;
    }
  if (!differing) {
    r.message = "ok: " + std::to_string(run.checkpoints.size()) + " state hashes equal";
    return r;
  }
  // the hash says the bits differ; the trace says by how much
  Largest position, angle, velocity;
  for (size_t i = 0; i < run.checkpoints.size(); ++i)
    for (size_t b = 0; b < run.bodies.size(); ++b) {
      const TraceSample& a = run.checkpoints[i].bodies[b];
      if (b >= record.trace.size() || i >= record.trace[b].size()) continue;
      const TraceSample& e = record.trace[b][i];
      if (run.threeD) {
        position.add(std::hypot(a.x - e.x, a.y - e.y, a.z - e.z), a.t, run.bodies[b]);
        angle.add(rotationBetween(a, e), a.t, run.bodies[b]);
        velocity.add(
            std::max(std::hypot(a.vx - e.vx, a.vy - e.vy, a.vz - e.vz), std::hypot(a.wx - e.wx, a.wy - e.wy, a.omega - e.omega)),
            a.t, run.bodies[b]);
        continue;
      }
      position.add(std::hypot(a.x - e.x, a.y - e.y), a.t, run.bodies[b]);
      angle.add(std::abs(a.angle - e.angle), a.t, run.bodies[b]);
      velocity.add(std::max(std::hypot(a.vx - e.vx, a.vy - e.vy), std::abs(a.omega - e.omega)), a.t, run.bodies[b]);
    }
  const StateTolerance& tol = record.golden.tolerance;
  std::ostringstream m;
  const auto part = [&](const char* what, const Largest& l, double tolerance) {
    m << what << " " << formatNumber(l.error) << (l.error <= tolerance ? " <= " : " > ") << formatNumber(tolerance);
    if (l.error > 0.0) m << " ('" << l.body << "' at t = " << formatNumber(l.t) << ")";
  };
  const bool within = position.error <= tol.position && angle.error <= tol.angle && velocity.error <= tol.velocity;
  m << (within ? "ok: " : "") << differing << " of " << run.checkpoints.size()
    << " state hashes differ (first at t = " << formatNumber(first) << "); largest error: ";
  part("position", position, tol.position);
  m << ", ";
  part("angle", angle, tol.angle);
  m << ", ";
  part("velocity", velocity, tol.velocity);
  if (!within) m << "; the physics changed";
  r.message = m.str();
  if (!within) r.status = LevelResult::Status::Failed;
  return r;
}

LevelResult drawListLevel(const GoldenRun& run, const GoldenRecord& record) {
  LevelResult r{Level::DrawList, LevelResult::Status::Ok, {}, {}};
  std::vector<std::string> failures;
  for (size_t i = 0; i < run.frames.size(); ++i) {
    const GoldenFrame& f = run.frames[i];
    // (the run is made at the record's frame times, so its i-th frame is the record's)
    const std::string path = (fs::path(record.folder) / (record.frameNames.at(i) + ".json")).string();
    const std::string difference = compareDrawnFrames(readDrawnFrame(path), f.drawn);
    if (!difference.empty()) failures.push_back(f.name + ": " + difference);
  }
  if (failures.empty()) {
    r.message = "ok: " + std::to_string(run.frames.size()) + " frames draw the same calls";
    return r;
  }
  r.status = LevelResult::Status::Failed;
  r.message =
      std::to_string(failures.size()) + " of " + std::to_string(run.frames.size()) + " frames differ: " + failures.front();
  if (failures.size() > 1) r.message += " (and " + std::to_string(failures.size() - 1) + " more)";
  r.message += "; what is shown changed";
  return r;
}

LevelResult pixelLevel(const GoldenRun& run, const GoldenRecord& record, bool strict) {
  LevelResult r{Level::Pixels, LevelResult::Status::Ok, {}, {}};
  if (!strict && (record.renderer != run.renderer || record.rendererVersion != run.rendererVersion)) {
    r.status = LevelResult::Status::Skipped;
    r.message = "skipped: recorded with " + record.renderer + " (" + record.rendererVersion + "), drawn now with " +
                run.renderer + " (" + run.rendererVersion + "); --strict compares them anyway";
    return r;
  }
  const render::draw::PixelTolerance tolerance{record.golden.pixelTolerance, record.golden.pixelFraction};
  long worst = 0;
  for (size_t i = 0; i < run.frames.size(); ++i) {
    const GoldenFrame& f = run.frames[i];
    const std::string png = (fs::path(record.folder) / (record.frameNames.at(i) + ".png")).string();
    const std::string bytes =
        render::jobs::readBounded(png, render::jobs::kMaxPngBytes, "baseline PNG", "record it again (rigidreel golden record)");
    // the size its header claims, before anything is decoded: a frame of another size is a
    // difference to report, not 3.6 GB of pixels to allocate
    const render::draw::PngSize size = render::draw::pngSize(bytes, png);
    const bool sameSize = size.width == f.image.width && size.height == f.image.height;
    render::draw::ImageComparison c;
    if (sameSize) c = render::draw::compareImages(render::draw::decodePng(bytes, png), f.image, tolerance);
    else c.sameSize = false;
    worst = std::max(worst, c.differing);
    if (c.passed()) continue;
    std::ostringstream m;
    if (!c.sameSize)
      m << f.name << ": " << f.image.width << "x" << f.image.height << ", recorded at " << size.width << "x" << size.height;
    else
      m << f.name << ": " << c.differing << " pixels differ by more than " << tolerance.channel << "/255 (at most " << c.allowed
        << " may; largest difference " << c.largest << "/255)";
    r.frames.push_back({f.name, f.t, png, f.image, std::move(c.diff), m.str()});
  }
  if (r.frames.empty()) {
    r.message = "ok: " + std::to_string(run.frames.size()) + " frames within " + std::to_string(tolerance.channel) +
                "/255 (most pixels off: " + std::to_string(worst) + ")";
    return r;
  }
  r.status = LevelResult::Status::Failed;
  r.message = std::to_string(r.frames.size()) + " of " + std::to_string(run.frames.size()) +
              " frames differ: " + r.frames.front().message;
  return r;
}

}  // namespace

const char* levelName(Level level) {
  switch (level) {
    case Level::State: return "state";
    case Level::DrawList: return "draw_list";
    case Level::Pixels: return "pixels";
  }
  return "?";
}

bool CaseResult::failed() const {
  for (const LevelResult& l : levels)
    if (l.failed()) return true;
  return false;
}

CaseResult checkRun(const GoldenRun& run, const GoldenRecord& record, bool strict) {
  CaseResult c{run.name, record.sceneFile, {}, {}};
  if (record.version != rigidreelVersion())
    c.warnings.push_back("recorded by rigidreel " + record.version + ", checked by " + rigidreelVersion());
  c.levels.push_back(stateLevel(run, record));
  c.levels.push_back(drawListLevel(run, record));
  c.levels.push_back(pixelLevel(run, record, strict));
  if (c.levels.back().status == LevelResult::Status::Skipped) c.warnings.push_back(c.levels.back().message);
  return c;
}

}  // namespace render::golden
