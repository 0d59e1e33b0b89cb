#include "render/frame/dashed.h"

#include <algorithm>

namespace render::frame {
using sim::core::Vec2;

void dashedLine(const std::vector<Vec2>& points, bool closed, double dash, double gap, const render::draw::Pen& pen,
                render::draw::Canvas& draw) {
  if (!(dash > 0.0 && gap > 0.0)) return;
  double phase = 0.0;  // along the pattern: [0, dash) drawn, [dash, dash + gap) not
  const size_t n = points.size();
  for (size_t i = 0; i + (closed ? 0 : 1) < n; ++i) {
    const Vec2 a = points[i], b = points[(i + 1) % n];
    const double length = (b - a).norm();
    double at = 0.0;
    while (at < length) {
      const bool on = phase < dash;
      const double step = std::min(length - at, on ? dash - phase : dash + gap - phase);
      if (on && step > 0.0) draw.segment(a + (b - a) * (at / length), a + (b - a) * ((at + step) / length), pen);
      at += step;
      phase += step;
      if (phase >= dash + gap) phase = 0.0;
    }
  }
}

}  // namespace render::frame
