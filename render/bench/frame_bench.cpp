// rigidreel_frame_bench: the measurements behind two choices, never asserted in tests.
//   anti-aliasing: milliseconds per 1280×720 frame and the mean error on edge pixels (0-255)
//     against a 4×4-supersampled, 4×-multisampled reference, for none, multisampling and
//     supersampling (gl_context.cpp keeps the better);
//   PNG: milliseconds and bytes per frame for zlib levels, row filters and strategies
//     (png_io.cpp keeps the better).
// usage: build/rigidreel_frame_bench   (after cmake --build build --target rigidreel_frame_bench)
#include <png.h>
#include <zlib.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "render/draw/gl_canvas.h"
#include "render/draw/png_io.h"

namespace {

using namespace render::draw;
using sim::core::Vec2;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

render::draw::Style style() {
  // the table's default colors, three bodies
  render::draw::Style s;
  s.background = Color::parse("#ffffff");
  s.bodies = {Color::parse("#4e79a7"), Color::parse("#f28e2b"), Color::parse("#8c8c8c")};
  s.fontSize = 20;
  return s;
}

// a lecture frame: a tilted plane, a hatched box, a turning box, a translucent polygon, a wheel,
// a contact with its normal, arrows and labels; `turn` moves things between frames
void scene(render::draw::GlCanvas& c, const render::draw::Camera& camera, double turn) {
  const auto at = [&](Vec2 p, Vec2 o) {
    return Vec2(o.x() + std::cos(turn) * p.x() - std::sin(turn) * p.y(), o.y() + std::sin(turn) * p.x() + std::cos(turn) * p.y());
  };
  c.begin(camera);
  c.halfPlane({0, -0.5}, {0.05, 1}, {Role::StaticBody, 2, 1});
  c.polygon({{-2.5, 0.2}, {-1.5, 0.2}, {-1.5, 1.2}, {-2.5, 1.2}}, {Role::StaticBody, 2, 1});
  c.polygon({at({-.5, -.5}, {-.5, 0}), at({.5, -.5}, {-.5, 0}), at({.5, .5}, {-.5, 0}), at({-.5, .5}, {-.5, 0})},
            {Role::Body, 0, 1});
  c.polygon({{0.1, 0.3}, {1.0, 0.0}, {1.3, 0.9}, {0.4, 1.2}}, {Role::Body, 1, 0.5});
  c.circle({1.8, 1.5}, 0.4, {Role::Body, 0, 1});
  c.segment({1.8, 1.5}, at({0.4, 0}, {1.8, 1.5}), {Role::BodyAxis, 0, 1});
  c.point({0, 0.3}, {Role::ContactPoint, -1, 1});
  c.arrow({0, 0.3}, {0.5, 0.35}, {Role::ContactNormal, -1, 1});
  c.arrow({-2, 2.5}, {-1.2, 2.0}, {Role::Impulse, -1, 1});
  c.arrow({1.8, 1.5}, {2.6, 2.2}, {Role::Velocity, 0, 1});
  c.text({-0.5, 0}, "box", {Role::Label, 0, 1});
  c.text(camera.toWorld({10, 10}), "t = 0.300 s", {Role::Caption, -1, 1});
}

}  // namespace

int main() {
  constexpr int kWidth = 1280, kHeight = 720, kFrames = 30;
  const render::draw::Style s = style();
  render::draw::TextRenderer text;
  const render::draw::Camera camera({0, 1}, 4.0, kWidth, kHeight);

  std::printf("anti-aliasing, %dx%d, mean of %d frames:\n", kWidth, kHeight, kFrames);
  Image reference;
  {
    render::draw::GlContext gl(kWidth, kHeight, {4, 4});
    render::draw::GlCanvas c(gl, text, s);
    scene(c, camera, 0.3);
    reference = c.finish();
  }
  Image sample;
  for (const render::draw::Antialiasing aa :
       {render::draw::Antialiasing{1, 1}, render::draw::Antialiasing{1, 4}, render::draw::Antialiasing{2, 1},
        render::draw::Antialiasing{3, 1}, render::draw::Antialiasing{2, 4}}) {
    render::draw::GlContext gl(kWidth, kHeight, aa);
    render::draw::GlCanvas c(gl, text, s);
    scene(c, camera, 0.3);
    const Image image = c.finish();
    if (aa.supersample == 1 && aa.samples == 4) sample = image;
    const auto start = Clock::now();
    for (int i = 0; i < kFrames; ++i) {
      scene(c, camera, 0.01 * i);
      (void)c.finish();
    }
    const double ms = msSince(start) / kFrames;
    // edge pixels: where the reference changes from one pixel to the next
    double error = 0.0;
    long edges = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x + 1 < kWidth; ++x) {
        const uint8_t *p = reference.pixel(x, y), *q = reference.pixel(x + 1, y), *a = image.pixel(x, y);
        if (std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) <= 6) continue;
        ++edges;
        for (int k = 0; k < 3; ++k) error += std::abs(a[k] - p[k]) / 3.0;
      }
    std::printf("  %d×%d supersampling, %d× multisampling: %6.1f ms, edge error %5.2f\n", aa.supersample, aa.supersample,
                aa.samples, ms, error / edges);
  }

  std::printf("PNG of that frame (4× multisampled), mean of %d encodings:\n", kFrames);
  struct Setting {
    const char* name;
    render::draw::PngSettings png;
  };
  for (const Setting& setting : {Setting{"libpng's default: level 6, all filters, Z_FILTERED", {6, PNG_ALL_FILTERS, Z_FILTERED}},
                                 Setting{"level 9, no filter", {9, PNG_FILTER_NONE, Z_DEFAULT_STRATEGY}},
                                 Setting{"level 6, no filter", {6, PNG_FILTER_NONE, Z_DEFAULT_STRATEGY}},
                                 Setting{"level 3, no filter", {3, PNG_FILTER_NONE, Z_DEFAULT_STRATEGY}},
                                 Setting{"level 1, no filter", {1, PNG_FILTER_NONE, Z_DEFAULT_STRATEGY}},
                                 Setting{"level 1, sub", {1, PNG_FILTER_SUB, Z_DEFAULT_STRATEGY}},
                                 Setting{"level 1, up, Z_RLE", {1, PNG_FILTER_UP, Z_RLE}}}) {
    size_t bytes = 0;
    const auto start = Clock::now();
    for (int i = 0; i < kFrames; ++i) bytes = render::draw::encodePng(sample, setting.png).size();
    std::printf("  %-52s %6.2f ms %7zu bytes\n", setting.name, msSince(start) / kFrames, bytes);
  }
  return 0;
}
