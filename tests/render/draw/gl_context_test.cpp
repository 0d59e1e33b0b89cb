// The GL context: a frame drawn once per sample position and resolved in rigidreel is the frame that
// llvmpipe's own 4× multisampling and resolving blit give, byte for byte (gl_context.cpp draws it
// that way because llvmpipe's resolve is slow, and the pictures must not change).
#include <doctest/doctest.h>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <functional>

#include "render/draw/gl_canvas.h"

using namespace render::draw;
using sim::core::Vec2;

namespace {

constexpr int kWidth = 320, kHeight = 180;

// what the frames show: a hatched ground and box, turned and translucent bodies, a wheel, a
// contact, arrows (no text: it is drawn on the read frame, not by GL)
void scene(render::draw::GlCanvas& c) {
  c.halfPlane({0, -0.5}, {0.05, 1}, {Role::StaticBody, 1, 1});
  c.polygon({{-2.5, 0.2}, {-1.5, 0.2}, {-1.5, 1.2}, {-2.5, 1.2}}, {Role::StaticBody, 1, 1});
  c.polygon({{-0.9, -0.3}, {0.1, -0.45}, {0.25, 0.55}, {-0.75, 0.7}}, {Role::Body, 0, 1});
  c.polygon({{0.1, 0.3}, {1.0, 0.0}, {1.3, 0.9}, {0.4, 1.2}}, {Role::Body, 2, 0.5});
  c.circle({1.8, 1.5}, 0.4, {Role::Body, 0, 0.7});
  c.segment({1.8, 1.5}, {2.1, 1.75}, {Role::BodyAxis, 0, 1});
  c.point({0, 0.3}, {Role::ContactPoint, -1, 1});
  c.arrow({0, 0.3}, {0.5, 0.35}, {Role::ContactNormal, -1, 1});
  c.arrow({-2, 2.5}, {-1.2, 2.0}, {Role::Impulse, -1, 0.6});
}

render::draw::Style style() {
  render::draw::Style s;
  s.background = Color::parse("#fdfcf7");
  s.bodies = {Color::parse("#4e79a7"), Color::parse("#8c8c8c"), Color::parse("#c8553d")};
  s.lineWidth = 1.5;
  return s;
}

// a few shapes in the middle of the frame: the other sample positions drawn only around them
void smallScene(render::draw::GlCanvas& c) {
  c.polygon({{-0.4, 0.7}, {0.3, 0.6}, {0.4, 1.3}, {-0.3, 1.4}}, {Role::Body, 0, 1});
  c.circle({0.9, 1.1}, 0.25, {Role::Body, 2, 0.5});
  c.arrow({0.9, 1.1}, {1.4, 0.9}, {Role::Velocity, 2, 1});
}

// the same calls drawn at once into a 4x multisampled framebuffer and resolved by a blit
Image multisampled(render::draw::GlContext& gl, render::draw::GlCanvas& canvas, const Camera& camera, const Color& bg,
                   const std::function<void(render::draw::GlCanvas&)>& draw) {
  GLuint framebuffers[2], renderbuffers[3];
  glGenFramebuffers(2, framebuffers);
  glGenRenderbuffers(3, renderbuffers);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[0]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, kWidth, kHeight);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[1]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, kWidth, kHeight);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[2]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kWidth, kHeight);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffers[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, renderbuffers[1]);
  REQUIRE(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
  glViewport(0, 0, kWidth, kHeight);
  glStencilMask(0xff);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glClearColor(static_cast<float>(bg.r), static_cast<float>(bg.g), static_cast<float>(bg.b), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  // an overlay draws at once, into whatever framebuffer is bound
  canvas.beginOverlay(camera);
  draw(canvas);
  // the opaque shapes wait in the canvas's batch until drawn
  canvas.flush();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffers[1]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers[2]);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers[0]);
  glDisable(GL_STENCIL_TEST);
  glBlitFramebuffer(0, 0, kWidth, kHeight, 0, 0, kWidth, kHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers[1]);
  Image frame;
  frame.width = kWidth;
  frame.height = kHeight;
  frame.rgba.resize(static_cast<size_t>(kWidth) * kHeight * 4);
  // (the context reads rows top first already)
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, frame.rgba.data());
  gl.makeCurrent();
  glDeleteFramebuffers(2, framebuffers);
  glDeleteRenderbuffers(3, renderbuffers);
  return frame;
}

long differingBytes(const Image& a, const Image& b) {
  long n = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) n += a.rgba[i] != b.rgba[i];
  return n;
}

// a context, a canvas on it and a camera on the scenes above
struct Fixture {
  render::draw::GlContext gl{kWidth, kHeight};
  render::draw::TextRenderer text;
  render::draw::Style s = style();
  render::draw::GlCanvas canvas{gl, text, s};
  Camera camera{{0.3, 1}, 4.0, kWidth, kHeight};
};

}  // namespace

TEST_CASE_FIXTURE(Fixture, "a frame drawn at each sample position is llvmpipe's 4x multisampled frame, byte for byte") {
  for (auto* draw : {&scene, &smallScene}) {
    canvas.begin(camera);
    draw(canvas);
    const Image drawn = canvas.finish();
    CHECK(differingBytes(drawn, multisampled(gl, canvas, camera, s.background, draw)) == 0);
  }
}

TEST_CASE_FIXTURE(Fixture, "drawn twice, a frame comes out the same (the recorded frame replaces the one before)") {
  canvas.begin(camera);
  scene(canvas);
  const Image first = canvas.finish();
  canvas.begin(camera);
  canvas.circle({0, 0}, 1.0, {Role::Body, 0, 1});
  const Image other = canvas.finish();
  canvas.begin(camera);
  scene(canvas);
  Image again = other;
  canvas.finish(again);
  CHECK(first != other);
  CHECK(first == again);
}

// a hatched ground and wall (static bodies, drawn first), and a box and a ball that move over them
void movingScene(render::draw::GlCanvas& c, double x) {
  c.halfPlane({0, -0.5}, {0.05, 1}, {Role::StaticBody, 1, 1});
  c.polygon({{-2.5, 0.2}, {-1.5, 0.2}, {-1.5, 1.2}, {-2.5, 1.2}}, {Role::StaticBody, 1, 1});
  c.polygon({{x - 0.5, -0.4}, {x + 0.5, -0.4}, {x + 0.5, 0.6}, {x - 0.5, 0.6}}, {Role::Body, 0, 1});
  c.circle({x + 1.0, 1.5 - x}, 0.3, {Role::Body, 2, 0.5});
  c.arrow({x, 0.1}, {x + 0.6, 0.3}, {Role::Velocity, 0, 1});
}

// the static part (its frame kept from the second frame on, only the moving part's region drawn at
// the four positions over it) changes no byte: every frame is llvmpipe's own multisampled frame,
// as the ground stays, as the camera moves (a new static part), and as a static body comes last
TEST_CASE_FIXTURE(Fixture, "frames over a kept static part are the frames drawn whole, byte for byte") {
  const Camera moved{{0.5, 1.1}, 4.0, kWidth, kHeight};
  struct Step {
    const Camera* camera;
    double x;
    bool staticLast;
  };
  const Step steps[] = {{&camera, -1.0, false}, {&camera, -0.7, false}, {&camera, -0.4, false}, {&camera, -0.4, false},
                        {&moved, 0.0, false},   {&moved, 0.3, false},   {&moved, 0.6, true},    {&camera, 0.9, false}};
  Image frame;
  for (const Step& step : steps) {
    const auto draw = [&](render::draw::GlCanvas& c) {
      movingScene(c, step.x);
      if (step.staticLast) c.circle({2.0, -0.2}, 0.3, {Role::StaticBody, 1, 1});
    };
    canvas.begin(*step.camera);
    draw(canvas);
    canvas.finish(frame);
    CHECK(differingBytes(frame, multisampled(gl, canvas, *step.camera, s.background, draw)) == 0);
  }
}

namespace {

// a frame's pixels as they are now in the context's framebuffer
Image framebufferPixels() {
  Image frame;
  frame.width = kWidth;
  frame.height = kHeight;
  frame.rgba.resize(static_cast<size_t>(kWidth) * kHeight * 4);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, frame.rgba.data());
  return frame;
}

// a translucent triangle to draw over, blending and the stencil test on as a canvas leaves them
// between primitives (its batch's stencil test passes every sample); `atOnce`: into a cleared
// frame, at the pixel centers (a recorded frame is cleared and shifted by read())
void translucentUnder(bool atOnce = true) {
  if (atOnce) {
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.95f, 0.9f, 0.8f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glBegin(GL_TRIANGLES);
  glColor4d(0.2, 0.55, 0.3, 0.45);
  glVertex2d(-0.9, -0.8), glVertex2d(0.7, -0.6), glVertex2d(-0.2, 0.9);
  glEnd();
}

// the same triangles one call each, blended (as a primitive outside the batch is drawn)
void blendedOneByOne(const std::vector<render::draw::TriangleVertex>& triangles) {
  glBegin(GL_TRIANGLES);
  for (const auto& v : triangles) glColor4d(v.r, v.g, v.b, v.a), glVertex2d(v.x, v.y);
  glEnd();
}

}  // namespace

// An opaque batch is drawn with blending and the stencil test off, as llvmpipe draws fastest
// (gl_context.cpp): under a blend function and a stencil test that would hide it, it still shows,
// with the pixels the same triangles give drawn one by one blended under the canvas's state; a batch
// with one translucent vertex is blended; the state after it is the state before it. At once (an
// overlay) and recorded into a frame drawn at each sample position alike.
TEST_CASE_FIXTURE(Fixture,
                  "an opaque batch draws the pixels blending draws, and leaves blending and the stencil test as they were") {
  gl.makeCurrent();
  std::vector<render::draw::TriangleVertex> opaque{
      {-0.7f, -0.7f, 0.123f, 0.456f, 0.789f, 1.0f}, {0.5f, -0.3f, 0.9f, 0.1f, 0.33f, 1.0f},
      {0.1f, 0.6f, 0.05f, 0.95f, 0.5f, 1.0f},       {0.3f, -0.9f, 0.7f, 0.7f, 0.2f, 1.0f},
      {0.95f, 0.8f, 0.7f, 0.7f, 0.2f, 1.0f},        {-0.4f, 0.2f, 0.7f, 0.7f, 0.2f, 1.0f}};
  // what blending would hide (the destination kept) and a stencil test no sample passes
  const auto hiding = [] {
    glBlendFuncSeparate(GL_ZERO, GL_ONE, GL_ZERO, GL_ONE);
    glStencilFunc(GL_NEVER, 0, 0xff);
  };
  SUBCASE("drawn at once") {
    translucentUnder();
    blendedOneByOne(opaque);
    const Image blended = framebufferPixels();
    translucentUnder();
    hiding();
    gl.triangleStore() = opaque;
    gl.drawTriangles(0);
    CHECK(glIsEnabled(GL_BLEND));
    CHECK(glIsEnabled(GL_STENCIL_TEST));
    CHECK(differingBytes(framebufferPixels(), blended) == 0);
    // one translucent vertex: blended, as before
    opaque.back().a = 0.6f;
    translucentUnder();
    blendedOneByOne(opaque);
    const Image translucent = framebufferPixels();
    CHECK(differingBytes(translucent, blended) > 0);
    translucentUnder();
    gl.triangleStore() = opaque;
    gl.drawTriangles(0);
    CHECK(differingBytes(framebufferPixels(), translucent) == 0);
    // drawn where blending and the stencil test are off, they stay off
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    opaque.back().a = 1.0f;
    gl.triangleStore() = opaque;
    gl.drawTriangles(0);
    CHECK_FALSE(glIsEnabled(GL_BLEND));
    CHECK_FALSE(glIsEnabled(GL_STENCIL_TEST));
  }
  SUBCASE("recorded into a frame") {
    const auto frame = [&](const std::function<void()>& draw) {
      gl.beginFrame();
      gl.clearFrame(s.background, false);
      translucentUnder(false);
      draw();
      return gl.read();
    };
    const Image background = frame([] {});
    const Image blended = frame([&] { blendedOneByOne(opaque); });
    const Image batched = frame([&] {
      hiding();
      gl.triangleStore() = opaque;
      gl.drawTriangles(0);
    });
    CHECK(differingBytes(blended, background) > 0);
    CHECK(differingBytes(batched, blended) == 0);
  }
}

namespace {

// a pile of opaque boxes, turned a little by `turn` and shifted by `x`, on y = −0.4 (the moving
// part all triangles of the store); pileScene puts it on a hatched ground, `extra` after it
void pile(render::draw::GlCanvas& c, double x, double turn, int rows, double size) {
  for (int row = 0; row < rows; ++row)
    for (int k = 0; k < rows - row; ++k) {
      const Vec2 center{x + (k - 0.5 * (rows - row)) * size * 1.05, -0.4 + (row + 0.5) * size};
      const double a = turn * (k - row), h = 0.5 * size;
      const Vec2 u{std::cos(a) * h, std::sin(a) * h}, v{-u.y(), u.x()};
      c.polygon({center - u - v, center + u - v, center + u + v, center - u + v}, {Role::Body, (k + row) % 3, 1});
    }
}
void pileScene(render::draw::GlCanvas& c, double x, double turn, int rows, double size,
               const std::function<void(render::draw::GlCanvas&)>& extra = {}) {
  c.halfPlane({0, -0.5}, {0.05, 1}, {Role::StaticBody, 1, 1});
  pile(c, x, turn, rows, size);
  if (extra) extra(c);
}

// the fixture's context, which draws in software where it can, beside one that draws every frame
// with GL: each frame drawn by both, into `frame` and `reference`
struct TwoWays : Fixture {
  render::draw::GlContext byGl{kWidth, kHeight};
  render::draw::GlCanvas glCanvas{byGl, text, s};
  Image frame, reference;
  TwoWays() { byGl.allowSoftware(false); }
  void both(const std::function<void(render::draw::GlCanvas&)>& draw) {
    gl.makeCurrent();
    canvas.begin(camera);
    draw(canvas);
    canvas.finish(frame);
    byGl.makeCurrent();
    glCanvas.begin(camera);
    draw(glCanvas);
    glCanvas.finish(reference);
    gl.makeCurrent();
  }
};

}  // namespace

// A frame whose moving part is triangles alone is drawn in software over the kept static part's own
// drawings (triangle_raster.h): every frame the one llvmpipe's 4x multisampling gives, byte for
// byte, and the one GL gives drawing it at each sample position, a translucent body's too; a frame
// with a box past the view's edge is drawn by GL
TEST_CASE_FIXTURE(TwoWays, "a pile's frames drawn in software over the kept ground are GL's, byte for byte") {
  for (int k = 0; k < 6; ++k) {
    const auto draw = [&](render::draw::GlCanvas& c) { pileScene(c, -0.2 + 0.013 * k, 0.002 * k, 5, 0.31); };
    both(draw);
    CHECK(differingBytes(frame, reference) == 0);
    CHECK(differingBytes(frame, multisampled(gl, canvas, camera, s.background, draw)) == 0);
  }
  // the first frame made the kept ground: the five after it were drawn in software
  CHECK(gl.softwareFrames() == 5);
  CHECK(byGl.softwareFrames() == 0);
  // a translucent body (its fill blended, its outline under a stencil value of its own): software's
  both([&](render::draw::GlCanvas& c) {
    pileScene(c, 0.1, 0.01, 5, 0.31, [](render::draw::GlCanvas& d) { d.circle({1.2, 0.6}, 0.3, {Role::Body, 2, 0.5}); });
  });
  CHECK(differingBytes(frame, reference) == 0);
  CHECK(gl.softwareFrames() == 6);
  // a box past the view's right edge: GL clips it, so GL draws it
  both([&](render::draw::GlCanvas& c) {
    pileScene(c, 0.1, 0.01, 5, 0.31, [](render::draw::GlCanvas& d) {
      d.polygon({{3.5, 0.0}, {4.3, 0.0}, {4.3, 0.5}, {3.5, 0.5}}, {Role::Body, 1, 1});
    });
  });
  CHECK(differingBytes(frame, reference) == 0);
  CHECK(gl.softwareFrames() == 6);
  // and software again, the ground kept all along
  both([&](render::draw::GlCanvas& c) { pileScene(c, 0.05, 0.003, 5, 0.31); });
  CHECK(differingBytes(frame, reference) == 0);
  CHECK(gl.softwareFrames() == 7);
}

// a frame of 200 small bodies takes two samples a pixel (GlCanvas's rule): drawn in software there too
TEST_CASE_FIXTURE(TwoWays, "a dense pile at two samples a pixel: software's frames are GL's, byte for byte") {
  for (int k = 0; k < 4; ++k) {
    both([&](render::draw::GlCanvas& c) { pileScene(c, 0.013 * k, 0.004 * k, 21, 0.09); });
    CHECK(gl.samples() == 2);
    CHECK(differingBytes(frame, reference) == 0);
  }
  CHECK(gl.softwareFrames() == 3);
}

// A frame with no ground, its bodies opaque (a ball, a turned block, an axis, an arrow), is drawn in
// software whole, over the background GL clears to: byte for byte GL's drawing and its 4x
// multisampling; with a translucent body too
TEST_CASE_FIXTURE(TwoWays, "a frame of opaque bodies alone is drawn in software whole, byte for byte GL's") {
  const auto opaqueScene = [](render::draw::GlCanvas& c, double x) {
    c.circle({x, 1.0}, 0.3, {Role::Body, 2, 1});
    c.segment({x, 1.0}, {x + 0.3, 1.0}, {Role::BodyAxis, 2, 1});
    c.polygon({{0.4, 0.2}, {1.3, 0.35}, {1.15, 1.25}, {0.25, 1.1}}, {Role::Body, 0, 1});
    c.arrow({x, 1.0}, {x + 0.5, 1.3}, {Role::Velocity, 2, 1});
  };
  for (int k = 0; k < 3; ++k) {
    const auto draw = [&](render::draw::GlCanvas& c) { opaqueScene(c, -1.0 + 0.37 * k); };
    both(draw);
    CHECK(differingBytes(frame, reference) == 0);
    CHECK(differingBytes(frame, multisampled(gl, canvas, camera, s.background, draw)) == 0);
  }
  CHECK(gl.softwareFrames() == 3);
  CHECK(byGl.softwareFrames() == 0);
  // a translucent body
  canvas.begin(camera);
  opaqueScene(canvas, 0.0);
  canvas.circle({-1.5, 0.5}, 0.3, {Role::Body, 1, 0.5});
  canvas.finish(frame);
  CHECK(gl.softwareFrames() == 4);
  CHECK(differingBytes(frame, multisampled(gl, canvas, camera, s.background, [&](render::draw::GlCanvas& c) {
                         opaqueScene(c, 0.0);
                         c.circle({-1.5, 0.5}, 0.3, {Role::Body, 1, 0.5});
                       })) == 0);
}

// What the canvas draws with GL calls of its own, a translucent stroke (its quads and joins, which
// overlap, under a stencil value of its own: each sample drawn once), is drawn in software too, with
// a ground kept and without one; byte for byte GL's, where blending a sample twice would show
TEST_CASE_FIXTURE(TwoWays, "translucent strokes the canvas draws apart, each sample once: software's are GL's") {
  const auto strokes = [](render::draw::GlCanvas& c, double x) {
    c.arrow({-1.0 + x, 1.6}, {0.6, 1.9}, {Role::Velocity, 2, 0.6});
    c.arrow({0.3, 1.2}, {-0.4 + x, 0.5}, {Role::Impulse, 1, 0.35});
    c.polygon({{0.4, 0.2}, {1.3 + x, 0.35}, {1.15, 1.25}, {0.25, 1.1}}, {Role::Body, 0, 0.45});
    c.circle({-1.2, 0.4 + x}, 0.25, {Role::Body, 1, 0.7});
  };
  for (int k = 0; k < 2; ++k) both([&](render::draw::GlCanvas& c) { pileScene(c, 0.01 * k, 0.0, 5, 0.31); });
  CHECK(gl.softwareFrames() == 1);
  for (int k = 0; k < 3; ++k) {
    const auto draw = [&](render::draw::GlCanvas& c) {
      pileScene(c, 0.02, 0.0, 5, 0.31, [&](auto& d) { strokes(d, 0.07 * k); });
    };
    both(draw);
    CHECK(differingBytes(frame, reference) == 0);
    CHECK(differingBytes(frame, multisampled(gl, canvas, camera, s.background, draw)) == 0);
  }
  CHECK(gl.softwareFrames() == 4);
  // no ground: the whole frame in software
  for (int k = 0; k < 3; ++k) {
    both([&](render::draw::GlCanvas& c) { strokes(c, 0.05 * k); });
    CHECK(differingBytes(frame, reference) == 0);
  }
  CHECK(gl.softwareFrames() == 7);
  // two translucent strokes crossing: each blends its own samples once, the second over the first
  // (one stencil group for both would leave the crossing once blended); under them, at the
  // crossing, an opaque body drawn after the first stroke and before the second
  both([&](render::draw::GlCanvas& c) {
    c.segment({-1.5, 0.2}, {1.5, 1.4}, {Role::Velocity, 2, 0.5});
    c.polygon({{-0.2, 0.6}, {0.3, 0.6}, {0.3, 1.1}, {-0.2, 1.1}}, {Role::Body, 0, 1});
    c.segment({-1.5, 1.4}, {1.5, 0.2}, {Role::Impulse, 2, 0.5});
  });
  CHECK(differingBytes(frame, reference) == 0);
  CHECK(gl.softwareFrames() == 8);
  CHECK(byGl.softwareFrames() == 0);
}

// A translucent static body's outline is a once primitive of the static part: over a kept ground
// only the moving part is drawn again, so the outline must not be blended a second time there
TEST_CASE_FIXTURE(TwoWays, "a translucent ground's outline is drawn once, kept with the ground") {
  const auto ground = [](render::draw::GlCanvas& c) {
    c.polygon({{-1.6, -0.6}, {2.2, -0.6}, {2.2, -0.1}, {-1.6, -0.1}}, {Role::StaticBody, 1, 0.5});
  };
  for (int k = 0; k < 4; ++k) {
    both([&](render::draw::GlCanvas& c) {
      ground(c);
      // bodies resting on it, over its outline
      for (int j = 0; j < 4; ++j)
        c.polygon({{-1.2 + 0.8 * j + 0.01 * k, -0.15}, {-0.7 + 0.8 * j, -0.15}, {-0.7 + 0.8 * j, 0.3}, {-1.2 + 0.8 * j, 0.3}},
                  {Role::Body, j % 3, 1});
    });
    CHECK(differingBytes(frame, reference) == 0);
  }
  // the first frame kept the ground; the three after it drawn in software over it
  CHECK(gl.softwareFrames() == 3);
}

// A finite ground (a static box: the kept drawings cover its region, not the whole frame), and
// frames that change between four samples and two (a dense pile) over it: GL's, byte for byte
TEST_CASE_FIXTURE(TwoWays, "over a static box, sparse and dense piles in turn: software's frames are GL's") {
  const auto ground = [](render::draw::GlCanvas& c) {
    c.polygon({{-1.6, -0.6}, {2.2, -0.6}, {2.2, -0.4}, {-1.6, -0.4}}, {Role::StaticBody, 1, 1});
  };
  for (int k = 0; k < 8; ++k) {
    const bool dense = k % 4 >= 2;
    both([&](render::draw::GlCanvas& c) {
      ground(c);
      if (dense) pile(c, 0.3 + 0.01 * k, 0.003 * k, 21, 0.08);
      else pile(c, 0.3 + 0.01 * k, 0.003 * k, 5, 0.31);
    });
    CHECK(gl.samples() == (dense ? 2 : 4));
    CHECK(differingBytes(frame, reference) == 0);
  }
  // the ground is kept from the second frame on (again at each change of samples): the seven after
  // the first are drawn in software
  CHECK(gl.softwareFrames() == 7);
}
