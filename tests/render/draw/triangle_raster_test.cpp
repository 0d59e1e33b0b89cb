// Triangles drawn in software: every sample the same as llvmpipe's, at each of the four sample
// positions, for triangles of every size and slant, level and upright edges on the sample rows and
// columns included, translucent ones blended as llvmpipe blends; and what is left to GL
// (two-coloured, outside the view).
#include "render/draw/triangle_raster.h"

#include <doctest/doctest.h>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <random>
#include <tuple>
#include <vector>

#include "render/draw/gl_context.h"
#include "render/draw/sample_resolve.h"

using namespace render::draw;

namespace {

constexpr int kWidth = 320, kHeight = 200;
constexpr double kHalfWidth = 8.37, kHalfHeight = kHalfWidth * kHeight / kWidth;

// glOrtho's x and y scales, as Mesa holds them (floats)
float orthoScale(double half) { return 2.0f / (static_cast<float>(half) - static_cast<float>(-half)); }

struct Drawn {
  std::vector<uint8_t> gl, software;
};

// `triangles` drawn by GL and in software at sample position `at`, over a background (with
// `blend`, blended as GlCanvas blends: GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)
Drawn drawBoth(const std::vector<TriangleVertex>& triangles, const std::array<float, 2>& at, bool blend = false) {
  Drawn d;
  if (blend) {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  glViewportIndexedf(0, 0.5f - at[0], 0.5f - at[1], static_cast<float>(kWidth), static_cast<float>(kHeight));
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  for (const TriangleVertex& v : triangles) {
    glColor4d(v.r, v.g, v.b, v.a);
    glVertex2d(v.x, v.y);
  }
  glEnd();
  glDisable(GL_BLEND);
  d.gl.resize(static_cast<size_t>(kWidth) * kHeight * 4);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, d.gl.data());
  d.software.assign(d.gl.size(), 0);
  for (size_t p = 3; p < d.software.size(); p += 4) d.software[p] = 255;
  RasterView view;
  view.scaleX = orthoScale(kHalfWidth), view.scaleY = orthoScale(kHalfHeight);
  view.halfWidth = kWidth / 2.0f, view.halfHeight = kHeight / 2.0f;
  view.translateX = 0.5f - at[0] + kWidth / 2.0f, view.translateY = 0.5f - at[1] + kHeight / 2.0f;
  rasterTriangles(triangles.data(), triangles.size(), view, {d.software.data(), 0, 0, kWidth, kHeight});
  return d;
}

// a GL context drawing 2D as GlCanvas does: the orthographic view, no blending, depth or culling
struct Context {
  GlContext gl{kWidth, kHeight, Antialiasing{1, 1, false}};
  Context() {
    gl.makeCurrent();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-kHalfWidth, kHalfWidth, -kHalfHeight, kHalfHeight, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
  }
};

// random triangles' places and colours, in the view
struct Randoms {
  std::mt19937 rng;
  std::uniform_real_distribution<float> centerX{-7.5f, 7.5f}, centerY{-4.5f, 4.5f}, offset{-0.6f, 0.6f}, channel{0.0f, 1.0f};
  explicit Randoms(unsigned seed) : rng(seed) {}
  float x() { return centerX(rng); }
  float y() { return centerY(rng); }
  float off() { return offset(rng); }
  float c() { return channel(rng); }
};

long differingPixels(const Drawn& d) {
  long n = 0;
  for (size_t p = 0; p < d.gl.size(); p += 4) n += std::memcmp(&d.gl[p], &d.software[p], 4) != 0;
  return n;
}

// GL's pixels that are not the black background
long coveredPixels(const Drawn& d) {
  long n = 0;
  for (size_t p = 0; p < d.gl.size(); p += 4) n += d.gl[p] != 0 || d.gl[p + 1] != 0 || d.gl[p + 2] != 0;
  return n;
}

// drawings made both ways, their pixels that differ and those GL covered
struct Tally {
  long drawings = 0, differing = 0, covered = 0;
  void add(const Drawn& d) { ++drawings, differing += differingPixels(d), covered += coveredPixels(d); }
};

}  // namespace

TEST_CASE("random opaque triangles: every sample llvmpipe's, at each of the four sample positions") {
  Context context;
  Randoms pick(11);
  Tally tally;
  for (int t = 0; t < 600; ++t) {
    // small (a pixel or two), box-sized, large; some with a level or an upright edge
    const float size = t % 3 == 0 ? 0.05f : t % 3 == 1 ? 1.0f : 6.0f;
    const float cx = pick.x(), cy = pick.y();
    std::vector<TriangleVertex> triangles;
    const float r = pick.c(), g = pick.c(), b = pick.c();
    for (int k = 0; k < 3; ++k) triangles.push_back({cx + size * pick.off(), cy + size * pick.off(), r, g, b, 1.0f});
    if (t % 4 == 0) triangles[1].y = triangles[0].y;
    if (t % 4 == 1) triangles[1].x = triangles[0].x;
    // a second triangle over the first, sharing an edge: the samples on it go to one of them
    for (int k = 0; k < 2; ++k) triangles.push_back({triangles[k].x, triangles[k].y, g, b, r, 1.0f});
    triangles.push_back({cx + size * pick.off(), cy + size * pick.off(), g, b, r, 1.0f});
    if (!rasterizesAlike(triangles.data(), triangles.size(), orthoScale(kHalfWidth), orthoScale(kHalfHeight))) continue;
    for (const auto& at : kSamplePositions) tally.add(drawBoth(triangles, at));
  }
  CHECK(tally.drawings > 1500);
  CHECK(tally.covered > 100000);
  CHECK(tally.differing == 0);
}

// a colour, alpha and background byte where llvmpipe's blend and exact rounding part (the source's
// share 0, the background's 194 · 232 / 255 = 176.502: llvmpipe 176) are among those drawn
TEST_CASE("random translucent triangles over opaque ones: blended as llvmpipe blends, every sample") {
  Context context;
  Randoms pick(17);
  Tally tally;
  for (int t = 0; t < 400; ++t) {
    const float size = t % 2 == 0 ? 1.0f : 6.0f;
    const float cx = pick.x(), cy = pick.y();
    std::vector<TriangleVertex> triangles;
    // an opaque one, then two translucent ones over it: any alpha, and bytes alpha may take
    const float r = pick.c(), g = pick.c(), b = pick.c();
    for (int k = 0; k < 3; ++k) triangles.push_back({cx + size * pick.off(), cy + size * pick.off(), r, g, b, 1.0f});
    for (int layer = 0; layer < 2; ++layer) {
      const float a = layer == 0 ? pick.c() : static_cast<float>(std::uniform_int_distribution<int>(1, 254)(pick.rng)) / 255.0f;
      const float tr = pick.c(), tg = pick.c(), tb = pick.c();
      for (int k = 0; k < 3; ++k) triangles.push_back({cx + size * pick.off(), cy + size * pick.off(), tr, tg, tb, a});
    }
    if (t == 0) {
      // the parting case, over the whole view
      triangles = {{-8, -5, 194 / 255.0f, 0, 0, 1}, {8, -5, 194 / 255.0f, 0, 0, 1}, {0, 5, 194 / 255.0f, 0, 0, 1},
                   {-8, -5, 0, 0, 0, 23 / 255.0f},  {8, -5, 0, 0, 0, 23 / 255.0f},  {0, 5, 0, 0, 0, 23 / 255.0f}};
    }
    // (a triangle reaching out of the view is clipped by GL: not drawn so)
    if (!rasterizesAlike(triangles.data(), triangles.size(), orthoScale(kHalfWidth), orthoScale(kHalfHeight))) continue;
    for (const auto& at : kSamplePositions) {
      const Drawn d = drawBoth(triangles, at, true);
      tally.add(d);
      if (t == 0) CHECK(d.gl[4 * (kWidth * kHeight / 2 + kWidth / 2)] == 176);
    }
  }
  CHECK(tally.drawings > 1000);
  CHECK(tally.covered > 100000);
  CHECK(tally.differing == 0);
}

TEST_CASE("triangles on the sample grid: level and upright edges through samples go as GL's") {
  Context context;
  // a pixel is 2 kHalfWidth / kWidth world units; edges exactly on pixel centers at sample 0.5
  const float px = static_cast<float>(2 * kHalfWidth / kWidth);
  long differing = 0;
  for (int i = 0; i < 40; ++i) {
    const float x0 = (i - 20) * 3.0f * px, y0 = (i % 7 - 3) * 5.0f * px;
    const std::vector<TriangleVertex> box = {{x0, y0, 1, 1, 1, 1},
                                             {x0 + 9 * px, y0, 1, 1, 1, 1},
                                             {x0 + 9 * px, y0 + 7 * px, 1, 1, 1, 1},
                                             {x0, y0, 0.5f, 0.2f, 0.9f, 1},
                                             {x0 + 9 * px, y0 + 7 * px, 0.5f, 0.2f, 0.9f, 1},
                                             {x0, y0 + 7 * px, 0.5f, 0.2f, 0.9f, 1}};
    for (const auto& at : kSamplePositions) differing += differingPixels(drawBoth(box, at));
    differing += differingPixels(drawBoth(box, {0.5f, 0.5f}));
  }
  CHECK(differing == 0);
}

// GL's viewport transform is one fused multiply-add: where that and a multiply then an add snap a
// corner to different subpixels, one of them a sample's column, the triangle's upright edge through
// the sample goes as the fused one puts it
TEST_CASE("an upright edge where fused and separate roundings part: GL's is the fused one") {
  Context context;
  const float sx = orthoScale(kHalfWidth), half = kWidth / 2.0f;
  const auto at = kSamplePositions[0];
  const float translate = 0.5f - at[0] + half;
  const auto snap = [](float window) { return std::llrint(static_cast<float>(window - 0.5f) * 256.0f); };
  std::vector<float> parted;
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> column(10, kWidth - 10);
  std::uniform_int_distribution<int> nudge(-40, 40);
  for (int tries = 0; tries < 2000000 && parted.size() < 24; ++tries) {
    // a vertex near where a corner's snap to a sample's column rounds (half a subpixel off it),
    // nudged by ulps
    const double target = (column(rng) + 0.5 + (tries % 2 ? 1.0 : -1.0) / 512.0 - translate) / half / sx;
    float x = static_cast<float>(target);
    for (int n = nudge(rng); n != 0; n += n > 0 ? -1 : 1) x = std::nextafter(x, n > 0 ? 1e9f : -1e9f);
    const float clip = sx * x;
    const long long fused = snap(std::fma(clip, half, translate));
    const volatile float product = clip * half;
    const long long separate = snap(product + translate);
    if (fused != separate && (fused % 256 == 0 || separate % 256 == 0)) parted.push_back(x);
  }
  REQUIRE(parted.size() >= 8);
  long differing = 0;
  for (const float x : parted) {
    // upright edges at x, the triangle to the right of one and to the left of the other
    const std::vector<TriangleVertex> triangles = {{x, -2.0f, 1, 1, 1, 1},
                                                   {x, 2.0f, 1, 1, 1, 1},
                                                   {x + 0.5f, 0.0f, 1, 1, 1, 1},
                                                   {x, -1.0f, 0.3f, 0.6f, 0.9f, 1},
                                                   {x - 0.4f, 0.5f, 0.3f, 0.6f, 0.9f, 1},
                                                   {x, 1.5f, 0.3f, 0.6f, 0.9f, 1}};
    differing += differingPixels(drawBoth(triangles, at));
  }
  CHECK(differing == 0);
}

TEST_CASE("what software does not draw as GL does is left to GL") {
  const float sx = orthoScale(kHalfWidth), sy = orthoScale(kHalfHeight);
  std::vector<TriangleVertex> t = {{0, 0, 1, 0, 0, 1}, {1, 0, 1, 0, 0, 1}, {0, 1, 1, 0, 0, 1}};
  CHECK(rasterizesAlike(t.data(), t.size(), sx, sy));
  // translucent: blended alike
  for (TriangleVertex& v : t) v.a = 0.5f;
  CHECK(rasterizesAlike(t.data(), t.size(), sx, sy));
  // two alphas (GL would blend them across the triangle)
  t[2].a = 1.0f;
  CHECK_FALSE(rasterizesAlike(t.data(), t.size(), sx, sy));
  for (TriangleVertex& v : t) v.a = 1.0f;
  // two colours (GL would blend them across the triangle)
  t[1].g = 0.5f;
  CHECK_FALSE(rasterizesAlike(t.data(), t.size(), sx, sy));
  t[1].g = 0.0f;
  // a corner outside the view: GL clips it into other triangles
  t[1].x = static_cast<float>(kHalfWidth) * 1.01f;
  CHECK_FALSE(rasterizesAlike(t.data(), t.size(), sx, sy));
  t[1].x = 1.0f;
  // not a number
  t[0].y = std::nanf("");
  CHECK_FALSE(rasterizesAlike(t.data(), t.size(), sx, sy));
  t[0].y = 0.0f;
  // not whole triangles
  CHECK_FALSE(rasterizesAlike(t.data(), 2, sx, sy));
  CHECK(rasterizesAlike(t.data(), 3, sx, sy));
}

// GlContext draws its probe once with GL and in software, and draws frames in software only if they
// agree: the probe has edges on sample columns and rows in plenty, and blends where llvmpipe's
// products and exact rounding part; here they agree
TEST_CASE("the probe's triangles: many, on samples' columns and rows, drawn alike by GL and software") {
  Context context;
  RasterView view;
  view.scaleX = orthoScale(kHalfWidth), view.scaleY = orthoScale(kHalfHeight);
  view.halfWidth = view.translateX = kWidth / 2.0f, view.halfHeight = view.translateY = kHeight / 2.0f;
  const std::vector<TriangleVertex> probe = probeTriangles(view, kWidth, kHeight);
  CHECK(probe.size() >= 3 * 40);
  CHECK(rasterizesAlike(probe.data(), probe.size(), view.scaleX, view.scaleY));
  // its corners are where the two roundings part: a separate multiply and add would snap them elsewhere
  long parted = 0;
  for (const TriangleVertex& v : probe)
    for (const auto& [clip, half, translate] : {std::tuple{view.scaleX * v.x, view.halfWidth, view.translateX},
                                                std::tuple{view.scaleY * v.y, view.halfHeight, view.translateY}}) {
      const volatile float product = clip * half;
      const float separate = product + translate, fused = std::fma(clip, half, translate);
      parted += std::llrint((separate - 0.5f) * 256.0f) != std::llrint((fused - 0.5f) * 256.0f);
    }
  CHECK(parted >= 40);
  const Drawn d = drawBoth(probe, {0.5f, 0.5f}, true);
  long parting = 0;
  // 194 under black at alpha 23, and 247 under 10 at alpha 16: exact rounding gives 177 and 233
  for (size_t p = 0; p < d.gl.size(); p += 4)
    parting += (d.gl[p] == 176 && d.gl[p + 2] == 116) || (d.gl[p + 1] == 232 && d.gl[p + 2] == 136);
  CHECK(coveredPixels(d) > 200);
  CHECK(parting > 20);
  CHECK(differingPixels(d) == 0);
  // a view too small to hold them has no probe (its frames are GL's): GL would clip the blending ones
  RasterView small = view;
  small.halfWidth = small.translateX = 30.0f, small.halfHeight = small.translateY = 30.0f;
  CHECK(probeTriangles(small, 60, 60).empty());
  small.halfWidth = small.translateX = small.halfHeight = small.translateY = 40.0f;
  CHECK_FALSE(probeTriangles(small, 80, 80).empty());
}

// a channel at an exact half (0.3 × 255 = 76.5, 0.7 × 255 = 178.5 in floats) goes to the even byte,
// as GL's does
TEST_CASE("colour channels at exact halves round to even, as GL's") {
  Context context;
  CHECK(0.3f * 255.0f == 76.5f);
  CHECK(0.7f * 255.0f == 178.5f);
  const std::vector<TriangleVertex> triangle = {
      {-2.0f, -2.0f, 0.3f, 0.7f, 0.5f, 1.0f}, {2.0f, -2.0f, 0.3f, 0.7f, 0.5f, 1.0f}, {0.0f, 2.0f, 0.3f, 0.7f, 0.5f, 1.0f}};
  const Drawn d = drawBoth(triangle, {0.5f, 0.5f});
  const size_t middle = (static_cast<size_t>(kHeight / 2) * kWidth + kWidth / 2) * 4;
  CHECK(d.gl[middle] == 76);
  CHECK(d.gl[middle + 1] == 178);
  CHECK(d.gl[middle + 2] == 128);
  CHECK(differingPixels(d) == 0);
}
