// A body's state stopped being finite: what both worlds throw, 2D and 3D, so that a caller
// reports a divergence once whatever the scene's dimension.
#pragma once

#include <stdexcept>

namespace sim::core {

struct Diverged : std::runtime_error {
  Diverged(double time, int body);
  double time;
  int body;
};

}  // namespace sim::core
