// The gnuplot charts of `sweep` and `stability`: the script's text (tick labels that break lines, a
// lower bound marked as one) and a golden image of each kind of chart, drawn by gnuplot from fixed
// numbers, so that a slip in the script (a literal "\n" under a bar, a bound drawn as a value)
// shows as pixels.
#include "render/analysis/chart.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

#include "render/draw/png_io.h"
#include "support/golden_compare.h"

namespace fs = std::filesystem;
using render::analysis::Chart;
using render::analysis::ChartSeries;

namespace {

// the work-precision chart of a sweep: error against cost, log-log, one line per method
Chart sweepChart() {
  Chart c;
  c.title = "spring_bar: work against precision (error vs rk4 at dt/64)";
  c.xLabel = "cost: wall seconds per simulated second";
  c.yLabel = "error";
  c.logX = c.logY = true;
  c.width = 640, c.height = 400;
  // slopes −1, −2 and −4: error ∝ cost^−order
  const std::pair<const char*, double> methods[] = {{"explicit_euler", 1}, {"midpoint", 2}, {"rk4", 4}};
  for (const auto& [name, order] : methods) {
    ChartSeries s{name, {}};
    for (double cost = 1e-4; cost <= 1.01e-2; cost *= std::sqrt(10.0))
      s.points.emplace_back(order * cost, 1e-2 * std::pow(1e-4 / cost, order));
    c.series.push_back(s);
  }
  return c;
}

// the stability chart: a bar per method, two-line tick labels too wide to stand side by side (turned),
// three methods holding up to the search's limit
Chart stabilityChart() {
  Chart c;
  c.title = "tunneling: the largest speed at which each method holds";
  c.yLabel = "largest stable speed";
  c.bars = c.barValues = true;
  c.logY = true;
  c.width = 640, c.height = 480;
  c.barLabels = {"explicit_euler\nevent",    "symplectic_euler\nevent",    "rk4\nevent",
                 "explicit_euler\nisolated", "symplectic_euler\nisolated", "rk4\nisolated"};
  c.series.push_back({"largest stable speed", {{3, 3.18}, {4, 3.18}, {5, 3.18}}});
  c.series.push_back({"holds up to the search's limit (at least this)", {{0, 100000}, {1, 100000}, {2, 100000}}, true});
  return c;
}

render::draw::Image drawn(const Chart& chart, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rigidreel-chart-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / (name + ".png")).string();
  render::analysis::writeChart(chart, path);
  render::draw::Image image = render::draw::readPng(path);
  fs::remove_all(dir);
  return image;
}

}  // namespace

TEST_CASE("a bar's tick label breaks its line where the label has a newline; gnuplot is given \\n, not \\\\n") {
  const std::string script = render::analysis::gnuplotScript(stabilityChart(), "out.png");
  CHECK(script.find("\"rk4\\nevent\" 2") != std::string::npos);
  CHECK(script.find("set xtics rotate by 30 right") != std::string::npos);
  CHECK(script.find("\\\\n") == std::string::npos);
}

TEST_CASE("a lower bound is hatched and labeled with ≥; the other bars with their values") {
  const std::string script = render::analysis::gnuplotScript(stabilityChart(), "out.png");
  CHECK(script.find("\"≥ 1e+05\"") != std::string::npos);
  CHECK(script.find("\"3.18\"") != std::string::npos);
  CHECK(script.find("fill pattern") != std::string::npos);
  CHECK(script.find("set encoding utf8") != std::string::npos);
}

TEST_CASE("golden: the work-precision chart of a sweep") { golden::checkGolden("charts/sweep", drawn(sweepChart(), "sweep")); }

TEST_CASE("golden: the stability chart, tick labels on two lines, turned, and bounds marked ≥") {
  golden::checkGolden("charts/stability", drawn(stabilityChart(), "stability"));
}
