// The GL canvas: every role lands where the camera says, in the color the style says; translucent
// shapes blend once (no darker joins); static shapes are hatched; frames are deterministic.
#include <doctest/doctest.h>

#include <cstdlib>
#include <numbers>

#include "render/draw/gl_canvas.h"

using namespace render::draw;
using sim::core::Vec2;

namespace {

render::draw::Style testStyle() {
  render::draw::Style s;
  s.background = Color::parse("#ffffff");
  s.bodies = {Color::parse("#4e79a7"), Color::parse("#8c8c8c")};
  s.lineWidth = 2.0;
  s.fontSize = 12;
  return s;
}

// each channel of the pixel within `tolerance` of the color
bool near(const Image& i, int x, int y, const Color& c, int tolerance = 3) {
  const uint8_t* p = i.pixel(x, y);
  return std::abs(p[0] - Color::byte(c.r)) <= tolerance && std::abs(p[1] - Color::byte(c.g)) <= tolerance &&
         std::abs(p[2] - Color::byte(c.b)) <= tolerance;
}

struct Fixture {
  render::draw::GlContext gl{100, 100};
  render::draw::TextRenderer text;
  render::draw::Style style = testStyle();
  render::draw::GlCanvas canvas{gl, text, style};
  // 10 m high: 0.1 m per pixel, the world origin at pixel (50, 50)
  Camera camera{Vec2::Zero(), 10.0, 100, 100};
};

}  // namespace

TEST_CASE_FIXTURE(Fixture, "a body is filled inside, outlined darker, and nothing is drawn outside it") {
  canvas.begin(camera);
  canvas.polygon({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, {Role::Body, 0, 1.0});
  const Image i = canvas.finish();
  const Color base = style.bodies[0];
  CHECK(near(i, 50, 50, base.mixed({1, 1, 1, 1}, 0.35)));
  CHECK(near(i, 70, 50, base.mixed({0, 0, 0, 1}, 0.35), 12));  // on the right edge, x = 2 m
  CHECK(near(i, 90, 50, style.background, 0));
  CHECK(near(i, 5, 5, style.background, 0));
}

// a mitred corner reaches half / cos(45°) out, a round join half: mitred while that is at most half
// a pixel further (a 2 px outline's 0.41 px), round past it (a 6 px outline's 1.24 px)
TEST_CASE("a box's outline is mitred where its corners would look round, round-joined where not") {
  const auto corner = [](double lineWidth) {
    render::draw::GlContext gl{100, 100};
    render::draw::TextRenderer text;
    render::draw::Style style = testStyle();
    style.lineWidth = lineWidth;
    render::draw::GlCanvas canvas{gl, text, style};
    canvas.begin(Camera{Vec2::Zero(), 10.0, 100, 100});
    // (-2, 2) m is pixel corner (30, 30): the outline's outer corner pixel is (29 - k, 29 - k)
    canvas.polygon({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, {Role::Body, 0, 1.0});
    const Image i = canvas.finish();
    const int k = static_cast<int>(lineWidth / 2) - 1;
    return std::pair{near(i, 29 - k, 29 - k, style.bodies[0].mixed({0, 0, 0, 1}, 0.35), 0),
                     near(i, 50, 29 - k, style.bodies[0].mixed({0, 0, 0, 1}, 0.35), 0)};
  };
  // 2 px: the corner pixel is the edge's color, whole
  CHECK(corner(2.0) == std::pair{true, true});
  // 6 px: the round join leaves the corner pixel partly background, while the edge is whole
  CHECK(corner(6.0) == std::pair{false, true});
}

TEST_CASE_FIXTURE(Fixture, "a translucent outline blends once, at its joins as along its edges") {
  canvas.begin(camera);
  canvas.polygon({{-3, -3}, {3, -3}, {3, 3}, {-3, 3}}, {Role::Body, 0, 0.5});
  const Image i = canvas.finish();
  // the corner (-3, 3) is pixel (20, 20): quads of two edges and a round join overlap there
  const uint8_t* corner = i.pixel(20, 20);
  const uint8_t* edge = i.pixel(50, 20);
  for (int c = 0; c < 3; ++c) CHECK(std::abs(corner[c] - edge[c]) <= 3);
}

TEST_CASE_FIXTURE(Fixture, "a half-plane fills its side out to the edges of the view, hatched") {
  canvas.begin(camera);
  canvas.halfPlane({0, -2}, {0, 1}, {Role::StaticBody, 1, 1.0});
  const Image i = canvas.finish();
  // above the boundary (y = -2 m, pixel row 70) nothing; below it the fill or the hatching everywhere
  CHECK(near(i, 0, 60, style.background, 0));
  CHECK(near(i, 99, 60, style.background, 0));
  int fill = 0, hatch = 0;
  const Color fillColor = style.role(Role::StaticBody).mixed({1, 1, 1, 1}, 0.6);
  for (int x = 0; x < 100; ++x)
    for (int y = 75; y < 100; ++y) {
      CHECK_FALSE(near(i, x, y, style.background, 0));
      near(i, x, y, fillColor) ? ++fill : ++hatch;
    }
  CHECK(fill > hatch);
  CHECK(hatch > 100);
}

TEST_CASE_FIXTURE(Fixture, "contact points, arrows and captions are drawn in their colors") {
  canvas.begin(camera);
  canvas.point({-2, 2}, {Role::ContactPoint, -1, 1.0});
  canvas.arrow({0, -2}, {3, -2}, {Role::ContactNormal, -1, 1.0});
  canvas.segment({-4, -4}, {4, -4}, {Role::ReferenceEdge, -1, 1.0});
  canvas.text(camera.toWorld({2, 2}), "t = 0", {Role::Caption, -1, 1.0});
  const Image i = canvas.finish();
  CHECK(near(i, 30, 30, style.role(Role::ContactPoint)));
  CHECK(near(i, 60, 70, style.role(Role::ContactNormal)));  // the arrow's shaft, y = -2 m
  CHECK(near(i, 50, 90, style.role(Role::ReferenceEdge)));
  int dark = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) dark += i.pixel(x, y)[0] < 100;
  CHECK(dark > 10);
}

// among many, a contact dot is blended in after the GL frame (DotLayer), unless GL draws over it
TEST_CASE_FIXTURE(Fixture, "contact dots among many lie at their points, under whatever is drawn after them") {
  const auto dotFrame = [&](bool bodyOver) {
    canvas.begin(camera);
    canvas.manyPoints(3.0);
    canvas.point({1, 1}, {Role::ContactPoint, -1, 1.0});  // pixel (60, 40)
    canvas.point({1, 1}, {Role::ContactPoint, -1, 1.0});
    canvas.manyPoints(0.0);
    if (bodyOver) canvas.polygon({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {Role::Body, 0, 1.0});
    return canvas.finish();
  };
  const Image dots = dotFrame(false);
  CHECK(near(dots, 60, 40, style.role(Role::ContactPoint), 0));
  // its disc: 3 px across its radius, about the point (pixel centers (59.5 .. 60.5, 39.5 .. 40.5)
  // around the point at the corner (60, 40))
  double area = 0.0, sx = 0.0, sy = 0.0;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x) {
      const double w = (255.0 - dots.pixel(x, y)[1]) / (255.0 - Color::byte(style.role(Role::ContactPoint).g));
      area += w, sx += w * (x + 0.5), sy += w * (y + 0.5);
    }
  CHECK(area == doctest::Approx(std::numbers::pi * 9.0).epsilon(0.03));
  CHECK(sx / area == doctest::Approx(60.0).epsilon(0.001));
  CHECK(sy / area == doctest::Approx(40.0).epsilon(0.001));
  // a body drawn after the dots covers them: drawn with GL, under it, in the order called
  const Image covered = dotFrame(true);
  CHECK(near(covered, 60, 40, style.bodies[0].mixed({1, 1, 1, 1}, 0.35)));
  CHECK(near(covered, 58, 42, style.role(Role::ContactPoint), 40) == false);
}

// the dots blended in and the dots GL draws (when something is drawn after them) are one polygon at
// the frame's sample positions: a video whose frames switch between the two does not flicker
TEST_CASE("contact dots among many look the same blended in as drawn with GL, at 4, 2 and 1 samples a pixel") {
  for (const int samples : {4, 2, 1}) {
    CAPTURE(samples);
    render::draw::GlContext gl{100, 100, {1, samples, false}};
    render::draw::TextRenderer text;
    const render::draw::Style style = testStyle();
    render::draw::GlCanvas canvas{gl, text, style};
    const Camera camera{Vec2::Zero(), 10.0, 100, 100};
    const auto dotFrame = [&](bool glAfter, double radius) {
      canvas.begin(camera);
      canvas.polygon({{-4, -4}, {4, -4}, {4, -1}, {-4, -1}}, {Role::Body, 0, 1.0});
      canvas.manyPoints(radius);
      for (int k = 0; k < 12; ++k) canvas.point({-3.7 + 0.61 * k, -1.0 + 0.013 * k}, {Role::ContactPoint, -1, 1.0});
      // and 400 more, spread over the body in no pattern
      for (int k = 0; k < 400; ++k)
        canvas.point({-4.0 + std::fmod(k * 0.7371, 8.0), -3.5 + std::fmod(k * 0.3917, 2.2)}, {Role::ContactPoint, -1, 1.0});
      canvas.manyPoints(0.0);
      // a body far from the dots, drawn after them
      if (glAfter) canvas.polygon({{3.5, 3.5}, {4, 3.5}, {4, 4}, {3.5, 4}}, {Role::Body, 1, 1.0});
      return canvas.finish();
    };
    for (const double radius : {0.8, 2.5, 4.0}) {
      CAPTURE(radius);
      const Image blended = dotFrame(false, radius), drawn = dotFrame(true, radius);
      int largest = 0;
      // (the rows of the dots and the body under them: the body after them lies at rows 10 to 15)
      for (int y = 30; y < 100; ++y)
        for (int x = 0; x < 100; ++x)
          for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(blended.pixel(x, y)[c] - drawn.pixel(x, y)[c]));
      // the same samples covered (GL's grid and its top-left rule for a sample on an edge); the two
      // round the resolve alike but for a level here and there
      CHECK(largest <= 1);
    }
  }
}

TEST_CASE_FIXTURE(Fixture, "the same calls give the same pixels") {
  auto draw = [&] {
    canvas.begin(camera);
    canvas.circle({0.3, 0.1}, 2.7, {Role::Body, 0, 1.0});
    canvas.polygon({{-4, -4}, {-1, -4.5}, {-2, -1}}, {Role::StaticBody, 1, 0.6});
    canvas.text({0.3, 0.1}, "ω", {Role::Label, 0, 1.0});
    return canvas.finish();
  };
  const Image a = draw();
  CHECK(draw() == a);
}

// the stencil is cleared only when its 255 values run out, in the middle of a frame too (4 values a
// frame here): every frame after is the first one's pixels, drawn into the same storage each time
TEST_CASE_FIXTURE(Fixture, "frames past the stencil's 255 values, into a reused buffer, are the first frame") {
  auto draw = [&](Image& into) {
    canvas.begin(camera);
    canvas.polygon({{-3, -3}, {3, -3}, {3, 3}, {-3, 3}}, {Role::Body, 0, 0.5});
    canvas.circle({1, 1}, 1.5, {Role::Body, 0, 0.5});
    canvas.finish(into);
  };
  Image first, frame;
  draw(first);
  draw(frame);
  const uint8_t* storage = frame.rgba.data();
  int differing = 0;
  for (int k = 0; k < 200; ++k) {
    draw(frame);
    differing += frame != first;
  }
  CHECK(differing == 0);
  CHECK(frame.rgba.data() == storage);
}

TEST_CASE("supersampled and multisampled contexts both give frames of the output size") {
  for (const render::draw::Antialiasing aa :
       {render::draw::Antialiasing{1, 1}, render::draw::Antialiasing{2, 1}, render::draw::Antialiasing{1, 4}}) {
    render::draw::GlContext gl(64, 32, aa);
    render::draw::TextRenderer text;
    const render::draw::Style style = testStyle();
    render::draw::GlCanvas canvas(gl, text, style);
    canvas.begin(Camera({0, 0}, 3.2, 64, 32));
    canvas.circle({0, 0}, 1.0, {Role::Body, 0, 1.0});
    const Image i = canvas.finish();
    CHECK(i.width == 64);
    CHECK(i.height == 32);
    CHECK(near(i, 32, 16, style.bodies[0].mixed({1, 1, 1, 1}, 0.35)));
  }
}

TEST_CASE_FIXTURE(Fixture, "opaque shapes are drawn in one batched call, however many; a static one adds its own few") {
  const auto calls = [&](int bodies) {
    canvas.begin(camera);
    canvas.polygon({{-4, -4}, {4, -4}, {4, -3}, {-4, -3}}, {Role::StaticBody, 1, 1.0});
    for (int i = 0; i < bodies; ++i) {
      const double x = -4.0 + 8.0 * (i % 40) / 40.0, y = -2.0 + 6.0 * (i / 40) / 40.0;
      canvas.polygon({{x, y}, {x + 0.1, y}, {x + 0.1, y + 0.1}, {x, y + 0.1}}, {Role::Body, 0, 1.0});
      canvas.circle({x, y + 0.05}, 0.05, {Role::Body, 0, 1.0});
      canvas.point({x, y}, {Role::ContactPoint, -1, 1.0});
      canvas.arrow({x, y}, {x, y + 0.3}, {Role::ContactNormal, -1, 1.0});
    }
    (void)canvas.finish();
    return canvas.drawCalls();
  };
  const int ten = calls(10), thousand = calls(1000);
  CHECK(ten == thousand);
  // the static box's fill (marking its pixels) and its hatching, the batch of its outline (the
  // frame's static part, kept apart), then one batch of every opaque call after it
  CHECK(thousand == 4);
}

TEST_CASE_FIXTURE(Fixture, "hatching is bounded by the frame: stripes a pixel apart at least, cut to the view") {
  // 1e16 m from the origin, stripes half a metre apart are 1.4e16 stripes from it: past 2⁵³, where
  // k + 1 == k and counting them one by one never ends; and a line width of 0.1 px asks for stripes
  // half a pixel apart, which the frame cannot show
  style.lineWidth = 0.1;
  const Camera far{Vec2(1e16, 0.0), 50.0, 100, 100};
  canvas.begin(far);
  canvas.polygon({{1e16 - 40, -10}, {1e16 + 40, -10}, {1e16 + 40, 10}, {1e16 - 40, 10}}, {Role::StaticBody, 1, 1.0});
  const Image i = canvas.finish();
  // drawn, filled where the box is and nowhere else
  CHECK(near(i, 50, 50, style.body(1).mixed({1, 1, 1, 1}, 0.6), 40));
  CHECK(near(i, 50, 10, style.background, 0));
}

TEST_CASE("a frame of at least 200 small moving bodies and no large one is drawn at two samples, any other at four") {
  using render::draw::Antialiasing;
  const render::draw::Style style = testStyle();
  render::draw::TextRenderer text;
  const Camera camera(Vec2::Zero(), 10.0, 100, 100);
  // `boxes` turned boxes 0.3 m (3 px) across, on a ground; `large`: one body 2 m (20 px) across too
  const auto frame = [&](const Antialiasing& aa, int boxes, bool large) {
    render::draw::GlContext gl(100, 100, aa);
    render::draw::GlCanvas canvas(gl, text, style);
    canvas.begin(camera);
    canvas.polygon({{-5, -5}, {5, -5}, {5, -4}, {-5, -4}}, {Role::StaticBody, 1, 1.0});
    for (int i = 0; i < boxes; ++i) {
      const double x = -4.5 + 0.45 * (i % 20) + 0.01 * (i / 20), y = -3.5 + 0.45 * (i / 20);
      canvas.polygon({{x, y}, {x + 0.3, y + 0.05}, {x + 0.25, y + 0.35}, {x - 0.05, y + 0.3}}, {Role::Body, 0, 1.0});
    }
    if (large) canvas.circle({2, 3}, 1.0, {Role::Body, 1, 1.0});
    return canvas.finish();
  };
  const Antialiasing four{1, 4, false}, two{1, 2, false};
  // the two drawings differ on these edges: otherwise the checks below could not fail
  REQUIRE(frame(four, 200, false) != frame(two, 200, false));
  CHECK(frame(Antialiasing{}, 200, false) == frame(two, 200, false));
  CHECK(frame(Antialiasing{}, 199, false) == frame(four, 199, false));
  CHECK(frame(Antialiasing{}, 200, true) == frame(four, 200, true));
}

TEST_CASE("two samples a pixel: an edge through the middle of a pixel column is half covered") {
  render::draw::GlContext gl(8, 8, render::draw::Antialiasing{1, 2, false});
  render::draw::TextRenderer text;
  const render::draw::Style style = testStyle();
  render::draw::GlCanvas canvas(gl, text, style);
  // 1 px per m, the origin at the frame's center: a bar (an area, no outline) whose right edge halves column 4
  canvas.begin(Camera(Vec2::Zero(), 8.0, 8, 8));
  canvas.polygon({{-4, -4}, {0.5, -4}, {0.5, 4}, {-4, 4}}, {Role::RotationalBar, 0, 1.0});
  const Image i = canvas.finish();
  const Color fill = style.bodies[0].mixed({1, 1, 1, 1}, 0.45);
  CHECK(near(i, 2, 4, fill));
  CHECK(near(i, 6, 4, style.background));
  // the samples at x + 0.25 and x + 0.75 of column 4 fall on either side of x = 4.5 px
  CHECK(near(i, 4, 4, fill.mixed(style.background, 0.5), 2));
}

TEST_CASE("an arrow on a body of its own hue is told apart: colours alike by hue, or close in every channel") {
  using render::draw::Color;
  using render::draw::GlCanvas;
  // the impulse's blue on a blue bar, the ω arrow's cyan on it: alike
  CHECK(GlCanvas::alike(Color::parse("#0072b2"), Color::parse("#3b6ea5")));
  CHECK(GlCanvas::alike(Color::parse("#17becf"), Color::parse("#3b6ea5")));
  // the velocity's green, the force's orange: apart
  CHECK_FALSE(GlCanvas::alike(Color::parse("#009e73"), Color::parse("#3b6ea5")));
  CHECK_FALSE(GlCanvas::alike(Color::parse("#e69f00"), Color::parse("#3b6ea5")));
  // two greys, of no hue, close in every channel
  CHECK(GlCanvas::alike(Color::parse("#7f7f7f"), Color::parse("#8c8c8c")));
  CHECK_FALSE(GlCanvas::alike(Color::parse("#1f1f1f"), Color::parse("#d0d0d0")));
}
