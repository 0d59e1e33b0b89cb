// How to draw a 3D scene: what its render: block adds to the keys every scene shares (size, fps,
// colors, title card, caption, slow motion, panels, labels, time, trails, springs, energy, momentum;
// render::scene::RenderDef): the perspective camera, the 3D teaching arrows and the world's axes.
#pragma once

#include <string>
#include <vector>

#include "sim/core/enum_names.h"
#include "sim/world3d/math.h"

namespace render::scene3d {

// the perspective camera: fitted over everything the run covers, looking along `direction`, or
// placed at `eye` looking at `target`; `up` is the world direction drawn upward
struct Camera3dDef {
  bool automatic = true;
  sim::world3d::Vec3 direction = sim::world3d::Vec3(1.0, -1.7, 0.9);  // auto: from the fitted center toward the eye
  double margin = 0.08;                                               // auto: free space on each side, a fraction of the view
  sim::world3d::Vec3 eye = sim::world3d::Vec3::Zero(), target = sim::world3d::Vec3::Zero();  // fixed
  sim::world3d::Vec3 up = sim::world3d::Vec3::UnitZ();
  double fov = 35.0;  // vertical field of view, degrees
};

// a teaching vector or text drawn every frame: one entry of `arrows:`
struct Arrow3dDef {
  enum class Show { Axes, Omega, AngularMomentum, Velocity, Path, OmegaPath, State };
  Show show = Show::Axes;
  int body = 0;                                        // index into the model's bodies
  sim::world3d::Vec3 at = sim::world3d::Vec3::Zero();  // a body point, body coordinates (velocity, path)
  std::string label;                                   // empty: the default of `show`
  bool value = false;                                  // the vector's value after the label
  std::string color;                                   // "#rrggbb"; empty: the color of `show`'s role
};

inline constexpr sim::core::EnumNames<Arrow3dDef::Show, 7> kShow3dNames{{{
    {Arrow3dDef::Show::Axes, "axes"},
    {Arrow3dDef::Show::Omega, "omega"},
    {Arrow3dDef::Show::AngularMomentum, "angular_momentum"},
    {Arrow3dDef::Show::Velocity, "velocity"},
    {Arrow3dDef::Show::Path, "path"},
    {Arrow3dDef::Show::OmegaPath, "omega_path"},
    {Arrow3dDef::Show::State, "state"},
}}};

struct Render3dDef {
  Camera3dDef camera;
  std::vector<Arrow3dDef> arrows;
  // m of arrow per rad/s, per kg·m²/s, per m/s; 0: the run's largest is a quarter of the view's height
  // at the camera's target
  double omegaScale = 0.0, angularMomentumScale = 0.0, velocityScale = 0.0;
  bool worldAxes = true;  // the world's x, y, z in the bottom-left corner
};

}  // namespace render::scene3d
