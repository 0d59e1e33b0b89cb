// One comparison of a closed-form answer with a run, as `rigidreel check` prints it: what the 2D
// and the 3D `expect` entries both produce.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace sim::core {

struct CheckResult {
  double time = 0.0;
  std::string quantity;  // e.g. "bar.velocity", "total_energy"
  std::vector<double> expected, actual;
  double error = 0.0;  // Euclidean norm of actual − expected
  double tolerance = 0.0;
  bool earlierRun = false;  // the expected value is an earlier run's (the entry's source: earlier_run), not a closed form
  bool passed() const { return error <= tolerance; }
};

// the comparison of `actual` with `expected`, component by component
inline CheckResult compareValues(double time, double tolerance, std::string quantity, std::vector<double> expected,
                                 std::vector<double> actual) {
  double sum = 0.0;
  for (size_t i = 0; i < expected.size(); ++i) sum += (actual[i] - expected[i]) * (actual[i] - expected[i]);
  return {time, std::move(quantity), std::move(expected), std::move(actual), std::sqrt(sum), tolerance};
}

}  // namespace sim::core
