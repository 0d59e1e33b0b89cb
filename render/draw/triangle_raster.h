// Triangles drawn in software as llvmpipe draws them, sample for sample, so that a frame's moving
// part (a pile's boxes and outlines, a fading arrow) need not go through GL at every sample
// position: there llvmpipe set up and filled each triangle four times a frame, seven tenths of a
// 210-box pile's render.
//
// What llvmpipe does, and this does alike (each step measured against it, tests/render/draw/
// triangle_raster_test.cpp: every sample of thousands of triangles at the four sample positions):
// the vertex in clip space is the projection's scale times the float vertex, rounded once; in the
// window, the viewport's scale and translation applied as one fused multiply-add; the corners
// snapped to its 1/256 px grid (round half to even) after the half-pixel offset; a sample inside
// when strictly inside every edge, or on an edge that is a left one or, level, the triangle's
// bottom in GL's window (y up), the top of the frame as stored; a colour channel rounded half to
// even from the float in [0, 1] times 255; a translucent colour blended in bytes, each channel
// s·a/255 + d·(255 − a)/255 with llvmpipe's products ((t + 128 + (t >> 8)) >> 8 for t = x·y, which
// rounds a quotient just over a half down), saturated. A triangle that reaches outside the view is
// clipped by GL into other triangles, whose edges this does not reproduce: such a frame stays GL's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/draw/gl_context.h"

namespace render::draw {

// how GL maps a batch's vertices (relative to the camera center) to the window at one sample position
struct RasterView {
  float scaleX = 1.0f, scaleY = 1.0f;          // the orthographic projection's (glOrtho's, in floats)
  float halfWidth = 1.0f, halfHeight = 1.0f;   // the viewport's scale: half its size in pixels
  float translateX = 0.0f, translateY = 0.0f;  // its translation, the sample position's shift in it
};

// where the triangles are drawn: the window region [x0, x1) × [y0, y1) (GL's pixels, y up), its
// rows top first (row 0 is y1 − 1), four bytes a pixel, as glReadPixels gives it with the rows inverted
struct RasterTarget {
  uint8_t* rows = nullptr;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// whether GL would draw `count` vertices (whole triangles) as rasterTriangles does: each
// triangle of one colour and inside the view, where GL clips nothing
bool rasterizesAlike(const TriangleVertex* vertices, size_t count, float scaleX, float scaleY);

// triangles that tell this emulation from a near miss, for a view of `view`: upright and level
// edges where a fused multiply-add and a multiply then an add snap a corner to different subpixels,
// one of them on a sample's row or column, and triangles sharing those edges; then translucent
// triangles over an opaque one, on bytes where llvmpipe's blend and exact rounding part (GlContext
// draws them once with GL and in software, and draws in software only if the two agree). None for
// a view under 64 px a side
std::vector<TriangleVertex> probeTriangles(const RasterView& view, int width, int height);

// the triangles drawn over `target` in order: an opaque one's colour written over each sample (a
// pixel's center in the shifted view) it covers, a translucent one's blended over it as llvmpipe
// blends (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA). With `stamps` (one a pixel of `target`, in its
// layout), they are one primitive under a stencil value of its own, as GlCanvas draws a translucent
// stroke: a sample whose stamp is `group` already is left as it is, and the others take that stamp
// (each sample drawn at most once)
void rasterTriangles(const TriangleVertex* vertices, size_t count, const RasterView& view, const RasterTarget& target,
                     uint32_t* stamps = nullptr, uint32_t group = 0);

}  // namespace render::draw
