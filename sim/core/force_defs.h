// What a scene file defines alike in 2D and 3D, generic over the dimension's vector: where a
// definition was written, and the forces and impulse events applied to named bodies. sim/scene's
// and sim/scene3d's SceneDef take them with Vec2 and Vec3 (plain definitions: no world sees them).
#pragma once

#include <limits>
#include <string>

namespace sim::core {

// where a definition came from in its file (1-based; 0 when unknown), for messages
struct SourceLoc {
  int line = 0;
  int column = 0;
};

template <class Vec>
struct PointForceDefOf {
  std::string body;
  Vec point = Vec::Zero();  // body coordinates as written
  Vec force = Vec::Zero();  // world, or body coordinates when bodyFrame
  bool bodyFrame = false;
  double from = 0.0;
  double until = std::numeric_limits<double>::infinity();
};

template <class Vec>
struct SpringDefOf {
  std::string body;
  Vec point = Vec::Zero();
  std::string body2;  // empty: the spring is anchored in the world at `anchor`
  Vec point2 = Vec::Zero();
  Vec anchor = Vec::Zero();
  double stiffness = 0.0;
  double restLength = 0.0;
  double damping = 0.0;
};

struct DragDef {
  std::string body;
  double linear = 0.0;
  double angular = 0.0;
};

template <class Vec>
struct EventDefOf {
  double time = 0.0;
  std::string body;
  Vec impulse = Vec::Zero();  // world coordinates
  Vec point = Vec::Zero();    // body coordinates as written, or world when pointInWorld
  bool pointInWorld = false;
};

}  // namespace sim::core
