#include "sim/core/step_grid.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "sim/core/settings.h"

namespace sim::core {

StepGrid::StepGrid(double dt, std::vector<double> instants) : dt_(dt), instants_(std::move(instants)) {
  std::sort(instants_.begin(), instants_.end());
}

bool StepGrid::same(double a, double b) const { return std::abs(a - b) <= settings::kTimeSnap * dt_; }

double StepGrid::nextStop(double time, double tEnd) const {
  double stop = std::min(tEnd, (index_ + 1) * dt_);
  // the first instant after now (an instant at now has been dealt with)
  const auto next = std::upper_bound(instants_.begin(), instants_.end(), time + settings::kTimeSnap * dt_);
  if (next != instants_.end()) stop = std::min(stop, *next);
  return stop;
}

double StepGrid::arrive(double stop, double tEnd) {
  const double gridPoint = (index_ + 1) * dt_;
  if (!same(stop, gridPoint)) return same(stop, tEnd) ? tEnd : stop;
  ++index_;
  return same(gridPoint, tEnd) ? tEnd : gridPoint;
}

}  // namespace sim::core
