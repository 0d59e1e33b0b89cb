#include "render/analysis/chart.h"

#include <unistd.h>

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "render/jobs/json_writer.h"
#include "render/jobs/process.h"

namespace render::analysis {
using namespace render::jobs;

namespace {

// a gnuplot string literal
std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

}  // namespace

std::string gnuplotScript(const Chart& chart, const std::string& pngPath) {
  std::ostringstream g;
  g << "set terminal pngcairo size 1280,800 font 'DejaVu Sans,12' noenhanced\n";
  g << "set output " << quoted(pngPath) << "\n";
  g << "set title " << quoted(chart.title) << "\n";
  g << "set xlabel " << quoted(chart.xLabel) << "\nset ylabel " << quoted(chart.yLabel) << "\n";
  g << "set grid\nset key outside right top\n";
  if (chart.logX) g << "set logscale x\n";
  if (chart.logY) g << "set logscale y\n";
  // inline data blocks: no temporary data files
  for (size_t i = 0; i < chart.series.size(); ++i) {
    g << "$S" << i << " << EOD\n";
    for (const auto& [x, y] : chart.series[i].points) g << formatNumber(x) << ' ' << formatNumber(y) << "\n";
    g << "EOD\n";
  }
  if (chart.bars) {
    g << "set style fill solid 0.7\nset boxwidth 0.6\nset xtics (";
    for (size_t i = 0; i < chart.barLabels.size(); ++i) g << (i ? ", " : "") << quoted(chart.barLabels[i]) << ' ' << i;
    g << ")\nset xrange [-0.6:" << formatNumber(static_cast<double>(chart.barLabels.size()) - 0.4) << "]\n";
  }
  g << "plot ";
  for (size_t i = 0; i < chart.series.size(); ++i)
    g << (i ? ", " : "") << "$S" << i << (chart.bars ? " using 1:2 with boxes" : " using 1:2 with linespoints lw 2 pt 7")
      << " title " << quoted(chart.series[i].title);
  if (chart.series.empty()) g << "NaN notitle";
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
  if (std::rename(temporary.c_str(), pngPath.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + pngPath);
  }
}

}  // namespace render::analysis
