// What a 3D frame shows besides the present state, gathered while the world steps: each center's
// path (trails), the paths of body points (`show: path`) and of ω's tip about its center
// (`show: omega_path`: the cone ω sweeps).
#pragma once

#include <utility>
#include <vector>

#include "sim/world3d/world.h"

namespace render::frame3d {

class History3d : public sim::world3d::StepObserver {
 public:
  struct Options {
    bool trails = false;
    std::vector<std::pair<int, sim::world3d::Vec3>> points;  // body points (body coordinates) whose paths to keep
    std::vector<int> omegaTips;                              // bodies whose ω to keep, from the start
    // a point closer than this to the last one kept replaces it: m for paths, rad/s for ω
    double spacing = 0.0, omegaSpacing = 0.0;
  };

  // starts with the world's present state
  History3d(const sim::world3d::World& world, Options options);
  void afterStep(const sim::world3d::World& world) override;
  void afterEvent(const sim::world3d::World& world, const sim::world3d::ImpulseEvent&) override { afterStep(world); }

  const Options& options() const { return options_; }
  // the same paths as a history with these spacings would hold after the same steps: exact from a
  // history that kept every step's point (spacings 0), as the survey's does (render/frame/kept_run_of.h)
  void respace(double spacing, double omegaSpacing);
  // about how much memory its paths hold, bytes
  size_t pathBytes() const;

  // by body (empty without trails)
  const std::vector<sim::world3d::Vec3>& trail(size_t body) const { return trails_[body]; }
  // by Options::points, world coordinates
  const std::vector<sim::world3d::Vec3>& pointPath(size_t k) const { return points_[k]; }
  // by Options::omegaTips: ω at each kept step (world frame)
  const std::vector<sim::world3d::Vec3>& omegaPath(size_t k) const { return omegas_[k]; }

 private:
  static void keep(std::vector<sim::world3d::Vec3>& path, const sim::world3d::Vec3& p, double spacing);

  Options options_;
  std::vector<std::vector<sim::world3d::Vec3>> trails_, points_, omegas_;
};

}  // namespace render::frame3d
