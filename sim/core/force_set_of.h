// The forces of a world, alike in 2D and 3D but for the vector: uniform gravity, and point forces,
// springs and drags on bodies by index. sim/core/forces.h's ForceSet (2D) and sim/world3d/forces.h's
// (3D) add what each dimension computes of them: forces and torques, potential energy, power.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

namespace sim::core {

inline constexpr int kWorldAnchor = -1;  // a spring end fixed in the world

// a constant force at a body point, on during [from, until)
template <class Vec>
struct PointForceOf {
  int body = 0;
  Vec point = Vec::Zero();  // body coordinates
  Vec force = Vec::Zero();  // world coordinates, or body coordinates when bodyFrame
  bool bodyFrame = false;   // the force turns with the body
  double from = 0.0;
  double until = std::numeric_limits<double>::infinity();
};

// a damped linear spring between a body point and a world anchor or another body's point
template <class Vec>
struct SpringOf {
  int bodyA = 0;
  Vec pointA = Vec::Zero();  // body coordinates of A
  int bodyB = kWorldAnchor;
  Vec pointB = Vec::Zero();  // body coordinates of B, or the world anchor
  double stiffness = 0.0;    // N/m
  double restLength = 0.0;   // m
  double damping = 0.0;      // N·s/m, along the spring
};

// linear and angular drag: f = −c v, τ = −c_ω ω (ω in the world frame)
struct Drag {
  int body = 0;
  double linear = 0.0;   // N·s/m
  double angular = 0.0;  // N·m·s
};

template <class Vec>
struct ForceSetOf {
  Vec gravity = Vec::Zero();  // m/s², acting at every center of mass
  std::vector<PointForceOf<Vec>> pointForces;
  std::vector<SpringOf<Vec>> springs;
  std::vector<Drag> drags;

  // times at which a force switches on or off: the step is split there
  std::vector<double> breakpoints() const {
    std::vector<double> t;
    for (const PointForceOf<Vec>& p : pointForces) {
      if (p.from > 0.0) t.push_back(p.from);
      if (std::isfinite(p.until)) t.push_back(p.until);
    }
    return t;
  }
};

}  // namespace sim::core
