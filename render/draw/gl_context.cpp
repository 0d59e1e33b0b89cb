#include "render/draw/gl_context.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cstddef>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "render/draw/gl_library.h"
#include "render/draw/sample_resolve.h"
#include "render/draw/triangle_raster.h"

namespace render::draw {

// 4× multisampling. Measured by build/rigidreel_frame_bench (render/bench/frame_bench.cpp) on a 1280×720
// frame of bodies, arrows, text and a hatched plane (llvmpipe, 2 cores): milliseconds per frame, and
// the mean error on edge pixels (0-255) against a 4×4-supersampled, 4×-multisampled reference:
//   none 10.6 ms, 14.0 | 4× MSAA 23.2 ms, 5.2 | 2×2 supersampling 27.3 ms, 5.8 |
//   3×3 supersampling 45.9 ms, 3.1 | 2×2 supersampling of 4× MSAA 66.9 ms, 2.3
// At 4 samples multisampling is both faster and closer than supersampling (its rotated grid beats
// the ordered one on near-horizontal and near-vertical edges); 9 samples cut the error by 40 % but
// double the time, which a 60 fps lecture video does not need.
//
// The 4 samples are drawn as 4 frames, each shifted by a fraction of a pixel so that its pixel
// centers fall on one of the sample positions, and averaged as llvmpipe's resolve averages
// (sample_resolve.h): the same frame to the bit (tests/render/draw/gl_context_test.cpp), without
// llvmpipe's resolving blit, which fetches every sample through its generic texture path. Of a
// 720p frame, a standalone OSMesa program measured (CPU ms a frame, a light scene, busy machine)
// 16.4 ms for the multisampled drawing and its resolve against 5.7 ms for the four drawings read
// back; after the first, the drawings are limited to where the canvas drew (drawnWithin), since
// elsewhere every sample is the background. `rigidreel render scenes/three_collisions_poll.yaml
// --variant A` (the 720p video and its poster, ffmpeg included): 4.3 → 2.7-3.1 CPU seconds.
//
// A 2D frame whose moving part is triangles alone (a pile's boxes, frames of a few bodies, fading
// arrows: translucent ones blended, a stroke's drawn once a sample) is drawn in software as llvmpipe
// draws it (triangle_raster.h), over the kept static part's own drawings at each sample position or
// over the background: GL's frame byte for byte. 2 s of the 210-box half-plane pile at 720p took
// 1.42 s, 0.47 s so (render/README.md, "Frames drawn in software").
//
// Fewer samples, measured by `build/rigidreel_bench build/rigidreel scenes/three_collisions_poll.yaml
// --antialiasing` (720p; wall ms per frame of rasterizing at the sample positions; against the
// 4-sample frames: the largest and mean channel difference, the share of pixels differing):
//   two-body poll:       4: 4.9 | 2: 2.3, max 128, mean 0.035, 0.23 % | 1: 1.2, max 179, 0.19, 0.33 %
//   210-box pyramid:     4: 10.7 | 2: 4.9, max 129, mean 0.27, 1.3 % | 1: 3.2, max 183, 0.46, 1.6 %
//   5,050-box pyramid:   4: 23.0 | 2: 12.2, max 114, mean 0.95, 5.3 % | 1: 6.7, max 170, 1.65, 6.4 %
// One sample is a different look at lecture scale: a large body's outline stair-stepped and heavier,
// a pile of 6 px boxes in vertical bands (each snapped to whole pixels, widths uneven). Two samples soften a
// large body's edge in visibly coarser steps (so large bodies keep four), but a frame of hundreds of
// bodies a few pixels across looks the same at 1:1: GlCanvas asks for two there (fewerSamples).
Antialiasing defaultAntialiasing() { return {1, 4}; }

namespace {

// How the stencil is cleared. llvmpipe keeps depth and stencil in one 32-bit word per pixel, so a
// stencil clear alone is a masked read-modify-write of all of them (14 % of a render's CPU time in
// `perf` once); with the depth (which 2D drawing never tests) it is a plain store. It is cleared
// before each drawing of a frame that marks pixels (the display list gives the same stencil values
// to each drawing), skipped for frames of opaque shapes only, and cleared again within a frame
// when the 255 values run out: a value given out once since the last clear is held by no pixel but
// the ones its own primitive marks, which is all the canvas's stencil test asks.
constexpr GLbitfield kStencilClear = GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT;

// glOrtho's scale over ±half as Mesa computes it: 2 / (right − left) of the bounds taken as floats
float orthoScale(double half) { return 2.0f / (static_cast<float>(half) - static_cast<float>(-half)); }

// Mesa's extension (GL_MESA_pack_invert): glReadPixels writes the rows top first, as frames are stored
constexpr GLenum kPackInvert = 0x8758;

}  // namespace

GlContext::GlContext(int width, int height, Antialiasing aa) : width_(width), height_(height), aa_(aa), samplesNow_(aa.samples) {
  const int w = width * aa.supersample, h = height * aa.supersample;
  if (aa.samples != 1 && aa.samples != 2 && aa.samples != static_cast<int>(kSamplePositions.size()))
    throw std::invalid_argument("GlContext: " + std::to_string(aa.samples) + " samples per pixel (1, 2 or 4)");
  loadGlLibrary();
  // RGBA, 24 depth bits (unused in 2D, but llvmpipe pairs stencil with depth), 8 stencil bits
  context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!context_) throw std::runtime_error("OSMesa could not create an OpenGL context (is libosmesa6 installed?)");
  // OSMesa's own buffer: a pixel, since frames are drawn into the framebuffer object below
  buffer_.resize(4);
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
    OSMesaDestroyContext(context_);
    throw std::runtime_error("OSMesa could not make its OpenGL context current");
  }
  glGenFramebuffers(1, &framebuffer_);
  glGenRenderbuffers(2, renderbuffers_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
  // under a memory limit llvmpipe leaves a buffer without storage (width 0) and says nothing: the
  // frame size, already within what the renderer draws, was never at fault
  bool outOfMemory = false;
  for (const GLuint buffer : renderbuffers_) {
    GLint made = 0;
    glBindRenderbuffer(GL_RENDERBUFFER, buffer);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &made);
    outOfMemory = outOfMemory || made != w;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[1]);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    OSMesaDestroyContext(context_);
    const std::string size = std::to_string(w) + "×" + std::to_string(h);
    if (outOfMemory)
      throw std::runtime_error(
          "OSMesa could not get the memory for frames of " + size + " (" +
          std::to_string(static_cast<long long>(w) * h * 8 >> 20) +
          " MB of colour and depth); give the process more memory (ulimit -v) or draw smaller frames (--size)");
    throw std::runtime_error("OSMesa cannot draw frames of " + size);
  }
  glGenBuffers(1, &vertexBuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(kPackInvert, 1);
  glViewport(0, 0, w, h);
  clearStencil();
}

GlContext::~GlContext() {
  makeCurrent();
  if (recording_) glEndList();
  for (const unsigned list : lists_) glDeleteLists(list, 1);
  glDeleteBuffers(1, &vertexBuffer_);
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteRenderbuffers(2, renderbuffers_);
  OSMesaDestroyContext(context_);
}

std::string GlContext::renderer() {
  makeCurrent();
  const GLubyte* s = glGetString(GL_RENDERER);
  return s ? reinterpret_cast<const char*>(s) : "unknown";
}

std::string GlContext::version() {
  makeCurrent();
  const GLubyte* s = glGetString(GL_VERSION);
  return s ? reinterpret_cast<const char*>(s) : "unknown";
}

void GlContext::makeCurrent() {
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
    throw std::runtime_error("OSMesa could not make its OpenGL context current");
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
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

void GlContext::beginFrame(bool byCanvas2d) {
  if (recording_) glEndList();
  // each drawing of the frame starts from a cleared stencil (read()), so its values count from 1
  lastStencil_ = 0;
  drawnWithin_.reset();
  movingWithin_.reset();
  key_.clear();
  part_ = 0;
  samplesNow_ = aa_.samples;
  staticStencil_ = false;
  clears_ = clearsDepth_ = false;
  ortho_.reset();
  byCanvas2d_ = byCanvas2d;
  direct_ = {false, false};
  once_.clear();
  onceTriangles_.clear();
  onceGroups_ = 0;
  steps_.clear();
  triangles_.clear();
  beginList();
  recording_ = true;
}

void GlContext::beginList() {
  if (lists_.size() <= steps_.size()) lists_.push_back(glGenLists(1));
  glNewList(lists_[steps_.size()], GL_COMPILE);
}

void GlContext::endStep(size_t first) {
  glEndList();
  steps_.push_back({part_, lists_[steps_.size()], first, triangles_.size() - first, opaque(first)});
}

void GlContext::drawTriangles(size_t first) {
  if (first >= triangles_.size()) return;
  if (recording_) {
    // Kept, not compiled: a display list copies an array's vertices into small blocks of its own
    // (a 5,050-box pile's frame spent a fifth of its time in malloc and free), where a buffer takes
    // them in one copy and each sample position's drawing reads them from there
    endStep(first);
    beginList();
    return;
  }
  glVertexPointer(2, GL_FLOAT, sizeof(TriangleVertex), &triangles_[first].x);
  glColorPointer(4, GL_FLOAT, sizeof(TriangleVertex), &triangles_[first].r);
  drawArrays(0, triangles_.size() - first, opaque(first));
  triangles_.resize(first);
}

bool GlContext::opaque(size_t first) const {
  for (size_t i = first; i < triangles_.size(); ++i)
    if (!(triangles_[i].a >= 1.0f)) return false;
  return true;
}

void GlContext::drawArrays(size_t first, size_t count, bool opaque) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  // opaque triangles drawn without blending or the stencil test, as llvmpipe draws fastest: the
  // same pixels (alpha 1 blends to the source exactly; a batch's stencil test passes all and keeps
  // all), and an eighth off the 210-box half-plane pile's 720p render
  const bool blend = opaque && glIsEnabled(GL_BLEND), stencil = opaque && glIsEnabled(GL_STENCIL_TEST);
  if (blend) glDisable(GL_BLEND);
  if (stencil) glDisable(GL_STENCIL_TEST);
  glDrawArrays(GL_TRIANGLES, static_cast<GLint>(first), static_cast<GLsizei>(count));
  if (blend) glEnable(GL_BLEND);
  if (stencil) glEnable(GL_STENCIL_TEST);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

void GlContext::sendTriangles() {
  if (triangles_.empty()) return;
  const size_t bytes = triangles_.size() * sizeof(TriangleVertex);
  glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
  // the buffer grows (to twice what a frame asks, so that a growing pile does not remake it each
  // frame) and is otherwise overwritten in place
  if (bytes > bufferBytes_) {
    bufferBytes_ = 2 * bytes;
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bufferBytes_), nullptr, GL_STREAM_DRAW);
  }
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), triangles_.data());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void GlContext::drawSteps(int parts) {
  // the triangles from the buffer sendTriangles() filled (client arrays are not part of a list)
  glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
  glVertexPointer(2, GL_FLOAT, sizeof(TriangleVertex), reinterpret_cast<const void*>(offsetof(TriangleVertex, x)));
  glColorPointer(4, GL_FLOAT, sizeof(TriangleVertex), reinterpret_cast<const void*>(offsetof(TriangleVertex, r)));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  for (const Step& step : steps_) {
    if (step.part >= parts) break;
    glCallList(step.list);
    if (step.count > 0) drawArrays(step.first, step.count, step.opaque);
  }
}

void GlContext::drawnWithin(const Bounds& pixels) { drawnWithin_ = pixels; }

void GlContext::fewerSamples(int samples) {
  if (samples == 2 && aa_.samples == 4 && aa_.fewerWhenDense) samplesNow_ = 2;
}

void GlContext::clearFrame(const Color& background, bool depth) {
  clears_ = true;
  clearsDepth_ = depth;
  clearColor_ = {static_cast<float>(background.r), static_cast<float>(background.g), static_cast<float>(background.b), 1.0f};
}

void GlContext::endStaticPart(std::vector<double> key) {
  if (!recording_ || part_ != 0) return;
  endStep(triangles_.size());
  key_ = std::move(key);
  staticStencil_ = lastStencil_ > 0;
  part_ = 1;
  beginList();
}

void GlContext::movingWithin(const Bounds& pixels) { movingWithin_ = pixels; }

void GlContext::orthographic(double halfWidth, double halfHeight) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-halfWidth, halfWidth, -halfHeight, halfHeight, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  // a second view in one frame (an overlay's) would leave the first one's triangles unknown
  if (recording_ && ortho_) byCanvas2d_ = false;
  ortho_ = std::array<float, 2>{orthoScale(halfWidth), orthoScale(halfHeight)};
}

void GlContext::drawsDirectly() {
  if (recording_) direct_[static_cast<size_t>(part_)] = true;
}

void GlContext::beginOnce() { ++onceGroups_; }

void GlContext::drawnOnce(const TriangleVertex* vertices, size_t count) {
  if (!recording_ || count == 0) return;
  // (the list being recorded is step steps_.size()'s, drawn before that step's triangles)
  once_.push_back({steps_.size(), part_, onceGroups_, onceTriangles_.size(), count});
  onceTriangles_.insert(onceTriangles_.end(), vertices, vertices + count);
}

bool GlContext::softwareAgrees() {
  if (softwareAgrees_) return *softwareAgrees_;
  // probe triangles drawn at the pixel centers, by GL and in software, in a view a pixel a unit
  const float halfWidth = static_cast<float>(width_) / 2.0f, halfHeight = static_cast<float>(height_) / 2.0f;
  RasterView view;
  view.scaleX = orthoScale(halfWidth), view.scaleY = orthoScale(halfHeight);
  view.halfWidth = view.translateX = halfWidth, view.halfHeight = view.translateY = halfHeight;
  const std::vector<TriangleVertex> probe = probeTriangles(view, width_, height_);
  if (probe.empty()) return *(softwareAgrees_ = false);
  glViewport(0, 0, width_, height_);
  glDisable(GL_SCISSOR_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-halfWidth, halfWidth, -halfHeight, halfHeight, -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glVertexPointer(2, GL_FLOAT, sizeof(TriangleVertex), &probe[0].x);
  glColorPointer(4, GL_FLOAT, sizeof(TriangleVertex), &probe[0].r);
  // the opaque triangles as a batch of them is drawn (blending and the stencil test off), the
  // translucent ones after them as GlCanvas draws them (blended, under a stencil test that passes)
  const auto translucent = std::find_if(probe.begin(), probe.end(), [](const TriangleVertex& v) { return !(v.a >= 1.0f); });
  const size_t opaqueCount = static_cast<size_t>(translucent - probe.begin());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  drawArrays(0, opaqueCount, true);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  drawArrays(opaqueCount, probe.size() - opaqueCount, false);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
  glVertexPointer(2, GL_FLOAT, sizeof(TriangleVertex), nullptr);
  glColorPointer(4, GL_FLOAT, sizeof(TriangleVertex), nullptr);
  std::vector<uint8_t> byGl(static_cast<size_t>(width_) * height_ * 4), bySoftware(byGl.size(), 0);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, byGl.data());
  for (size_t i = 3; i < bySoftware.size(); i += 4) bySoftware[i] = 255;
  rasterTriangles(probe.data(), probe.size(), view, {bySoftware.data(), 0, 0, width_, height_});
  // (the frame's own drawing sets the viewport, the clear and the view again)
  softwareAgrees_ = byGl == bySoftware;
  return *softwareAgrees_;
}

bool GlContext::softwareDraws(int firstPart) const {
  if (!softwareAllowed_ || !byCanvas2d_ || !ortho_ || aa_.supersample != 1 || samplesNow_ < 2) return false;
  for (int part = firstPart; part < 2; ++part)
    if (direct_[part]) return false;
  for (const Step& step : steps_)
    if (step.part >= firstPart && step.count > 0 &&
        !rasterizesAlike(&triangles_[step.first], step.count, (*ortho_)[0], (*ortho_)[1]))
      return false;
  for (const OnceRange& once : once_)
    if (once.part >= firstPart && !rasterizesAlike(&onceTriangles_[once.first], once.count, (*ortho_)[0], (*ortho_)[1]))
      return false;
  return true;
}

bool GlContext::drawnInSoftware(uint8_t* frame, const Region& moving) {
  // the moving part's triangles over the kept static part's own drawings at each sample position
  if (staticDrawings_ != samplesNow_ || moving.x0 < staticRegion_.x0 || moving.y0 < staticRegion_.y0 ||
      moving.x1 > staticRegion_.x1 || moving.y1 > staticRegion_.y1)
    return false;
  if (!softwareDraws(1) || !softwareAgrees()) return false;
  const size_t keptRow = static_cast<size_t>(staticRegion_.x1 - staticRegion_.x0) * 4;
  const size_t row = static_cast<size_t>(moving.x1 - moving.x0) * 4;
  rasterize(frame, moving, 1, [&](int k, uint8_t* drawing) {
    for (int r = 0; r < moving.y1 - moving.y0; ++r)
      std::memcpy(drawing + r * row,
                  staticSamples_[k].data() + (staticRegion_.y1 - moving.y1 + r) * keptRow + (moving.x0 - staticRegion_.x0) * 4,
                  row);
  });
  return true;
}

bool GlContext::drawnWholeInSoftware(uint8_t* frame, const Region& region) {
  // every part's triangles over the background, which is the frame outside `region`
  if (!clears_ || !softwareDraws(0) || !softwareAgrees()) return false;
  const std::array<uint8_t, 4> background = clearBytes();
  const auto fill = [&](uint8_t* at, size_t pixels) {
    for (size_t i = 0; i < pixels; ++i) std::memcpy(at + 4 * i, background.data(), 4);
  };
  const auto fillStart = std::chrono::steady_clock::now();
  fill(frame, static_cast<size_t>(width_) * height_);
  if (cost_) cost_->raster += std::chrono::duration<double>(std::chrono::steady_clock::now() - fillStart).count();
  const size_t pixels = static_cast<size_t>(region.x1 - region.x0) * (region.y1 - region.y0);
  rasterize(frame, region, 0, [&](int, uint8_t* drawing) { fill(drawing, pixels); });
  return true;
}

void GlContext::rasterize(uint8_t* frame, const Region& region, int firstPart, const std::function<void(int, uint8_t*)>& under) {
  const auto drawStart = std::chrono::steady_clock::now();
  const size_t bytes = static_cast<size_t>(region.x1 - region.x0) * (region.y1 - region.y0) * 4;
  for (int k = 0; k < samplesNow_; ++k) {
    samples_[k].resize(bytes);
    under(k, samples_[k].data());
    const std::array<float, 2> at =
        samplesNow_ == 4 ? kSamplePositions[static_cast<size_t>(k)] : kTwoSamplePositions[static_cast<size_t>(k)];
    RasterView view;
    view.scaleX = (*ortho_)[0], view.scaleY = (*ortho_)[1];
    view.halfWidth = static_cast<float>(width_) / 2.0f, view.halfHeight = static_cast<float>(height_) / 2.0f;
    // (as glViewportIndexedf's translation: the shift, then half the size added in floats)
    view.translateX = (0.5f - at[0]) + view.halfWidth, view.translateY = (0.5f - at[1]) + view.halfHeight;
    const RasterTarget target{samples_[k].data(), region.x0, region.y0, region.x1, region.y1};
    // each step's primitives drawn once a sample (its list's), then its triangles; the stamps
    // cleared for each drawing, as GL's stencil is
    if (!once_.empty()) stamps_.assign(bytes / 4, 0);
    auto once = once_.begin();
    for (size_t s = 0; s < steps_.size(); ++s) {
      const Step& step = steps_[s];
      for (; once != once_.end() && once->step == s; ++once)
        if (once->part >= firstPart)
          rasterTriangles(&onceTriangles_[once->first], once->count, view, target, stamps_.data(), once->group);
      if (step.part >= firstPart && step.count > 0) rasterTriangles(&triangles_[step.first], step.count, view, target);
    }
  }
  if (cost_) cost_->raster += std::chrono::duration<double>(std::chrono::steady_clock::now() - drawStart).count();
  resolveInto(frame, region, false, samplesNow_);
  ++softwareFrames_;
}

std::array<uint8_t, 4> GlContext::clearBytes() {
  // GL's own bytes for the clear colour: cleared and read back once per colour
  if (clearColor_ != clearedColor_) {
    glDisable(GL_SCISSOR_TEST);
    glClearColor(clearColor_[0], clearColor_[1], clearColor_[2], clearColor_[3]);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, clearedBytes_.data());
    clearedColor_ = clearColor_;
  }
  return clearedBytes_;
}

Image GlContext::read() {
  Image frame;
  read(frame);
  return frame;
}

GlContext::Region GlContext::regionOf(const Bounds& b) const {
  const int w = width_ * aa_.supersample, h = height_ * aa_.supersample;
  // what the canvas said, widened by two pixels for the shift and the rounding (clamped as doubles
  // first: a half-plane's vertices lie far outside the frame)
  const auto pixel = [&](double v, double size) { return static_cast<int>(std::clamp(v * aa_.supersample, -4.0, size + 4.0)); };
  Region r;
  if (b.empty()) return r;
  r.x0 = std::clamp(pixel(std::floor(b.min.x()), w) - 2, 0, w);
  r.x1 = std::clamp(pixel(std::ceil(b.max.x()), w) + 2, r.x0, w);
  r.y0 = std::clamp(h - pixel(std::ceil(b.max.y()), h) - 2, 0, h);
  r.y1 = std::clamp(h - pixel(std::floor(b.min.y()), h) + 2, r.y0, h);
  return r;
}

void GlContext::resolveRegion(uint8_t* frame, int parts, const Region& region, bool firstWhole, bool stencil, bool keep) {
  const int w = width_ * aa_.supersample, h = height_ * aa_.supersample;
  const int bw = region.x1 - region.x0, bh = region.y1 - region.y0;
  const int drawings = region.empty() ? 1 : samplesNow_;
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  for (int k = 0; k < drawings; ++k) {
    // the pixel centers (x + 0.5, y + 0.5) onto the sample positions: the drawing shifted by their
    // difference, a multiple of 1/8 px, which GL's 1/256 px vertex grid keeps exact
    const std::array<float, 2> at = drawings == 4   ? kSamplePositions[static_cast<size_t>(k)]
                                    : drawings == 2 ? kTwoSamplePositions[static_cast<size_t>(k)]
                                                    : std::array{0.5f, 0.5f};
    const auto drawStart = Clock::now();
    glViewportIndexedf(0, 0.5f - at[0], 0.5f - at[1], static_cast<float>(w), static_cast<float>(h));
    // the frame's clears first, of the whole frame: llvmpipe clears whole tiles at memory speed,
    // while under a scissor Mesa clears by drawing a quad through the fragment shader (a profile of
    // a 3D render found the drawings' shader time 6 times larger with the clears scissored)
    GLbitfield clear = stencil ? kStencilClear : 0;
    if (clears_) {
      glClearColor(clearColor_[0], clearColor_[1], clearColor_[2], clearColor_[3]);
      clear |= GL_COLOR_BUFFER_BIT | (clearsDepth_ ? kStencilClear : 0);
    }
    if (clear & kStencilClear) {
      glStencilMask(0xff);
      glClearStencil(0);
      glClearDepth(1.0);
      glDepthMask(GL_TRUE);
    }
    if (clear) glClear(clear);
    // after the first, only where the frame differs from the background (or from the static part)
    const bool whole = k == 0 && firstWhole;
    if (!whole) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(region.x0, region.y0, bw, bh);
    }
    drawSteps(parts);
    glDisable(GL_SCISSOR_TEST);
    auto readStart = Clock::now();
    if (cost_) {
      glFinish();
      cost_->raster += since(drawStart);
      readStart = Clock::now();
    }
    if (whole) {
      glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, frame);
    } else {
      samples_[k].resize(static_cast<size_t>(bw) * bh * 4);
      glReadPixels(region.x0, region.y0, bw, bh, GL_RGBA, GL_UNSIGNED_BYTE, samples_[k].data());
    }
    if (cost_) cost_->readback += since(readStart);
  }
  if (drawings == 1) return;
  if (keep) keepStaticSamples(frame, region, firstWhole, drawings);
  resolveInto(frame, region, firstWhole, drawings);
}

void GlContext::resolveInto(uint8_t* frame, const Region& region, bool firstWhole, int drawings) {
  const auto resolveStart = std::chrono::steady_clock::now();
  const int w = width_ * aa_.supersample, h = height_ * aa_.supersample;
  // rows top first: the region's top row is the frame's row h − y1
  const size_t row = static_cast<size_t>(region.x1 - region.x0) * 4;
  for (int r = 0; r < region.y1 - region.y0; ++r) {
    uint8_t* at = frame + (static_cast<size_t>(h - region.y1 + r) * w + region.x0) * 4;
    const uint8_t* first = firstWhole ? at : samples_[0].data() + r * row;
    if (drawings == 2) resolveTwoSamples(first, samples_[1].data() + r * row, at, row);
    else
      resolveSamples({first, samples_[1].data() + r * row, samples_[2].data() + r * row, samples_[3].data() + r * row}, at, row);
  }
  if (cost_) cost_->resolve += std::chrono::duration<double>(std::chrono::steady_clock::now() - resolveStart).count();
}

void GlContext::keepStaticSamples(const uint8_t* frame, const Region& region, bool firstWhole, int drawings) {
  const int w = width_ * aa_.supersample, h = height_ * aa_.supersample;
  const size_t row = static_cast<size_t>(region.x1 - region.x0) * 4;
  for (int k = 0; k < drawings; ++k) {
    if (k > 0 || !firstWhole) {
      staticSamples_[k] = samples_[k];
      continue;
    }
    // the first drawing is the whole frame: its rows within the region
    staticSamples_[0].resize(row * (region.y1 - region.y0));
    for (int r = 0; r < region.y1 - region.y0; ++r)
      std::memcpy(staticSamples_[0].data() + r * row, frame + (static_cast<size_t>(h - region.y1 + r) * w + region.x0) * 4, row);
  }
  staticRegion_ = region;
  staticDrawings_ = drawings;
}

void GlContext::read(Image& frame) {
  const int w = width_ * aa_.supersample, h = height_ * aa_.supersample;
  const size_t bytes = static_cast<size_t>(w) * h * 4;
  // the frame itself takes the first drawing, unless it is to be downsampled
  uint8_t* first = nullptr;
  if (aa_.supersample == 1) {
    frame.width = w;
    frame.height = h;
    frame.rgba.resize(bytes);
    first = frame.rgba.data();
  } else {
    drawn_.resize(bytes);
    first = drawn_.data();
  }
  const bool recorded = recording_;
  if (recorded) {
    endStep(triangles_.size());
    sendTriangles();
  }
  recording_ = false;
  // a frame that marks no pixels in the stencil (opaque shapes only) needs no cleared stencil
  const bool stencil = lastStencil_ > 0;
  if (!recorded) {
    // drawn at once (no beginFrame): what the framebuffer holds is the frame, at the pixel centers
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, first);
  } else if (part_ == 1 && movingWithin_ && drawnWithin_ && aa_.samples > 1) {
    // The static part's frame is kept once two frames in a row have the same static part. Outside
    // the moving part's region only the static part draws, at every sample position, so the pixels
    // there are the kept frame's; inside it the whole frame is drawn at the four positions, as
    // everywhere before (a pixel's value does not depend on the scissor). Byte for byte the frame
    // the four whole drawings make.
    if (kept_.size() != bytes || keptKey_ != key_ || keptSamples_ != samplesNow_) {
      if (lastKey_ == key_) {
        kept_.resize(bytes);
        staticDrawings_ = 0;
        resolveRegion(kept_.data(), 1, regionOf(*drawnWithin_), true, staticStencil_, true);
        keptKey_ = key_;
        keptSamples_ = samplesNow_;
      } else {
        kept_.clear();
        keptKey_.clear();
      }
    }
    lastKey_ = key_;
    if (!kept_.empty()) {
      const auto copyStart = std::chrono::steady_clock::now();
      std::memcpy(first, kept_.data(), bytes);
      if (cost_) cost_->resolve += std::chrono::duration<double>(std::chrono::steady_clock::now() - copyStart).count();
      const Region moving = regionOf(*movingWithin_);
      if (!moving.empty() && !drawnInSoftware(first, moving)) resolveRegion(first, 2, moving, false, stencil);
    } else {
      resolveRegion(first, 2, regionOf(*drawnWithin_), true, stencil);
    }
  } else {
    // where the drawings at the other positions may differ from the first: what the canvas said,
    // or the whole frame
    const Region all = drawnWithin_ ? regionOf(*drawnWithin_) : Region{0, 0, w, h};
    if (!drawnWholeInSoftware(first, all)) resolveRegion(first, 2, all, true, stencil);
  }
  // a skipped clear left older frames' values in the stencil: a primitive drawn at once (not
  // recorded) clears it before taking a value
  if (!stencil) lastStencil_ = 255;
  if (aa_.supersample == 1) return;
  Image drawn;
  drawn.width = w;
  drawn.height = h;
  drawn.rgba = drawn_;
  frame = downsample(drawn, aa_.supersample);
}

}  // namespace render::draw
