#include "render/draw/dot_layer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "render/draw/sample_resolve.h"
#include "render/jobs/interrupt.h"

namespace render::draw {

namespace {

// the samples a mask covers (the build targets no popcnt instruction, and libgcc's call is slower)
int covered(uint16_t mask) {
  static constexpr auto kBits = [] {
    std::array<uint8_t, 256> bits{};
    for (int i = 0; i < 256; ++i) bits[i] = static_cast<uint8_t>(std::popcount(static_cast<unsigned>(i)));
    return bits;
  }();
  return kBits[mask & 0xff] + kBits[mask >> 8];
}

// a pixel index clamped into [0, size] (as a double first: a dot may lie far off)
int lowPixel(double v, int size) { return static_cast<int>(std::clamp(std::floor(v), 0.0, static_cast<double>(size))); }
int highPixel(double v, int size) { return static_cast<int>(std::clamp(std::ceil(v), 0.0, static_cast<double>(size))); }

// GL's subpixel grid (llvmpipe snaps vertices to 1/256 px)
constexpr double kSubpixels = 256.0;
constexpr long long kSubpixelsInt = 256;
// dots and centers past this many pixels are tested unsnapped (no grid coordinate overflows)
constexpr double kLargestSnappedPx = 1 << 20;

// a regular polygon of circumradius 1: its corners at angles 2kπ / n, each edge's outward normal at
// (2k + 1)π / n, and its apothem
struct Edges {
  std::vector<sim::core::Vec2> corners, normals;
  double apothem = 0.0;
  explicit Edges(int n) : apothem(std::cos(std::numbers::pi / n)) {
    for (int k = 0; k < n; ++k) {
      corners.emplace_back(std::cos(2.0 * std::numbers::pi * k / n), std::sin(2.0 * std::numbers::pi * k / n));
      const double angle = (2 * k + 1) * std::numbers::pi / n;
      normals.emplace_back(std::cos(angle), std::sin(angle));
    }
  }
};

// a dot's polygon as llvmpipe rasterizes it: its corners snapped to the 1/256 px grid, a sample
// inside when strictly inside every edge, or on a left edge or a top one (in GL's window, y up):
// the top-left rule, which matched llvmpipe at every sample of 412 dots at 1, 2 and 4 samples a
// pixel (tests/render/draw/gl_canvas_test.cpp). In subpixels, x to the right, y down.
struct SnappedPolygon {
  static constexpr int kMostCorners = 16;
  // each edge (corner i to corner i + 1) as e(x, y) = a·y − b·x + c, positive inside, and whether a
  // sample where e = 0 is inside; the first n set, the rest left unset (zeroing them was most of a
  // dense frame's dots)
  std::array<long long, kMostCorners> a, b, c;
  std::array<bool, kMostCorners> tiesIn;
  int n = 0;

  SnappedPolygon(double x, double y, double radius, const Edges& unit) : n(static_cast<int>(unit.corners.size())) {
    // the corners, rounded half to even as llvmpipe's snap (adding and taking away 1.5 · 2⁵² rounds
    // a double under 2⁵¹ to the nearest whole number, ties to even, without a call to libm)
    constexpr double kRound = 6755399441055744.0;
    const auto snap = [](double v) { return static_cast<long long>((v * kSubpixels + kRound) - kRound); };
    std::array<std::array<long long, 2>, kMostCorners> p;
    for (int i = 0; i < n; ++i) p[i] = {snap(x + radius * unit.corners[i].x()), snap(y - radius * unit.corners[i].y())};
    long long area = 0;
    for (int i = 0; i < n; ++i) area += p[i][0] * p[(i + 1) % n][1] - p[(i + 1) % n][0] * p[i][1];
    const long long orientation = area >= 0 ? 1 : -1;
    for (int i = 0; i < n; ++i) {
      const auto &from = p[i], &to = p[(i + 1) % n];
      a[i] = (to[0] - from[0]) * orientation, b[i] = (to[1] - from[1]) * orientation;
      c[i] = b[i] * from[0] - a[i] * from[1];
      // the edge's inward normal (−b, a): to the right, a left edge; straight up on the frame (y
      // down), a top edge
      tiesIn[i] = -b[i] > 0 || (b[i] == 0 && a[i] < 0);
    }
  }
  bool covers(long long x, long long y) const {
    for (int i = 0; i < n; ++i) {
      const long long e = a[i] * y - b[i] * x + c[i];
      if (e < 0 || (e == 0 && !tiesIn[i])) return false;
    }
    return true;
  }
};

// the covered share of each pixel (`mask`: the run's box from (x0, y0), `width` wide; `touched`:
// each row's span), at `color`'s alpha, blended over what GL drew
void blendCovered(Image& frame, const Color& color, size_t samples, const std::vector<uint16_t>& mask,
                  const std::vector<std::pair<int, int>>& touched, int x0, int y0, int width) {
  const double alpha = std::clamp(color.a, 0.0, 1.0) / static_cast<double>(samples);
  const double rgb[3] = {255.0 * std::clamp(color.r, 0.0, 1.0), 255.0 * std::clamp(color.g, 0.0, 1.0),
                         255.0 * std::clamp(color.b, 0.0, 1.0)};
  for (size_t row = 0; row < touched.size(); ++row) {
    const int y = y0 + static_cast<int>(row);
    for (int x = touched[row].first; x < touched[row].second; ++x) {
      const uint16_t m = mask[row * static_cast<size_t>(width) + (x - x0)];
      if (m == 0) continue;
      const double cover = alpha * covered(m);
      uint8_t* p = frame.pixel(x, y);
      // rounded to the nearest (every value is at least 0)
      for (int ch = 0; ch < 3; ++ch) p[ch] = static_cast<uint8_t>(p[ch] + (rgb[ch] - p[ch]) * cover + 0.5);
    }
  }
}

}  // namespace

std::vector<SamplePosition> samplePositions(int samples, int supersample) {
  std::vector<std::array<float, 2>> at;
  if (samples == 4) at.assign(kSamplePositions.begin(), kSamplePositions.end());
  else if (samples == 2) at.assign(kTwoSamplePositions.begin(), kTwoSamplePositions.end());
  else at = {{0.5f, 0.5f}};
  const int s = std::max(1, supersample);
  if (static_cast<size_t>(s * s) * at.size() > 16) throw std::invalid_argument("samplePositions: more than 16 a pixel");
  std::vector<SamplePosition> out;
  // GL's positions are from a pixel's lower-left corner, y up; here from its top-left, y down
  for (int j = 0; j < s; ++j)
    for (int i = 0; i < s; ++i)
      for (const auto& p : at) out.push_back({(i + p[0]) / s, (j + 1.0 - p[1]) / s});
  return out;
}

void DotLayer::add(const sim::core::Vec2& center, double radius, int corners, const Color& color) {
  // a dot that covers no sample, or whose place or color is not a number, draws nothing
  if (!(radius > 0.0) || corners < 3 || !std::isfinite(center.x()) || !std::isfinite(center.y()) || !std::isfinite(radius))
    return;
  if (!std::isfinite(color.r) || !std::isfinite(color.g) || !std::isfinite(color.b) || !(color.a > 0.0)) return;
  dots_.push_back({center.x(), center.y(), radius, corners, color});
}

// the sample positions, in pixels and in subpixels (GL's are multiples of 1/8 px: exact), the
// polygons by their corners (a frame's dots share one), and the run's masks and spans, kept from
// run to run (a translucent dot is a run of its own)
struct DotLayer::Scratch {
  const std::vector<SamplePosition>& positions;
  std::vector<std::array<long long, 2>> subpixel;
  std::map<int, Edges> polygons;
  std::vector<uint16_t> mask;
  std::vector<std::pair<int, int>> touched;
};

void DotLayer::drawInto(Image& frame, const std::vector<SamplePosition>& positions) const {
  if (positions.empty() || positions.size() > 16) throw std::invalid_argument("DotLayer: 1 to 16 sample positions a pixel");
  Scratch scratch{positions, {}, {}, {}, {}};
  for (const SamplePosition& q : positions)
    scratch.subpixel.push_back({std::llround(q[0] * kSubpixels), std::llround(q[1] * kSubpixels)});
  size_t first = 0;
  // opaque dots of one color in a row cover a sample once, as GL's opaque fans do; a translucent
  // dot blends over what is under it, the dot before it too, as GL blends each translucent fan
  const auto sameOpaque = [](const Color& a, const Color& b) {
    return a.a >= 1.0 && a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
  };
  for (size_t i = 1; i <= dots_.size(); ++i) {
    if (i < dots_.size() && sameOpaque(dots_[i].color, dots_[first].color)) continue;
    drawRun(first, i, frame, scratch);
    first = i;
  }
}

void DotLayer::drawRun(size_t first, size_t last, Image& frame, Scratch& scratch) const {
  const std::vector<SamplePosition>& positions = scratch.positions;
  const std::vector<std::array<long long, 2>>& subpixel = scratch.subpixel;
  std::vector<uint16_t>& mask = scratch.mask;
  std::vector<std::pair<int, int>>& touched = scratch.touched;
  int x0 = frame.width, y0 = frame.height, x1 = 0, y1 = 0;
  for (size_t i = first; i < last; ++i) {
    const Dot& d = dots_[i];
    x0 = std::min(x0, lowPixel(d.x - d.radius, frame.width)), x1 = std::max(x1, highPixel(d.x + d.radius, frame.width));
    y0 = std::min(y0, lowPixel(d.y - d.radius, frame.height)), y1 = std::max(y1, highPixel(d.y + d.radius, frame.height));
  }
  if (x1 <= x0 || y1 <= y0) return;
  const int w = x1 - x0;
  mask.assign(static_cast<size_t>(w) * (y1 - y0), 0);
  const auto at = [&](int x, int y) -> uint16_t& { return mask[static_cast<size_t>(y - y0) * w + (x - x0)]; };
  // each row's touched pixels, so that blending visits the dots' pixels, not the run's whole box
  touched.assign(static_cast<size_t>(y1 - y0), {x1, x0});
  // the last dot's polygon at hand
  const Edges* edges = nullptr;
  int lastCorners = 0;
  const uint16_t all = static_cast<uint16_t>((1u << positions.size()) - 1);
  // each dot's samples joined into the run's: a sample under two dots is covered once
  for (size_t i = first; i < last; ++i) {
    // thousands of large dots take long: Ctrl-C ends them here (a flag read, no more)
    render::jobs::checkInterrupted();
    const Dot& d = dots_[i];
    if (d.corners != lastCorners)
      edges = &scratch.polygons.try_emplace(d.corners, d.corners).first->second, lastCorners = d.corners;
    // in units of the radius, so that no square overflows
    const double inv = 1.0 / d.radius, inner2 = edges->apothem * edges->apothem;
    // a dot on the frame's scale: its corners on GL's grid, its edges GL's, so that a sample on an
    // edge falls to the side GL gives it
    std::optional<SnappedPolygon> snapped;
    if (d.radius < kLargestSnappedPx && std::abs(d.x) < kLargestSnappedPx && std::abs(d.y) < kLargestSnappedPx &&
        d.corners <= SnappedPolygon::kMostCorners)
      snapped.emplace(d.x, d.y, d.radius, *edges);
    const int px0 = lowPixel(d.x - d.radius, frame.width), px1 = highPixel(d.x + d.radius, frame.width);
    const int py0 = lowPixel(d.y - d.radius, frame.height), py1 = highPixel(d.y + d.radius, frame.height);
    for (int y = py0; y < py1; ++y) {
      auto& [lo, hi] = touched[static_cast<size_t>(y - y0)];
      lo = std::min(lo, px0), hi = std::max(hi, px1);
      const double top = (y - d.y) * inv, bottom = (y + 1 - d.y) * inv;
      const double nearY = std::max({top, -bottom, 0.0}), farY = std::max(std::abs(top), std::abs(bottom));
      for (int x = px0; x < px1; ++x) {
        const double left = (x - d.x) * inv, right = (x + 1 - d.x) * inv;
        const double nearX = std::max({left, -right, 0.0}), farX = std::max(std::abs(left), std::abs(right));
        // outside the polygon's circle, or inside the circle within it
        if (nearX * nearX + nearY * nearY >= 1.0) continue;
        if (farX * farX + farY * farY < inner2) {
          at(x, y) = all;
          continue;
        }
        uint16_t m = 0;
        for (size_t s = 0; s < positions.size(); ++s) {
          bool inside = true;
          if (snapped) {
            inside = snapped->covers(x * kSubpixelsInt + subpixel[s][0], y * kSubpixelsInt + subpixel[s][1]);
          } else {
            const double qx = (x + positions[s][0] - d.x) * inv, qy = (y + positions[s][1] - d.y) * inv;
            for (const sim::core::Vec2& n : edges->normals) inside = inside && qx * n.x() + qy * n.y() < edges->apothem;
          }
          if (inside) m |= static_cast<uint16_t>(1u << s);
        }
        at(x, y) |= m;
      }
    }
  }
  blendCovered(frame, dots_[first].color, positions.size(), mask, touched, x0, y0, w);
}

}  // namespace render::draw
