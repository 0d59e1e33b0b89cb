#include "sim/core/step_grid.h"

#include <doctest/doctest.h>

using sim::core::StepGrid;

TEST_CASE("steps stop at the next grid point, instant or end, whichever comes first") {
  StepGrid grid(0.1, {0.45, 0.25, 0.25});
  CHECK(grid.nextStop(0.0, 1.0) == 0.1);
  CHECK(grid.nextStop(0.0, 0.05) == 0.05);
  CHECK(grid.arrive(0.1, 1.0) == 0.1);
  CHECK(grid.arrive(0.2, 1.0) == 0.2);
  CHECK(grid.nextStop(0.2, 1.0) == 0.25);  // the instant cuts the step short
  CHECK(grid.arrive(0.25, 1.0) == 0.25);
  CHECK(grid.nextStop(0.25, 1.0) == 0.30000000000000004);  // back on the grid: 3 × 0.1
  CHECK(grid.arrive(grid.nextStop(0.25, 1.0), 1.0) == 3 * 0.1);
}

TEST_CASE("the grid never shifts: grid points are index × dt, and round-off near them snaps onto them") {
  StepGrid grid(0.1, {});
  double t = 0.0;
  for (int k = 1; k <= 1000; ++k) t = grid.arrive(grid.nextStop(t, 200.0), 200.0);
  CHECK(t == 1000 * 0.1);  // not the sum of a thousand 0.1s
  // an instant within round-off of a grid point is that grid point
  StepGrid near(0.1, {0.2 + 1e-13});
  double u = near.arrive(near.nextStop(0.0, 1.0), 1.0);
  u = near.arrive(near.nextStop(u, 1.0), 1.0);
  CHECK(u == 2 * 0.1);
  CHECK(near.same(u, 0.2 + 1e-13));
  CHECK(!near.same(u, 0.2 + 1e-9));
}
