// The trace CSV (`simulate --trace`, a golden record's trace.csv, `compare --trace`'s input): a
// header `t,body,x,y,angle,vx,vy,omega,kinetic_energy`, then one row per body per instant, as
// render/trace/trace_writer.h writes it, read back (another simulator's trajectory: any time grid,
// interpolated).
#pragma once

#include <string>
#include <vector>

#include "sim/scene/scene_def.h"
#include "sim/scene3d/scene_def.h"
#include "sim/world/world.h"

namespace render::trace {

inline constexpr const char* kTraceHeader = "t,body,x,y,angle,vx,vy,omega,kinetic_energy";
// a 3D scene's (render/trace/trace_writer.h)
inline constexpr const char* kTraceHeader3d = "t,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy";

// one body's state at one time, as a row gives it
struct TraceSample {
  double t = 0.0;
  double x = 0.0, y = 0.0, angle = 0.0, vx = 0.0, vy = 0.0, omega = 0.0;
  double kineticEnergy = 0.0;  // J (0 when the trace leaves it empty)
  int line = 0;                // of the file
  // a 3D body's further coordinates (omega is then ω's z, angle unused): z, its velocity's z, ω's x
  // and y, and its orientation q = [qw, qx, qy, qz]
  double z = 0.0, vz = 0.0, wx = 0.0, wy = 0.0;
  double qw = 1.0, qx = 0.0, qy = 0.0, qz = 0.0;
};

// a trace read for a scene: each body's samples (by the scene's body index) in the file's order,
// which is time order
struct Trace {
  std::string file;
  std::vector<std::vector<TraceSample>> bodies;
  size_t rows = 0;
};

// the trace in `path` (`file` names it in messages) read against the scene's bodies: a header with
// the columns t, body, x, y, angle, vx, vy, omega (kinetic_energy and any order allowed), finite
// numbers, times not going back for a body, and only bodies the scene has. Throws
// sim::yaml::SceneError at the fault's FILE:LINE:COL.
Trace readTrace(const std::string& path, const sim::scene::SceneDef& def);
Trace traceText(const std::string& text, const std::string& file, const sim::scene::SceneDef& def);
// the same of a 3D scene, its columns t, body, x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy, wz
Trace readTrace(const std::string& path, const sim::scene3d::SceneDef& def);
Trace traceText(const std::string& text, const std::string& file, const sim::scene3d::SceneDef& def);

// the body's state at time t, linear between the samples around it; of two rows at one time (before
// and after an event) the later, or with `before` the earlier; false when t is outside the samples'
// times
bool sampleAt(const std::vector<TraceSample>& samples, double t, TraceSample& out, bool before = false);

}  // namespace render::trace
