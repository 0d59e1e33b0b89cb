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

Image GlContext::read() {
  const int w = width_ * aa_.supersample, h = height_ * aa_.supersample;
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
  if (framebuffer_) glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  Image drawn;
  drawn.width = w;
  drawn.height = h;
  drawn.rgba = buffer_;
  return downsample(drawn, aa_.supersample);
}

}  // namespace render::draw
