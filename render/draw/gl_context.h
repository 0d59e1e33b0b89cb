// The OpenGL context, off-screen: one RAII owner of an OSMesa context (Mesa's llvmpipe, software GL,
// no display or GPU) and of the framebuffer it draws into. Anti-aliasing is chosen here: the scene is
// drawn `supersample` times larger (in each direction), once per sample position, and reduced to the
// output size on reading (see gl_context.cpp for the measurements).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "render/draw/camera.h"
#include "render/draw/image.h"

struct osmesa_context;

namespace render::draw {

struct Antialiasing {
  int supersample = 1;  // the frame drawn this many times wider and higher, box-filtered down
  int samples = 4;      // samples per drawn pixel: 1 (none) or 4, at llvmpipe's 4× multisampling positions
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
  // make this context current (after another one was)
  void makeCurrent();
  // a frame begins: the GL calls until read() are recorded (a display list), to be drawn once per
  // sample; a canvas calls this before its first GL call of a frame
  void beginFrame();
  // what the frame recorded since beginFrame() draws lies within `pixels` (output pixels, x to the
  // right, y down from the top-left corner; empty: nothing but the background). Outside it every
  // sample is the background, so the drawings at the other sample positions are limited to it.
  // Unsaid, the whole frame is drawn at each position.
  void drawnWithin(const Bounds& pixels);
  // draw the recorded frame at each sample position, resolve the samples and return the frame at the
  // output size, top row first
  Image read();
  // the same into `frame`: GL reads the frame straight into its storage, which is reused (neither
  // allocated nor cleared) when it has the frame's size already
  void read(Image& frame);
  // a stencil value no pixel holds, for a primitive that marks its pixels: values count up from 1
  // and the stencil is cleared only when the 8 bits run out, not every frame (see gl_context.cpp)
  int freshStencil();

 private:
  int width_, height_;
  Antialiasing aa_;
  osmesa_context* context_ = nullptr;
  std::vector<uint8_t> buffer_;  // OSMesa's own color buffer, never drawn into (the framebuffer object is)
  unsigned framebuffer_ = 0, renderbuffers_[2] = {0, 0};
  unsigned list_ = 0;       // the display list of the frame being drawn
  bool recording_ = false;  // between beginFrame() and read()
  std::optional<Bounds> drawnWithin_;  // what drawnWithin() said of the frame being drawn
  // the drawings at the other sample positions, and the supersampled frame, reused from frame to frame
  std::array<std::vector<uint8_t>, 3> samples_;
  std::vector<uint8_t> drawn_;
  int lastStencil_ = 0;  // the last value given out since the stencil was cleared
  // the stencil (and depth) cleared, every value free again
  void clearStencil();
};

}  // namespace render::draw
