#include "render/draw/gl_context.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "render/draw/gl_library.h"

namespace render::draw {

// 4× multisampling. Measured by build/rigidreel_frame_bench (render/frame_bench.cpp) on a 1280×720
// frame of bodies, arrows, text and a hatched plane (llvmpipe, 2 cores): milliseconds per frame, and
// the mean error on edge pixels (0-255) against a 4×4-supersampled, 4×-multisampled reference:
//   none 10.6 ms, 14.0 | 4× MSAA 23.2 ms, 5.2 | 2×2 supersampling 27.3 ms, 5.8 |
//   3×3 supersampling 45.9 ms, 3.1 | 2×2 supersampling of 4× MSAA 66.9 ms, 2.3
// At 4 samples multisampling is both faster and closer than supersampling (its rotated grid beats
// the ordered one on near-horizontal and near-vertical edges); 9 samples cut the error by 40 % but
// double the time, which a 60 fps lecture video does not need.
Antialiasing defaultAntialiasing() { return {1, 4}; }

namespace {

// How the stencil is cleared. llvmpipe keeps depth and stencil in one 32-bit word per sample, so a
// stencil clear alone is a masked read-modify-write of all of them (at 720p with 4 samples, 14.7 MB
// a clear and 14 % of a render's CPU time in `perf`); with the depth (which 2D drawing never tests)
// it is a plain store. And it is done only when the 255 values run out (every 5 to 25 frames of the
// lecture's scenes) rather than every frame: a value given out once since the last clear is held by
// no pixel but the ones its own primitive marks, which is all the canvas's stencil test asks.
constexpr GLbitfield kStencilClear = GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT;

}  // namespace

GlContext::GlContext(int width, int height, Antialiasing aa) : width_(width), height_(height), aa_(aa) {
  const int w = width * aa.supersample, h = height * aa.supersample;
  loadGlLibrary();
  // RGBA, 24 depth bits (unused, but llvmpipe pairs stencil with depth), 8 stencil bits
  context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!context_) throw std::runtime_error("OSMesa could not create an OpenGL context (is libosmesa6 installed?)");
  buffer_.resize(static_cast<size_t>(w) * h * 4);
  makeCurrent();
  if (aa.samples > 1) {
    // OSMesa attaches its buffer to the window-system framebuffer on first use: touch it once, or
    // the resolving blit goes nowhere
    glClear(GL_COLOR_BUFFER_BIT);
    // a multisampled framebuffer object, resolved into OSMesa's buffer by a blit in read()
    glGenFramebuffers(1, &framebuffer_);
    glGenRenderbuffers(2, renderbuffers_);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, aa.samples, GL_RGBA8, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, aa.samples, GL_DEPTH24_STENCIL8, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[1]);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      OSMesaDestroyContext(context_);
      throw std::runtime_error("OSMesa cannot draw " + std::to_string(aa.samples) + "-sample anti-aliased frames of " +
                               std::to_string(w) + "×" + std::to_string(h));
    }
  }
  glViewport(0, 0, w, h);
  clearStencil();
}

GlContext::~GlContext() {
  if (framebuffer_) {
    makeCurrent();
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteRenderbuffers(2, renderbuffers_);
  }
  OSMesaDestroyContext(context_);
}

void GlContext::makeCurrent() {
  const int w = width_ * aa_.supersample, h = height_ * aa_.supersample;
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, w, h))
    throw std::runtime_error("OSMesa could not make its OpenGL context current");
  // rows in the buffer from the top, as images and video frames are stored
  OSMesaPixelStore(OSMESA_Y_UP, 0);
  if (framebuffer_) glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
}

void GlContext::clearStencil() {
  glStencilMask(0xff);
  glClearStencil(0);
  glClear(kStencilClear);
  lastStencil_ = 0;
}

int GlContext::freshStencil() {
  if (lastStencil_ == 255) clearStencil();
  return ++lastStencil_;
}

Image GlContext::read() {
  Image frame;
  read(frame);
  return frame;
}

void GlContext::read(Image& frame) {
  const int w = width_ * aa_.supersample, h = height_ * aa_.supersample;
  // OSMesa copies what GL drew into the buffer it was made current with: the frame itself, unless
  // it is to be downsampled
  uint8_t* target = buffer_.data();
  if (aa_.supersample == 1) {
    frame.width = w;
    frame.height = h;
    frame.rgba.resize(static_cast<size_t>(w) * h * 4);
    target = frame.rgba.data();
  }
  if (!OSMesaMakeCurrent(context_, target, GL_UNSIGNED_BYTE, w, h))
    throw std::runtime_error("OSMesa could not make its OpenGL context current");
  if (framebuffer_) {
    // the resolve is a copy: no per-fragment tests may mask it
    glDisable(GL_STENCIL_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    // OSMesa copies into its buffer when GL finishes with the window-system framebuffer bound
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  glFinish();
  // OSMesa's own buffer again, so that it never keeps a pointer into a frame handed on
  makeCurrent();
  if (aa_.supersample == 1) return;
  Image drawn;
  drawn.width = w;
  drawn.height = h;
  drawn.rgba = buffer_;
  frame = downsample(drawn, aa_.supersample);
}

}  // namespace render::draw
