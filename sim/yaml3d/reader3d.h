// Reading the 3D values of a scene file: vectors [x, y, z], orientations and inertia tensors, with
// sim/yaml's Reader (FILE:LINE:COL messages) underneath. Shared by the 3D model's reader and the
// renderer's reader of a 3D scene's render: block.
#pragma once

#include "sim/world3d/math.h"
#include "sim/yaml/yaml_reader.h"

namespace sim::yaml3d {

class Reader3d : public sim::yaml::Reader {
 public:
  using Reader::Reader;

  sim::world3d::Vec3 vec3(const YAML::Node& n, const std::string& key) const {
    if (!n.IsSequence() || n.size() != 3) fail(n, "expected [x, y, z] for '" + key + "', got " + shape(n));
    return {finite(n[0], key), finite(n[1], key), finite(n[2], key)};
  }
  // the dimension's reader of a vector (Reader's is vec2)
  static constexpr auto kVector = &Reader3d::vec3;

  // `orientation`: a unit quaternion [w, x, y, z] (normalized when its length is 1 to round-off,
  // refused when further off) or {axis: [x, y, z], angle: θ}
  sim::world3d::Quat orientation(const YAML::Node& n, const std::string& key) const {
    try {
      if (n.IsMap()) {
        checkKeys(n, {"axis", "angle"}, key);
        const YAML::Node axis = required(n, "axis", key + " as an axis and an angle");
        return sim::world3d::axisAngle(vec3(axis, "axis"),
                                       finite(required(n, "angle", key + " as an axis and an angle"), "angle"));
      }
      if (!n.IsSequence() || n.size() != 4)
        fail(n, "expected a unit quaternion [w, x, y, z] or {axis: [x, y, z], angle: θ} for '" + key + "', got " + shape(n));
      return sim::world3d::unitQuaternion(finite(n[0], key), finite(n[1], key), finite(n[2], key), finite(n[3], key));
    } catch (const std::invalid_argument& e) {
      fail(n, e.what());
    }
  }

  // `inertia`: the three principal moments [I1, I2, I3] (the body's axes are principal), or the 3 × 3
  // tensor [[Ixx, Ixy, Ixz], [Iyx, Iyy, Iyz], [Izx, Izy, Izz]] in body axes, kg·m²
  sim::world3d::Mat3 inertia(const YAML::Node& n, const std::string& key) const {
    if (n.IsSequence() && n.size() == 3 && n[0].IsScalar()) {
      const sim::world3d::Vec3 moments(positive(n[0], key), positive(n[1], key), positive(n[2], key));
      return moments.asDiagonal();
    }
    if (n.IsSequence() && n.size() == 3) {
      sim::world3d::Mat3 m;
      for (int r = 0; r < 3; ++r) m.row(r) = vec3(n[r], key + " row").transpose();
      return m;
    }
    fail(n, "expected [I1, I2, I3] or a 3 × 3 tensor [[Ixx, Ixy, Ixz], [Iyx, Iyy, Iyz], [Izx, Izy, Izz]] for '" + key +
                "', got " + shape(n));
  }

 private:
  static std::string shape(const YAML::Node& n) {
    return n.IsSequence() ? "a list of " + std::to_string(n.size()) + " values" : sim::yaml::describe(n);
  }
};

}  // namespace sim::yaml3d
