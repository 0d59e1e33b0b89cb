// Charts through gnuplot (Debian's gnuplot-nox): a generated script on its standard input, a PNG
// written under a temporary name and renamed when gnuplot succeeds. We chose gnuplot over drawing
// charts ourselves: log axes, ticks, legends and labels are its job and it does them well.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace render::analysis {

struct ChartSeries {
  std::string title;
  std::vector<std::pair<double, double>> points;
  // bars only: each value is a lower bound (a search that stopped at its limit, not at a failure):
  // drawn hatched and labeled "≥ value"
  bool lowerBounds = false;
};

struct Chart {
  std::string title, xLabel, yLabel;
  bool logX = false, logY = false;
  bool bars = false;                   // one bar per point (x is the bar's index) instead of lines
  std::vector<std::string> barLabels;  // a tick label per bar; '\n' breaks a line
  bool barValues = false;              // each bar labeled with its value, 3 significant digits
  std::vector<ChartSeries> series;
  // said in the middle of the plot: why it has nothing to draw ("every error is exactly 0"); series
  // without points are left out of the plot, and a chart with none left draws its axes and the note
  std::string note;
  int width = 1280, height = 800;  // pixels
};

// the gnuplot script that draws `chart` into `pngPath`
std::string gnuplotScript(const Chart& chart, const std::string& pngPath);

// draws the chart; throws std::runtime_error with gnuplot's message when it fails, or when the PNG
// gnuplot wrote does not read back whole (to its IEND chunk: gnuplot exits 0 on a full disk)
void writeChart(const Chart& chart, const std::string& pngPath);

}  // namespace render::analysis
