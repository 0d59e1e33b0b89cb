#include "render/draw/triangle_raster.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

namespace render::draw {

namespace {

// llvmpipe's subpixel grid: 1/256 px
constexpr float kSubpixels = 256.0f;

// a coordinate in the window as GL's viewport transform gives it (one fused multiply-add), then
// snapped to the grid after the half-pixel offset, ties to even (llvmpipe's lrintf)
long long snapped(float clip, float scale, float translate) {
  const float window = std::fma(clip, scale, translate);
  return std::llrint(static_cast<float>(window - 0.5f) * kSubpixels);
}

// ⌊a / b⌋ and ⌈a / b⌉ for b > 0
long long floorDiv(long long a, long long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
long long ceilDiv(long long a, long long b) { return -floorDiv(-a, b); }

// a channel in [0, 1] as the framebuffer's byte
uint8_t unorm8(float c) { return static_cast<uint8_t>(std::nearbyint(std::clamp(c, 0.0f, 1.0f) * 255.0f)); }

// a · b / 255 in bytes as llvmpipe's blend computes it: (t + 128 + (t >> 8)) >> 8 for t = a b, which
// rounds a quotient just over a half (x.502) down where exact rounding goes up (measured against it
// over 2.1 million colour, alpha and background bytes: every one alike)
int blendProduct(int a, int b) {
  const int t = a * b;
  return (t + 128 + (t >> 8)) >> 8;
}

// the source over the frame's pixel with GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA (and for alpha GL_ONE,
// GL_ONE_MINUS_SRC_ALPHA), each channel a sum of two such products, saturated
void blendOver(const uint8_t source[4], uint8_t* pixel) {
  const int a = source[3], rest = 255 - a;
  for (int k = 0; k < 3; ++k)
    pixel[k] = static_cast<uint8_t>(std::min(255, blendProduct(source[k], a) + blendProduct(pixel[k], rest)));
  pixel[3] = static_cast<uint8_t>(std::min(255, a + blendProduct(pixel[3], rest)));
}

// one triangle's edges in fixed point, oriented so that the inside is to the left (e > 0)
struct Edges {
  long long px[3], py[3], dx[3], dy[3];
  bool tieIn[3];
  bool empty = false;

  Edges(const long long x[3], const long long y[3]) {
    const long long area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    empty = area == 0;
    const long long o = area > 0 ? 1 : -1;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      px[i] = x[i], py[i] = y[i];
      dx[i] = (x[j] - x[i]) * o, dy[i] = (y[j] - y[i]) * o;
      // GL's window y is up: a left edge runs down; a level edge on the inside's lower side (its
      // bottom here, the frame's top as stored) runs to the right
      tieIn[i] = dy[i] < 0 || (dy[i] == 0 && dx[i] > 0);
    }
  }

  // the pixels [lo, hi) of row `y` whose sample (at the pixel's grid point) is inside
  void span(long long y, long long& lo, long long& hi) const {
    const long long Y = y * static_cast<long long>(kSubpixels);
    for (int i = 0; i < 3; ++i) {
      // e(X) = dx (Y − py) − dy (X − px) ≥ t, t = 0 on a tie that is in, else 1
      const long long a = dx[i] * (Y - py[i]) + dy[i] * px[i], t = tieIn[i] ? 0 : 1;
      const long long step = static_cast<long long>(kSubpixels);
      if (dy[i] == 0) {
        if (a < t) hi = lo;
      } else if (dy[i] > 0) {
        hi = std::min(hi, floorDiv(a - t, dy[i] * step) + 1);
      } else {
        lo = std::max(lo, ceilDiv(t - a, -dy[i] * step));
      }
      if (hi <= lo) return;
    }
  }
};

}  // namespace

std::vector<TriangleVertex> probeTriangles(const RasterView& view, int width, int height) {
  // world coordinates whose corner snaps apart under the two roundings, next to sample k's column
  // (or row) k: searched from the value half a subpixel off the sample, a few ulps at a time
  const auto parted = [](float scale, float half, float translate, int k) -> std::optional<float> {
    for (const double side : {-1.0, 1.0}) {
      float x = static_cast<float>((k + 0.5 + side / 512.0 - translate) / half / scale);
      for (int n = 0; n < 64; ++n, x = std::nextafter(x, side > 0 ? 1e30f : -1e30f)) {
        const float clip = scale * x, product = clip * half;
        const long long fused = snapped(clip, half, translate), separate = std::llrint((product + translate - 0.5f) * kSubpixels);
        if (fused != separate && (fused % 256 == 0 || separate % 256 == 0)) return x;
      }
    }
    return std::nullopt;
  };
  std::vector<TriangleVertex> out;
  const auto triangle = [&](float x0, float y0, float x1, float y1, float x2, float y2, float shade) {
    for (const auto& [x, y] : {std::pair{x0, y0}, std::pair{x1, y1}, std::pair{x2, y2}})
      out.push_back({x, y, shade, 1.0f - shade, 0.7f, 1.0f});
  };
  // a pixel in world units, and the view's middle
  const float px = 1.0f / (view.scaleX * view.halfWidth), py = 1.0f / (view.scaleY * view.halfHeight);
  for (int k = 4; k + 4 < std::min(width, height); k += 7) {
    const std::optional<float> x = parted(view.scaleX, view.halfWidth, view.translateX, k);
    const std::optional<float> y = parted(view.scaleY, view.halfHeight, view.translateY, k);
    if (x)
      triangle(*x, -3 * py, *x, 3 * py, *x + 2 * px, 0.0f, 0.3f), triangle(*x, -2 * py, *x - 2 * px, 0.5f * py, *x, 2 * py, 0.7f);
    if (y)
      triangle(-3 * px, *y, 3 * px, *y, 0.0f, *y + 2 * py, 0.3f), triangle(-2 * px, *y, 0.5f * px, *y - 2 * py, 2 * px, *y, 0.7f);
  }
  // blending: translucent triangles over an opaque one, in a quarter of the view the edges above
  // keep clear, on bytes where llvmpipe's products and exact rounding part (194 under 0 at alpha 23:
  // 176, not 177; 247 under 10 at alpha 16: 232, not 233). A view too small for them (or for the
  // edges) has no probe: its frames are GL's
  const float side = 8.0f;
  if (out.empty() || view.halfWidth < 4.0f * side || view.halfHeight < 4.0f * side) return {};
  const float cx = 0.5f * view.halfWidth * px, cy = 0.5f * view.halfHeight * py;
  const auto colored = [&](float x0, float y0, float x1, float y1, float x2, float y2, const std::array<float, 4>& c) {
    for (const auto& [x, y] : {std::pair{x0, y0}, std::pair{x1, y1}, std::pair{x2, y2}})
      out.push_back({x, y, c[0], c[1], c[2], c[3]});
  };
  const std::array<float, 4> under{194 / 255.0f, 247 / 255.0f, 0.5f, 1.0f};
  colored(cx - side * px, cy - side * py, cx + side * px, cy - side * py, cx, cy + side * py, under);
  colored(cx - side * px, cy - side * py, cx, cy - side * py, cx - 0.5f * side * px, cy + side * py,
          {0.0f, 0.0f, 0.0f, 23 / 255.0f});
  colored(cx, cy - side * py, cx + side * px, cy - side * py, cx + 0.5f * side * px, cy + side * py,
          {0.0f, 10 / 255.0f, 1.0f, 16 / 255.0f});
  return out;
}

bool rasterizesAlike(const TriangleVertex* v, size_t count, float scaleX, float scaleY) {
  if (count % 3 != 0) return false;
  for (size_t i = 0; i < count; ++i) {
    const TriangleVertex& p = v[i];
    const TriangleVertex& first = v[i - i % 3];
    if (p.r != first.r || p.g != first.g || p.b != first.b || p.a != first.a) return false;
    // (the comparisons fail for a NaN: such a vertex is GL's to draw)
    if (!(std::abs(scaleX * p.x) <= 1.0f && std::abs(scaleY * p.y) <= 1.0f)) return false;
  }
  return true;
}

void rasterTriangles(const TriangleVertex* v, size_t count, const RasterView& view, const RasterTarget& target, uint32_t* stamps,
                     uint32_t group) {
  const int width = target.x1 - target.x0;
  if (width <= 0 || target.y1 <= target.y0) return;
  for (size_t i = 0; i + 3 <= count; i += 3) {
    long long x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = snapped(view.scaleX * v[i + k].x, view.halfWidth, view.translateX);
      y[k] = snapped(view.scaleY * v[i + k].y, view.halfHeight, view.translateY);
    }
    const Edges edges(x, y);
    if (edges.empty) continue;
    const uint8_t color[4] = {unorm8(v[i].r), unorm8(v[i].g), unorm8(v[i].b), unorm8(v[i].a)};
    // (an opaque one is written as GL draws it, blending off: the same bytes as blended at alpha 1)
    const bool opaque = v[i].a >= 1.0f;
    uint32_t pixel;
    std::memcpy(&pixel, color, sizeof pixel);
    const long long step = static_cast<long long>(kSubpixels);
    const long long rowLo = std::max<long long>(target.y0, ceilDiv(*std::min_element(y, y + 3), step));
    const long long rowHi = std::min<long long>(target.y1, floorDiv(*std::max_element(y, y + 3), step) + 1);
    const long long colLo = std::max<long long>(target.x0, ceilDiv(*std::min_element(x, x + 3), step));
    const long long colHi = std::min<long long>(target.x1, floorDiv(*std::max_element(x, x + 3), step) + 1);
    for (long long row = rowLo; row < rowHi; ++row) {
      long long lo = colLo, hi = colHi;
      edges.span(row, lo, hi);
      if (hi <= lo) continue;
      const size_t at = static_cast<size_t>(target.y1 - 1 - row) * width + static_cast<size_t>(lo - target.x0);
      uint8_t* out = target.rows + at * 4;
      if (stamps) {
        // (the stencil test: a sample this primitive drew already is not drawn again)
        for (uint32_t* stamp = stamps + at; lo < hi; ++lo, out += 4, ++stamp) {
          if (*stamp == group) continue;
          *stamp = group;
          if (opaque) std::memcpy(out, &pixel, sizeof pixel);
          else blendOver(color, out);
        }
      } else if (opaque)
        for (long long c = lo; c < hi; ++c, out += 4) std::memcpy(out, &pixel, sizeof pixel);
      else
        for (long long c = lo; c < hi; ++c, out += 4) blendOver(color, out);
    }
  }
}

}  // namespace render::draw
