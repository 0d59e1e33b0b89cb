// The fixed step grid of a run: steps of dt from t = 0, each cut short where something happens at
// an exact instant (an impulse, a force switching on or off, the end of the run), so that no step
// straddles one and the grid itself never shifts. Two times closer than kTimeSnap·dt are the same
// instant (sim/core/settings.h). The 2D and the 3D world step on it through their one timeline
// (timeline.h).
#pragma once

#include <vector>

namespace sim::core {

class StepGrid {
 public:
  StepGrid() = default;
  // `instants`: the times of events and force switches, in any order
  StepGrid(double dt, std::vector<double> instants);

  // where the step that starts at `time` ends on the way to tEnd: the next grid point, instant or
  // tEnd, whichever comes first
  double nextStop(double time, double tEnd) const;
  // the time reached by a step to `stop`: the grid point or tEnd itself when `stop` is one of
  // them to within the snap (so that round-off never accumulates along the grid)
  double arrive(double stop, double tEnd);
  // a and b are the same instant
  bool same(double a, double b) const;

 private:
  double dt_ = 1.0;
  long index_ = 0;                // the current time lies in [index_ dt, (index_ + 1) dt)
  std::vector<double> instants_;  // sorted
};

}  // namespace sim::core
