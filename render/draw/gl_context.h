// The OpenGL context, off-screen: one RAII owner of an OSMesa context (Mesa's llvmpipe, software GL,
// no display or GPU) and of the framebuffer it draws into. Anti-aliasing is chosen here: the scene is
// drawn `supersample` times larger (in each direction), once per sample position, and reduced to the
// output size on reading (see gl_context.cpp for the measurements).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/draw/camera.h"
#include "render/draw/image.h"

struct osmesa_context;

namespace render::draw {

struct Antialiasing {
  int supersample = 1;         // the frame drawn this many times wider and higher, box-filtered down
  int samples = 4;             // samples per drawn pixel: 1 (none), 2 or 4, at Direct3D's standard positions
  bool fewerWhenDense = true;  // fewerSamples() is heeded (false: every frame at `samples`)
};

// where a context's read()s spent their time, in seconds (for the bench: measured only when asked,
// since it waits for GL after each drawing)
struct ReadCost {
  double raster = 0.0;    // the recorded frame drawn at each sample position, GL finished
  double readback = 0.0;  // the drawings read out of GL
  double resolve = 0.0;   // the samples averaged into the frame
};

// a vertex of a batch of triangles as GL takes it: position (relative to the camera center) and color
struct TriangleVertex {
  float x, y, r, g, b, a;
};

// the anti-aliasing frames are drawn with (chosen by measurement, see gl_context.cpp)
Antialiasing defaultAntialiasing();

class GlContext {
 public:
  // a context current on this thread, drawing `width` × `height` output pixels; throws
  // std::runtime_error when OSMesa cannot make one
  GlContext(int width, int height, Antialiasing aa = defaultAntialiasing());
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // pixels drawn per output pixel in each direction: GL's viewport is width × scale() wide
  int scale() const { return aa_.supersample; }
  // the renderer and its version as GL reports them, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)" and
  // "4.5 (Compatibility Profile) Mesa 22.3.6" (a golden record names them: pixels may differ on another)
  std::string renderer();
  std::string version();
  // make this context current (after another one was)
  void makeCurrent();
  // a frame begins: the GL calls until read() are recorded (display lists, and the triangles given to
  // drawTriangles), to be drawn once per sample; a canvas calls this before its first GL call of a frame.
  // `byCanvas2d`: the 2D canvas draws the whole frame, and says when it draws with GL calls of its
  // own (drawsDirectly()): only such a frame may be drawn in software
  void beginFrame(bool byCanvas2d = false);
  // the frame's store of triangles: a canvas appends a batch's vertices here, then drawTriangles()
  std::vector<TriangleVertex>& triangleStore() { return triangles_; }
  // the store's vertices from `first` on drawn as GL_TRIANGLES, in order with the GL calls around
  // them: within a frame they stay in the store, sent to GL once and drawn at each sample position
  // from there (not compiled into a display list: see gl_context.cpp); outside one, drawn at once
  // and taken out of the store
  void drawTriangles(size_t first);
  // the frame starts cleared to `background` (with `depth`, its depth and stencil too): cleared by
  // read() before each drawing, never under a scissor (see gl_context.cpp)
  void clearFrame(const Color& background, bool depth);
  // what the frame recorded since beginFrame() draws lies within `pixels` (output pixels, x to the
  // right, y down from the top-left corner; empty: nothing but the background). Outside it every
  // sample is the background, so the drawings at the other sample positions are limited to it.
  // Unsaid, the whole frame is drawn at each position.
  void drawnWithin(const Bounds& pixels);
  // what the frame recorded so far is its static part (drawn first, and the same from frame to frame:
  // the ground and its hatching), `key` every value its GL calls took; what follows is recorded apart
  void endStaticPart(std::vector<double> key);
  // what the frame recorded after its static part draws lies within `pixels` (as drawnWithin). Said,
  // a frame whose static part's key is the last frame's is the static part's frame, drawn and
  // resolved once and kept, with only the region of `pixels` drawn at the four positions over it
  void movingWithin(const Bounds& pixels);
  // the orthographic view of a 2D frame (glOrtho over ±halfWidth × ±halfHeight, depth ±1), recorded
  // like any GL call and remembered, so that the frame's moving part may be drawn in software
  void orthographic(double halfWidth, double halfHeight);
  // a canvas draws with GL calls of its own (not triangles of the store) in the part being recorded:
  // the frame's moving part is then drawn by GL
  void drawsDirectly();
  // a canvas draws, with GL calls of its own, a primitive GL draws each sample of at most once (a
  // translucent stroke under a stencil value of its own): beginOnce() as it begins, then its
  // triangles as GL makes them (whole ones, one colour each) to drawnOnce(), so that software may
  // still draw the frame (in order with the rest of the part being recorded)
  void beginOnce();
  void drawnOnce(const TriangleVertex* vertices, size_t count);
  // whether a frame's moving part may be drawn in software where that gives GL's pixels (the
  // default; off, every frame is drawn by GL: the tests and the bench compare the two), and how many
  // frames have been
  void allowSoftware(bool allowed) { softwareAllowed_ = allowed; }
  long softwareFrames() const { return softwareFrames_; }
  // the frame being drawn takes `samples` (2) samples a pixel rather than the context's 4: a frame
  // dense with small bodies (GlCanvas's rule), where the two look alike (gl_context.cpp)
  void fewerSamples(int samples);
  // the samples a pixel of the frame being drawn (or, after read(), last drawn) is drawn at
  int samples() const { return samplesNow_; }
  // draw the recorded frame at each sample position, resolve the samples and return the frame at the
  // output size, top row first
  Image read();
  // the same into `frame`: GL reads the frame straight into its storage, which is reused (neither
  // allocated nor cleared) when it has the frame's size already
  void read(Image& frame);
  // a stencil value no pixel holds, for a primitive that marks its pixels: values count up from 1
  // and the stencil is cleared only when the 8 bits run out, not every frame (see gl_context.cpp)
  int freshStencil();
  // read()s add their costs to `*cost` from now on (nullptr: not measured, the default)
  void measureInto(ReadCost* cost) { cost_ = cost; }

 private:
  int width_, height_;
  Antialiasing aa_;
  osmesa_context* context_ = nullptr;
  std::vector<uint8_t> buffer_;  // OSMesa's own color buffer, never drawn into (the framebuffer object is)
  unsigned framebuffer_ = 0, renderbuffers_[2] = {0, 0};
  // the frame being drawn, in order: each step a display list, then the store's triangles from
  // `first` (`count` of them, maybe none), in the static part (0) or the rest (1)
  struct Step {
    int part = 0;
    unsigned list = 0;
    size_t first = 0, count = 0;
    bool opaque = false;  // every vertex's alpha 1: drawn with blending and the stencil test off
  };
  std::vector<Step> steps_;
  // the primitives drawn once a sample (drawnOnce()), each with the step whose list draws it and
  // its own group: their triangles, ranges of onceTriangles_
  struct OnceRange {
    size_t step = 0;
    int part = 0;
    uint32_t group = 0;
    size_t first = 0, count = 0;
  };
  std::vector<OnceRange> once_;
  std::vector<TriangleVertex> onceTriangles_;
  uint32_t onceGroups_ = 0;
  std::vector<uint32_t> stamps_;           // rasterize()'s, a pixel each: the group that drew it last
  std::vector<unsigned> lists_;            // display lists made so far, reused from frame to frame
  std::vector<TriangleVertex> triangles_;  // the frame's triangles (drawTriangles)
  unsigned vertexBuffer_ = 0;              // the GL buffer they are sent to for drawing, and its size
  size_t bufferBytes_ = 0;
  int part_ = 0;                        // the part being recorded
  bool recording_ = false;              // between beginFrame() and read()
  std::optional<Bounds> drawnWithin_;   // what drawnWithin() said of the frame being drawn
  std::optional<Bounds> movingWithin_;  // what movingWithin() said of it
  // the static part's key this frame, the last frame's, and the key of the kept static frame
  std::vector<double> key_, lastKey_, keptKey_;
  bool staticStencil_ = false;  // whether the static part marks pixels in the stencil
  // what clearFrame() said of the frame being drawn
  bool clears_ = false, clearsDepth_ = false;
  std::array<float, 4> clearColor_{};
  std::vector<uint8_t> kept_;                  // the static part's frame, resolved
  std::optional<std::array<float, 2>> ortho_;  // orthographic()'s x and y scales this frame
  bool byCanvas2d_ = false;                    // beginFrame()'s
  std::array<bool, 2> direct_{};               // drawsDirectly() was said of the static part, of the rest
  bool softwareAllowed_ = true;
  std::optional<bool> softwareAgrees_;  // softwareAgrees(), once found
  long softwareFrames_ = 0;
  int samplesNow_;       // the samples of the frame being drawn (aa_.samples or fewer)
  int keptSamples_ = 0;  // the samples kept_ was resolved at
  // the drawings at the sample positions (of a region), and the supersampled frame, reused from
  // frame to frame
  std::array<std::vector<uint8_t>, 4> samples_;
  std::vector<uint8_t> drawn_;
  int lastStencil_ = 0;  // the last value given out since the stencil was cleared
  ReadCost* cost_ = nullptr;
  // the stencil (and depth) cleared, every value free again
  void clearStencil();
  // a pixel region in GL's window coordinates (y up)
  struct Region {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
  };
  // the static part's drawings at each sample position within staticRegion_ (staticDrawings_ of
  // them, 0 for none), kept with kept_
  std::array<std::vector<uint8_t>, 4> staticSamples_;
  Region staticRegion_;
  int staticDrawings_ = 0;
  // the region of the frame that output pixels `b` may touch at any sample position
  Region regionOf(const Bounds& b) const;
  // the display list steps_.size() records into, begun
  void beginList();
  // the list being recorded ended, a step with the triangles from `first` on (none: `first` is the
  // store's size)
  void endStep(size_t first);
  // the frame's triangles sent to GL's buffer, for drawSteps()
  void sendTriangles();
  // the recorded steps of parts below `parts` drawn once (at one sample position)
  void drawSteps(int parts);
  // whether every triangle from `first` on is opaque (alpha 1)
  bool opaque(size_t first) const;
  // the bound arrays' triangles [first, first + count), opaque ones drawn as such
  void drawArrays(size_t first, size_t count, bool opaque);
  // the recorded lists up to `parts` drawn at the sample positions and resolved into `frame`
  // (top row first) within `region`; with `firstWhole`, the first drawing is the whole frame and
  // read into `frame` (outside the region every sample is alike), else only the region is drawn
  // (with `keep`, the drawings kept too, in staticSamples_)
  void resolveRegion(uint8_t* frame, int parts, const Region& region, bool firstWhole, bool stencil, bool keep = false);
  // samples_ (and the frame's own rows, with `firstWhole`) resolved into `frame` within `region`
  void resolveInto(uint8_t* frame, const Region& region, bool firstWhole, int drawings);
  // the drawings just made within `region` kept in staticSamples_
  void keepStaticSamples(const uint8_t* frame, const Region& region, bool firstWhole, int drawings);
  // whether the recorded steps of parts from `firstPart` on are triangles that software draws as
  // GL would (triangle_raster.h), in a frame it may draw
  bool softwareDraws(int firstPart) const;
  // the moving part drawn in software over the kept static part's drawings and resolved into
  // `frame` within `moving`, when software draws it as GL would; whether it was
  bool drawnInSoftware(uint8_t* frame, const Region& moving);
  // the whole frame drawn so, over the background, which it is outside `region`; whether it was
  bool drawnWholeInSoftware(uint8_t* frame, const Region& region);
  // the steps of parts from `firstPart` on rasterized at each sample position over what `under`
  // puts in that position's drawing of `region`, then resolved into `frame` within it
  void rasterize(uint8_t* frame, const Region& region, int firstPart, const std::function<void(int, uint8_t*)>& under);
  // the clear colour's bytes as GL clears to them (found by GL once per colour)
  std::array<uint8_t, 4> clearBytes();
  std::array<float, 4> clearedColor_{-1.0f, -1.0f, -1.0f, -1.0f};
  std::array<uint8_t, 4> clearedBytes_{};
  // whether software draws probe triangles (triangle_raster.h) as this GL does, sample for sample:
  // drawn by both once, the first time it is asked (a GL that rounds otherwise is left to draw)
  bool softwareAgrees();
};

}  // namespace render::draw
