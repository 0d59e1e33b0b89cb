#include "render/analysis/chart.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "render/jobs/json_writer.h"
#include "render/jobs/process.h"

namespace render::analysis {
using namespace render::jobs;

namespace {

// a gnuplot string literal: in double quotes gnuplot reads \n as a line break
std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '\n') {
      q += "\\n";
      continue;
    }
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

// a bar's value as its label: 3 significant digits, "≥ " before a lower bound
std::string valueLabel(double y, bool lowerBound) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", y);
  return (lowerBound ? "≥ " : "") + std::string(buf);
}

// a PNG that ends: the signature first, the IEND chunk (length 0, type, CRC) last
bool wholePng(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in || in.tellg() < 20) return false;
  char tail[12], head[8];
  in.seekg(-12, std::ios::end);
  in.read(tail, 12);
  in.seekg(0);
  in.read(head, 8);
  return in && std::string(head, 8) == "\x89PNG\r\n\x1a\n" && std::string(tail, 8) == std::string("\0\0\0\0IEND", 8);
}

}  // namespace

std::string gnuplotScript(const Chart& chart, const std::string& pngPath) {
  std::ostringstream g;
  // UTF-8 labels (≥, ω); no enhanced text mode, so that '_' in method names stays an underscore
  g << "set encoding utf8\n";
  g << "set terminal pngcairo size " << chart.width << ',' << chart.height << " font 'DejaVu Sans,12' noenhanced\n";
  g << "set output " << quoted(pngPath) << "\n";
  g << "set title " << quoted(chart.title) << "\n";
  g << "set xlabel " << quoted(chart.xLabel) << "\nset ylabel " << quoted(chart.yLabel) << "\n";
  g << "set grid\n";
  bool turned = false;  // the bars' tick labels
  if (chart.bars) {
    // the key above the bars (at the right it would squeeze them), and room below for the tick
    // labels, which gnuplot does not leave for labels of several lines. Labels wider than their bars'
    // room (about 0.6 em a character of DejaVu at 12 pt, 16 px) are turned, so as not to run into
    // each other, and take more room below
    size_t lines = 1, longest = 0;
    for (const std::string& label : chart.barLabels) {
      size_t start = 0, count = 1;
      for (size_t end; (end = label.find('\n', start)) != std::string::npos; start = end + 1, ++count)
        longest = std::max(longest, end - start);
      longest = std::max(longest, label.size() - start);
      lines = std::max(lines, count);
    }
    const double room = 0.8 * chart.width / static_cast<double>(std::max<size_t>(1, chart.barLabels.size()));
    turned = 0.6 * 16.0 * static_cast<double>(longest) > room;
    const double below = static_cast<double>(lines) + 2.0 + (turned ? 0.25 * static_cast<double>(longest) : 0.0);
    g << "set key outside top center horizontal\nset bmargin " << std::lround(below) << "\n";
  } else {
    g << "set key outside right top\n";
  }
  if (!chart.note.empty()) g << "set label 1 " << quoted(chart.note) << " at graph 0.5, 0.5 center\n";
  if (chart.logX) g << "set logscale x\n";
  if (chart.logY) g << "set logscale y\n";
  // inline data blocks: no temporary data files
  for (size_t i = 0; i < chart.series.size(); ++i) {
    g << "$S" << i << " << EOD\n";
    for (const auto& [x, y] : chart.series[i].points) g << formatNumber(x) << ' ' << formatNumber(y) << "\n";
    g << "EOD\n";
  }
  if (chart.bars) {
    g << "set style fill solid 0.7\nset boxwidth 0.6\nset xtics " << (turned ? "rotate by 30 right " : "") << "(";
    for (size_t i = 0; i < chart.barLabels.size(); ++i) g << (i ? ", " : "") << quoted(chart.barLabels[i]) << ' ' << i;
    g << ")\nset xrange [-0.6:" << formatNumber(static_cast<double>(chart.barLabels.size()) - 0.4) << "]\n";
  }
  // each bar's value above it, as its own data block of x, y, text
  const bool values = chart.bars && chart.barValues;
  if (values)
    for (size_t i = 0; i < chart.series.size(); ++i) {
      g << "$V" << i << " << EOD\n";
      for (const auto& [x, y] : chart.series[i].points)
        if (std::isfinite(y))
          g << formatNumber(x) << ' ' << formatNumber(y) << ' ' << quoted(valueLabel(y, chart.series[i].lowerBounds)) << "\n";
      g << "EOD\n";
    }
  // room above the tallest bar for its label
  if (values) g << "set offsets 0, 0, graph 0.08, 0\n";
  g << "plot ";
  bool plotted = false;
  for (size_t i = 0; i < chart.series.size(); ++i) {
    const ChartSeries& s = chart.series[i];
    // gnuplot refuses to plot a block without points
    if (s.points.empty()) continue;
    const std::string style = !chart.bars     ? " using 1:2 with linespoints lw 2 pt 7"
                              : s.lowerBounds ? " using 1:2 with boxes fill pattern 4 border"
                                              : " using 1:2 with boxes";
    g << (plotted ? ", " : "") << "$S" << i << style << " title " << quoted(s.title);
    plotted = true;
  }
  if (values)
    for (size_t i = 0; i < chart.series.size(); ++i)
      if (!chart.series[i].points.empty()) g << ", $V" << i << " using 1:2:3 with labels offset 0,0.8 notitle";
  if (!plotted) g << "[1:10] [1:10] NaN notitle";
  g << "\n";
  return g.str();
}

void writeChart(const Chart& chart, const std::string& pngPath) {
  const std::string temporary = pngPath + ".part-" + std::to_string(::getpid()) + ".png";
  const ProcessResult r = runProgram({"gnuplot"}, gnuplotScript(chart, temporary));
  if (r.status != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("gnuplot failed drawing " + pngPath + " (status " + std::to_string(r.status) + "): " + r.errorTail);
  }
  if (!wholePng(temporary)) {
    std::remove(temporary.c_str());
    throw std::runtime_error(pngPath + ": gnuplot's PNG is cut short (is the disk full?); the previous chart is kept");
  }
  if (std::rename(temporary.c_str(), pngPath.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + pngPath);
  }
}

}  // namespace render::analysis
