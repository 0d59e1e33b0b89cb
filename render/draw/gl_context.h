// The OpenGL context, off-screen: one RAII owner of an OSMesa context (Mesa's llvmpipe, software GL,
// no display or GPU) and of the framebuffer it draws into. Anti-aliasing is chosen here: the scene is
// drawn `supersample` times larger (in each direction) into `samples`-sample multisampled storage and
// reduced to the output size on reading (see gl_context.cpp for the measurements).
#pragma once

#include <memory>
#include <vector>

#include "render/draw/image.h"

struct osmesa_context;

namespace render::draw {

struct Antialiasing {
  int supersample = 1;  // the frame drawn this many times wider and higher, box-filtered down
  int samples = 4;      // multisample samples per drawn pixel (1: none); llvmpipe offers 4
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
  // wait for GL, resolve the samples and return the frame at the output size, top row first
  Image read();
  // the same into `frame`: OSMesa copies the frame straight into its storage, which is reused
  // (neither allocated nor cleared) when it has the frame's size already
  void read(Image& frame);
  // a stencil value no pixel holds, for a primitive that marks its pixels: values count up from 1
  // and the stencil is cleared only when the 8 bits run out, not every frame (see gl_context.cpp)
  int freshStencil();

 private:
  int width_, height_;
  Antialiasing aa_;
  osmesa_context* context_ = nullptr;
  std::vector<uint8_t> buffer_;  // OSMesa's color buffer: the drawn size, top row first
  unsigned framebuffer_ = 0, renderbuffers_[2] = {0, 0};
  int lastStencil_ = 0;  // the last value given out since the stencil was cleared
  // the stencil (and depth) cleared, every value free again
  void clearStencil();
};

}  // namespace render::draw
