#include "render/draw/dot_layer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "render/jobs/interrupt.h"

namespace render::draw {

namespace {

// the 4 × 4 sample positions' offsets within a pixel, in either direction
constexpr double kGrid[4] = {0.125, 0.375, 0.625, 0.875};

// the samples a mask covers (the build targets no popcnt instruction, and libgcc's call is slower)
int covered(uint16_t mask) {
  static constexpr auto kBits = [] {
    std::array<uint8_t, 256> bits{};
    for (int i = 0; i < 256; ++i) bits[i] = static_cast<uint8_t>(std::popcount(static_cast<unsigned>(i)));
    return bits;
  }();
  return kBits[mask & 0xff] + kBits[mask >> 8];
}

}  // namespace

void DotLayer::add(const sim::core::Vec2& center, double radius, const Color& color) {
  // a dot that covers no sample, or whose place is not a number, draws nothing
  if (!(radius > 0.0) || !std::isfinite(center.x()) || !std::isfinite(center.y()) || !std::isfinite(radius)) return;
  dots_.push_back({center.x(), center.y(), radius, color});
}

void DotLayer::drawInto(Image& frame) const {
  std::vector<uint16_t> mask;
  size_t first = 0;
  for (size_t i = 1; i <= dots_.size(); ++i) {
    const auto sameColor = [&](const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; };
    if (i < dots_.size() && sameColor(dots_[i].color, dots_[first].color)) continue;
    drawRun(first, i, frame, mask);
    first = i;
  }
}

void DotLayer::drawRun(size_t first, size_t last, Image& frame, std::vector<uint16_t>& mask) const {
  // the pixels the run's dots may touch, within the frame (clamped as doubles: a dot may lie far off)
  const auto lowPixel = [](double v, int size) {
    return static_cast<int>(std::clamp(std::floor(v), 0.0, static_cast<double>(size)));
  };
  const auto highPixel = [](double v, int size) {
    return static_cast<int>(std::clamp(std::ceil(v), 0.0, static_cast<double>(size)));
  };
  int x0 = frame.width, y0 = frame.height, x1 = 0, y1 = 0;
  for (size_t i = first; i < last; ++i) {
    const Dot& d = dots_[i];
    x0 = std::min(x0, lowPixel(d.x - d.radius, frame.width)), x1 = std::max(x1, highPixel(d.x + d.radius, frame.width));
    y0 = std::min(y0, lowPixel(d.y - d.radius, frame.height)), y1 = std::max(y1, highPixel(d.y + d.radius, frame.height));
  }
  if (x1 <= x0 || y1 <= y0) return;
  const int w = x1 - x0;
  mask.assign(static_cast<size_t>(w) * (y1 - y0), 0);
  // each row's touched pixels, so that blending visits the dots' pixels, not the run's whole box
  std::vector<std::pair<int, int>> touched(static_cast<size_t>(y1 - y0), {x1, x0});
  // each dot's samples joined into the run's: a sample under two dots is covered once
  for (size_t i = first; i < last; ++i) {
    // thousands of large dots take long: Ctrl-C ends them here (a flag read, no more)
    render::jobs::checkInterrupted();
    const Dot& d = dots_[i];
    const double r2 = d.radius * d.radius;
    const int px0 = lowPixel(d.x - d.radius, frame.width), px1 = highPixel(d.x + d.radius, frame.width);
    const int py0 = lowPixel(d.y - d.radius, frame.height), py1 = highPixel(d.y + d.radius, frame.height);
    for (int y = py0; y < py1; ++y) {
      auto& [lo, hi] = touched[static_cast<size_t>(y - y0)];
      lo = std::min(lo, px0), hi = std::max(hi, px1);
      // the circle's half width at each of the pixel's four sample rows (negative: none there)
      double chord[4];
      for (int j = 0; j < 4; ++j) {
        const double dy = y + kGrid[j] - d.y;
        chord[j] = r2 > dy * dy ? std::sqrt(r2 - dy * dy) : -1.0;
      }
      // the pixels of the row the disc covers whole: within its half width at the row's farther edge
      const double farDy = std::max(std::abs(y - d.y), std::abs(y + 1 - d.y));
      const double inner = r2 > farDy * farDy ? std::sqrt(r2 - farDy * farDy) : -1.0;
      uint16_t* row = mask.data() + static_cast<size_t>(y - y0) * w - x0;
      for (int x = px0; x < px1; ++x) {
        if (x >= d.x - inner && x + 1 <= d.x + inner) {
          row[x] = 0xffff;
          continue;
        }
        uint16_t m = 0;
        for (int j = 0; j < 4; ++j)
          for (int k = 0; k < 4; ++k)
            if (std::abs(x + kGrid[k] - d.x) < chord[j]) m |= static_cast<uint16_t>(1u << (4 * j + k));
        row[x] |= m;
      }
    }
  }
  // the covered share of each pixel, at the run's alpha, blended over what GL drew
  const Color& c = dots_[first].color;
  const double alpha = std::clamp(c.a, 0.0, 1.0) / 16.0;
  const double color[3] = {255.0 * std::clamp(c.r, 0.0, 1.0), 255.0 * std::clamp(c.g, 0.0, 1.0),
                           255.0 * std::clamp(c.b, 0.0, 1.0)};
  for (int y = y0; y < y1; ++y) {
    const auto [lo, hi] = touched[static_cast<size_t>(y - y0)];
    const uint16_t* row = mask.data() + static_cast<size_t>(y - y0) * w - x0;
    for (int x = lo; x < hi; ++x) {
      if (row[x] == 0) continue;
      const double cover = alpha * covered(row[x]);
      uint8_t* p = frame.pixel(x, y);
      // rounded to the nearest (every value is at least 0)
      for (int ch = 0; ch < 3; ++ch) p[ch] = static_cast<uint8_t>(p[ch] + (color[ch] - p[ch]) * cover + 0.5);
    }
  }
}

}  // namespace render::draw
