#include "render/draw/gl_canvas.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/jobs/interrupt.h"

namespace render::draw {

using sim::core::Vec2;
namespace {

const Color kWhite{1.0, 1.0, 1.0, 1.0};
const Color kBlack{0.0, 0.0, 0.0, 1.0};

// a unit vector at a right angle to d, counter-clockwise
Vec2 perpendicular(const Vec2& d) { return {-d.y(), d.x()}; }

}  // namespace

GlCanvas::GlCanvas(GlContext& gl, TextRenderer& text, const Style& style)
    : gl_(gl), textRenderer_(text), style_(style), batch_(gl.triangleStore()) {}

void GlCanvas::begin(const Camera& camera) { start(camera, true); }

void GlCanvas::beginOverlay(const Camera& camera) { start(camera, false); }

void GlCanvas::start(const Camera& camera, bool clear) {
  // a new frame is recorded, to be drawn at each sample position; an overlay adds to the frame begun
  if (clear) gl_.beginFrame(true);
  // a frame begun here is all drawn by this canvas, which can say where (finish()); an overlay's
  // frame has drawing the canvas did not see
  bounded_ = clear;
  drawn_ = Bounds();
  under_.reset();
  moving_ = Bounds();
  inStatic_ = clear, staticLate_ = false, staticDrew_ = false;
  key_.clear();
  // the static part is drawn through this camera, over this background
  keyed({camera.center().x(), camera.center().y(), camera.pixelSize(), static_cast<double>(camera.widthPx()),
         static_cast<double>(camera.heightPx()), style_.background.r, style_.background.g, style_.background.b});
  camera_ = camera;
  px_ = camera.pixelSize();
  texts_.clear();
  lateDots_.clear();
  smallBodies_ = largeBodies_ = 0;
  // 2D drawing in call order: no depth test; straight alpha blending that keeps the frame opaque
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xff);
  stencil_ = glStencil_ = -1;  // unknown: the first primitive sets the stencil state
  once_ = false;
  batchFirst_ = batch_.size();
  batching_ = false;
  drawCalls_ = 0;
  // the color only (an overlay keeps what is drawn): each primitive's stencil value is one no pixel
  // holds (GlContext::freshStencil)
  if (clear) gl_.clearFrame(style_.background, false);
  // world units, y up, centered on the camera: vertices are sent relative to the center, so that
  // single-precision GL keeps its digits for what is on screen
  gl_.orthographic(0.5 * camera.worldWidth(), 0.5 * camera.worldHeight());
}

Image GlCanvas::finish() {
  Image image;
  finish(image);
  return image;
}

void GlCanvas::enter(Role role) {
  const bool isStatic = role == Role::StaticBody;
  if (!bounded_ || isStatic == inStatic_) return;
  if (isStatic) {
    staticLate_ = true;
    return;
  }
  inStatic_ = false;
  flush();
  gl_.endStaticPart(std::move(key_));
  key_.clear();
}

void GlCanvas::finish(Image& image) {
  const auto inPixels = [&](const Bounds& world) {
    Bounds pixels;
    if (!world.empty()) pixels.add(camera_.toPixel(world.min)), pixels.add(camera_.toPixel(world.max));
    return pixels;
  };
  flush();
  if (bounded_) {
    gl_.drawnWithin(inPixels(drawn_));
    if (inStatic_) enter(Role::Body);
    if (!staticLate_ && staticDrew_) gl_.movingWithin(inPixels(moving_));
  } else if (under_) {
    Bounds pixels = inPixels(drawn_);
    pixels.add(*under_);
    gl_.drawnWithin(pixels);
  }
  under_.reset();
  if (bounded_ && smallBodies_ >= kDenseBodies && largeBodies_ == 0) gl_.fewerSamples(2);
  gl_.read(image);
  // the dots nothing drew over, then the text over everything
  if (!lateDots_.empty()) {
    DotLayer dots;
    for (const LateDot& d : lateDots_) dots.add(camera_.toPixel(d.at), d.radiusPx, d.corners, d.color);
    lateDots_.clear();
    dots.drawInto(image, samplePositions(gl_.samples(), gl_.scale()));
  }
  // a halo of the background around each letter, a tenth of the size: legible over any line
  const int halo = std::max(1, style_.fontSize / 10);
  for (const QueuedText& t : texts_)
    textRenderer_.draw(image, t.text, t.pixel.x(), t.pixel.y(), t.anchor, style_.fontSize, t.color,
                       style_.background.withAlpha(t.color.a), halo);
  texts_.clear();
}

namespace {

// hue (degrees) and saturation of a colour (HSV)
std::pair<double, double> hueAndSaturation(const Color& c) {
  const double hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b}), chroma = hi - lo;
  if (!(chroma > 0.0)) return {0.0, 0.0};
  double h = hi == c.r   ? std::fmod((c.g - c.b) / chroma, 6.0)
             : hi == c.g ? (c.b - c.r) / chroma + 2.0
                         : (c.r - c.g) / chroma + 4.0;
  h *= 60.0;
  if (h < 0.0) h += 360.0;
  return {h, chroma / hi};
}

}  // namespace

bool GlCanvas::alike(const Color& a, const Color& b) {
  // hard to tell apart: two saturated colours within 40° of hue, or two close in every channel
  const auto [ha, sa] = hueAndSaturation(a);
  const auto [hb, sb] = hueAndSaturation(b);
  const double hue = std::min(std::abs(ha - hb), 360.0 - std::abs(ha - hb));
  const double distance = std::sqrt((a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) + (a.b - b.b) * (a.b - b.b));
  return (sa > 0.25 && sb > 0.25 && hue < 40.0) || distance < 0.25;
}

Color GlCanvas::fillColor(const Pen& s) const {
  switch (s.role) {
    case Role::Body:
    case Role::BodyPart: return style_.body(s.body).mixed(kWhite, 0.35);
    case Role::StaticBody: return style_.body(s.body).mixed(kWhite, 0.6);
    case Role::RotationalBar: return style_.body(s.body).mixed(kWhite, 0.45);
    // a panel lets what is behind it show a little
    case Role::Panel: return style_.role(Role::Panel).withAlpha(0.85);
    // a text's backing lets the hatching or body under it show faintly
    case Role::Backing: return style_.role(Role::Backing).withAlpha(0.8);
    default: return strokeColor(s);
  }
}

Color GlCanvas::strokeColor(const Pen& s) const {
  // a teaching arrow's own `color`
  if (s.color >= 0 && s.color < static_cast<int>(style_.arrows.size()) && style_.arrows[s.color].a > 0.0)
    return style_.arrows[s.color];
  switch (s.role) {
    case Role::Body:
    case Role::BodyEdge:
    case Role::BodyAxis: return style_.body(s.body).mixed(kBlack, 0.35);
    case Role::StaticBody: return style_.body(s.body).mixed(kBlack, 0.25);
    // a trail is its body's color (the trail color's for none), as the bars are
    case Role::Trail: return style_.body(s.body);
    default: return info(s.role).colorKey.empty() ? style_.body(s.body) : style_.role(s.role);
  }
}

double GlCanvas::strokeWidth(Role role) const { return info(role).width * style_.lineWidth; }

void GlCanvas::polygon(const std::vector<Vec2>& vertices, const Pen& s) {
  if (vertices.empty()) return;
  enter(s.role);
  // bars and panels are areas without an outline
  if (info(s.role).area) {
    if (s.role == Role::BodyPart) {
      Bounds extent;
      for (const Vec2& v : vertices) extent.add(v);
      countBody(extent.size().maxCoeff());
    }
    beginPrimitive(fillColor(s), s.opacity, false, false);
    fillConvex(vertices);
    return;
  }
  const bool solid = s.role == Role::Body || s.role == Role::StaticBody;
  if (s.role == Role::Body) {
    Bounds extent;
    for (const Vec2& v : vertices) extent.add(v);
    countBody(extent.size().maxCoeff());
  }
  // an opaque moving body a few pixels across: two fills, fewer triangles than a fill and its outline
  const bool opaque = s.opacity >= 1.0 && fillColor(s).a >= 1.0 && strokeColor(s).a >= 1.0;
  if (s.role == Role::Body && opaque && fillOutlined(vertices, fillColor(s), strokeColor(s), strokeWidth(s.role))) return;
  if (solid) {
    beginPrimitive(fillColor(s), s.opacity, s.role == Role::StaticBody, false);
    fillConvex(vertices);
    if (s.role == Role::StaticBody) {
      Bounds area;
      for (const Vec2& v : vertices) area.add(v);
      hatch(area, strokeColor(s), s.opacity);
    }
  }
  beginPrimitive(strokeColor(s), s.opacity);
  strokeClosed(vertices, strokeWidth(s.role));
}

void GlCanvas::circle(const Vec2& center, double radius, const Pen& s) {
  enter(s.role);
  // a part of a body made of parts: filled; its outline comes in pieces (Role::BodyEdge)
  if (s.role == Role::BodyPart) {
    countBody(2.0 * radius);
    beginPrimitive(fillColor(s), s.opacity, false, false);
    fillDisc(center, radius);
    return;
  }
  const bool solid = s.role == Role::Body || s.role == Role::StaticBody;
  if (s.role == Role::Body) countBody(2.0 * radius);
  if (solid) {
    beginPrimitive(fillColor(s), s.opacity, s.role == Role::StaticBody, false);
    fillDisc(center, radius);
    if (s.role == Role::StaticBody) {
      Bounds area;
      area.add(center - Vec2(radius, radius));
      area.add(center + Vec2(radius, radius));
      hatch(area, strokeColor(s), s.opacity);
    }
  }
  beginPrimitive(strokeColor(s), s.opacity);
  ring(center, radius, strokeWidth(s.role));
}

void GlCanvas::countBody(double extent) {
  // (NaN counts as large: a frame that cannot say is drawn at four)
  if (extent < kSmallOutlinePx * px_) ++smallBodies_;
  else ++largeBodies_;
}

void GlCanvas::halfPlane(const Vec2& point, const Vec2& normal, const Pen& s) {
  if (!(normal.norm() > 0.0)) return;
  enter(s.role);
  const Vec2 n = normal.normalized(), t = perpendicular(n);
  const Bounds view = camera_.view();
  // the boundary point nearest the view's center, and a length that reaches past every corner
  const Vec2 p0 = point + t * t.dot(view.center() - point);
  const double reach = view.size().norm() + (view.center() - p0).norm();
  beginPrimitive(fillColor(s), s.opacity, true);
  // the solid side is n·(r − p) ≤ 0: a quad from the boundary away from n, clipped by GL
  fillConvex({p0 - t * reach, p0 + t * reach, p0 + t * reach - n * reach, p0 - t * reach - n * reach});
  hatch(view, strokeColor(s), s.opacity);
  beginPrimitive(strokeColor(s), s.opacity);
  strokeSegment(p0 - t * reach, p0 + t * reach, strokeWidth(s.role));
}

void GlCanvas::segment(const Vec2& a, const Vec2& b, const Pen& s) {
  enter(s.role);
  beginPrimitive(strokeColor(s), s.opacity);
  strokeSegment(a, b, strokeWidth(s.role));
}

void GlCanvas::point(const Vec2& p, const Pen& s) {
  enter(s.role);
  const double w = style_.lineWidth;
  const bool many = manyDotRadius_ > 0.0;
  const double tolerance = many ? 0.25 : 0.05;
  switch (s.role) {
    case Role::CenterOfMass: {
      // the quartered disc: two opposite quarters in the role's color, two in the background
      const double r = 5.0 * w * px_;
      beginPrimitive(style_.background, s.opacity, false, false);
      fillDisc(p, r, tolerance);
      beginPrimitive(strokeColor(s), s.opacity, false, false);
      for (int quarter : {0, 2}) {
        std::vector<Vec2> fan{p};
        for (int k = 0; k <= 8; ++k) {
          const double a = 0.5 * std::numbers::pi * (quarter + k / 8.0);
          fan.push_back(p + r * Vec2(std::cos(a), std::sin(a)));
        }
        fillConvex(fan);
      }
      beginPrimitive(strokeColor(s), s.opacity);
      ring(p, r, w);
      break;
    }
    case Role::IncidentVertex:
      // a ring, so the vertex itself stays visible inside it
      beginPrimitive(strokeColor(s), s.opacity);
      ring(p, 4.0 * w * px_, w);
      break;
    case Role::ContactPoint:
      // many: a plain dot scaled to the bodies, whose rim would be under a pixel, blended in after
      // the frame (DotLayer) unless GL draws over it
      if (many) {
        const Color c = strokeColor(s);
        const auto [corners, radius] = manyDot(manyDotRadius_);
        lateDots_.push_back({p, radius, corners, c.withAlpha(c.a * std::clamp(s.opacity, 0.0, 1.0))});
        break;
      }
      // a dot with a rim of the background, visible over a body of the same color
      beginPrimitive(style_.background, s.opacity, false, false);
      fillDisc(p, 2.9 * w * px_, tolerance);
      beginPrimitive(strokeColor(s), s.opacity, false, false);
      fillDisc(p, 2.2 * w * px_, tolerance);
      break;
    default: beginPrimitive(strokeColor(s), s.opacity, false, false); fillDisc(p, 1.6 * w * px_, tolerance);
  }
}

std::pair<int, double> GlCanvas::manyDot(double radiusPx) {
  // every dot of a frame has one radius: worked out once
  if (radiusPx == manyDot_.first && px_ == manyDot_.second) return manyDotShape_;
  manyDot_ = {radiusPx, px_};
  // A dot a pixel or two across needs no more than its area: as few as 4 chords within a quarter
  // pixel, the polygon grown to the disc's area (a frame of 20,000 contact dots drew 8 triangles a
  // dot, three times its 5,050 boxes' triangles)
  const double r = radiusPx * px_;
  const int n = discSegments(r, 0.25, kLeastManyDotSegments);
  const double grow = std::sqrt(std::numbers::pi / (0.5 * n * std::sin(2.0 * std::numbers::pi / n)));
  manyDotShape_ = {discSegments(grow * r, 0.25, kLeastManyDotSegments), grow * radiusPx};
  return manyDotShape_;
}

void GlCanvas::drawLateDots() {
  // taken out first: each dot's beginPrimitive() would come back here
  const std::vector<LateDot> dots = std::move(lateDots_);
  lateDots_.clear();
  for (const LateDot& d : dots) {
    beginPrimitive(d.color.withAlpha(1.0), d.color.a, false, false);
    // the polygon DotLayer covers: `corners` points on the circle of the dot's radius, from angle 0
    const std::vector<Vec2>& circle = unitCircle(d.corners);
    shape(GL_TRIANGLE_FAN);
    for (int i = 0; i < d.corners; ++i) vertex(d.at + d.radiusPx * px_ * circle[static_cast<size_t>(i)]);
    endShape();
  }
}

void GlCanvas::arrow(const Vec2& tail, const Vec2& head, const Pen& s) {
  enter(s.role);
  // an arrow on a body of its own hue (a blue impulse on a blue bar) is outlined in the background,
  // so that the two are always told apart
  if (s.body >= 0 && alike(strokeColor(s), style_.body(s.body))) {
    beginPrimitive(style_.background, s.opacity);
    strokeArrow(tail, head, strokeWidth(s.role), style_.lineWidth);
  }
  beginPrimitive(strokeColor(s), s.opacity);
  strokeArrow(tail, head, strokeWidth(s.role));
}

void GlCanvas::text(const Vec2& at, const std::string& text, const Pen& s) {
  const Anchor anchor = s.role == Role::Caption ? Anchor::TopLeft : Anchor::Center;
  texts_.push_back({camera_.toPixel(at), text, anchor, strokeColor(s).withAlpha(s.opacity)});
}

void GlCanvas::label(const Vec2& anchor, const Vec2& direction, const std::string& text, const Pen& s) {
  const TextBox box = textRenderer_.measure(text, style_.fontSize);
  // in pixels, y down: the direction's y flips
  const Vec2 center = labelCenter(camera_.toPixel(anchor), Vec2(direction.x(), -direction.y()), 0.5 * box.width,
                                  0.5 * (box.ascent + box.descent), style_.fontSize / 3.0);
  texts_.push_back({center, text, Anchor::Center, strokeColor(s).withAlpha(s.opacity)});
}

void GlCanvas::beginPrimitive(const Color& c, double opacity, bool marks, bool overlaps) {
  // a frame of many bodies takes long: Ctrl-C ends it here, not after it (a flag read, no more)
  render::jobs::checkInterrupted();
  // GL draws over the kept dots: they go under it, as drawn in order
  if (!lateDots_.empty()) drawLateDots();
  const double alpha = c.a * std::clamp(opacity, 0.0, 1.0);
  keyed({c.r, c.g, c.b, alpha, marks ? 1.0 : 0.0});
  if ((alpha >= 1.0 || !overlaps) && !marks) {
    // opaque, or one convex fan (GL's rasterization rules cover each sample of it once): overlaps
    // do not show, so no stencil, and no state between primitives: its triangles join the batch,
    // drawn with the others in one call, in order (a stencil change per primitive made
    // contact-heavy frames several times slower, and a call per primitive made frames of many
    // bodies cost in proportion to the calls; fading contact dots, a call each, made a frame of a
    // 210-box pyramid's 800 contacts cost three times its bodies)
    batching_ = true;
    once_ = false;
    color_ = {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b), static_cast<float>(alpha)};
    stencil_ = 0;
    return;
  }
  // translucent or marking: drawn apart, under its own stencil value, after the batch before it
  // (one that does not mark is given to the context too, so that software may draw it)
  flush();
  batching_ = false;
  once_ = !marks;
  if (once_) gl_.beginOnce();
  color_ = {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b), static_cast<float>(alpha)};
  glColor4d(c.r, c.g, c.b, alpha);
  stencil_ = glStencil_ = gl_.freshStencil();
  glStencilFunc(GL_NOTEQUAL, stencil_, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
}

void GlCanvas::vertex(const Vec2& world) {
  drawn_.add(world);
  if (!inStatic_) moving_.add(world);
  else staticDrew_ = true;
  const Vec2& c = camera_.center();
  keyed({world.x() - c.x(), world.y() - c.y()});
  // GL takes the double as a float: the same float here, so that batched pixels are the same
  const BatchVertex v{
      static_cast<float>(world.x() - c.x()), static_cast<float>(world.y() - c.y()), color_[0], color_[1], color_[2], color_[3]};
  if (!batching_) {
    glVertex2d(world.x() - c.x(), world.y() - c.y());
    if (once_) shapeVertex(v, onceShape_);
    return;
  }
  shapeVertex(v, batch_);
}

void GlCanvas::shapeVertex(const BatchVertex& v, std::vector<BatchVertex>& out) {
  if (shapeMode_ == GL_TRIANGLES) {
    out.push_back(v);
    return;
  }
  // the fan's and the strip's triangles as GL makes them (a strip's odd ones with their first two
  // vertices swapped), one after another in the batch
  if (shapeCount_ >= 2) {
    if (shapeMode_ == GL_TRIANGLE_FAN) {
      out.push_back(shapeFirst_), out.push_back(shapePrevious_);
    } else if (shapeCount_ % 2 == 0) {
      out.push_back(shapeFirst_), out.push_back(shapePrevious_);
    } else {
      out.push_back(shapePrevious_), out.push_back(shapeFirst_);
    }
    out.push_back(v);
  }
  // a fan keeps its first vertex and its last; a strip, its last two
  if (shapeCount_ == 0) shapeFirst_ = v;
  else if (shapeMode_ == GL_TRIANGLE_STRIP && shapeCount_ >= 2) shapeFirst_ = shapePrevious_;
  if (shapeCount_ >= 1) shapePrevious_ = v;
  ++shapeCount_;
}

void GlCanvas::shape(unsigned mode) {
  keyed({-1.0, static_cast<double>(mode)});
  shapeMode_ = mode;
  shapeCount_ = 0;
  if (!batching_) {
    ++drawCalls_;
    // (a once primitive's shapes are fans, strips and triangles; any other mode is GL's to draw)
    if (mode != GL_TRIANGLES && mode != GL_TRIANGLE_FAN && mode != GL_TRIANGLE_STRIP) once_ = false;
    if (once_) onceShape_.clear();
    else gl_.drawsDirectly();
    glBegin(mode);
  }
}

void GlCanvas::endShape() {
  if (batching_) return;
  glEnd();
  if (once_) gl_.drawnOnce(onceShape_.data(), onceShape_.size());
}

void GlCanvas::flush() {
  if (batch_.size() == batchFirst_) return;
  // opaque: no stencil test, nothing marked
  if (glStencil_ != 0) {
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencil_ = 0;
  }
  gl_.drawTriangles(batchFirst_);
  ++drawCalls_;
  batchFirst_ = batch_.size();
}

void GlCanvas::fillConvex(const std::vector<Vec2>& vertices) {
  shape(GL_TRIANGLE_FAN);
  for (const Vec2& v : vertices) vertex(v);
  endShape();
}

const std::vector<Vec2>& GlCanvas::unitCircle(int n) {
  // the unit circle's n + 1 points, computed once per segment count and shared by every disc
  std::vector<Vec2>& points = unitCircles_[n];
  if (points.empty())
    for (int i = 0; i <= n; ++i) {
      const double a = 2.0 * std::numbers::pi * i / n;
      points.emplace_back(std::cos(a), std::sin(a));
    }
  return points;
}

int GlCanvas::discSegments(double radius, double tolerance, int least) const {
  // chords within `tolerance` px of the circle: n = π / acos(1 − tolerance / r), r in pixels
  const double r = radius / px_;
  if (!(r > tolerance)) return least;
  // clamped before the conversion: past 10¹⁵ px (a fixed camera a femtometre high) the quotient is
  // infinite, and converting it is undefined behavior
  return static_cast<int>(
      std::clamp(std::ceil(std::numbers::pi / std::acos(1.0 - tolerance / r)), static_cast<double>(least), 720.0));
}

void GlCanvas::fillDisc(const Vec2& center, double radius, double tolerance, int least) {
  const std::vector<Vec2>& circle = unitCircle(discSegments(radius, tolerance, least));
  // a fan from its first rim point: n − 2 triangles, not the n a fan from the center makes, and the
  // same samples (the same outline, each sample inside it covered once by either)
  shape(GL_TRIANGLE_FAN);
  for (size_t i = 0; i + 1 < circle.size(); ++i) vertex(center + radius * circle[i]);
  endShape();
}

void GlCanvas::ring(const Vec2& center, double radius, double width) {
  const double half = 0.5 * width * px_;
  const double inner = std::max(0.0, radius - half), outer = radius + half;
  const std::vector<Vec2>& circle = unitCircle(discSegments(outer));
  shape(GL_TRIANGLE_STRIP);
  for (const Vec2& u : circle) {
    vertex(center + outer * u);
    vertex(center + inner * u);
  }
  endShape();
}

void GlCanvas::strokeSegment(const Vec2& a, const Vec2& b, double width) {
  const double half = 0.5 * width * px_;
  const Vec2 d = b - a;
  if (d.norm() > 1e-9 * px_) {
    const Vec2 side = perpendicular(d.normalized()) * half;
    fillConvex({a - side, b - side, b + side, a + side});
  }
  // round caps, which also join consecutive segments smoothly
  fillDisc(a, half);
  fillDisc(b, half);
}

void GlCanvas::strokeClosed(const std::vector<Vec2>& vertices, double width) {
  const double half = 0.5 * width * px_;
  // an outline whose mitred corners are as good as round: one strip with mitred corners, 2 triangles
  // an edge (the joins were four fifths of a box's triangles)
  if (mitredLooksRound(vertices, half)) {
    strokeMitred(vertices, half);
    return;
  }
  // each edge, and one round join at each vertex: the same pixels as every edge with both its caps
  // (the one color covers them once), with half the discs
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vec2 &a = vertices[i], &b = vertices[(i + 1) % vertices.size()];
    const Vec2 d = b - a;
    if (d.norm() > 1e-9 * px_) {
      const Vec2 side = perpendicular(d.normalized()) * half;
      fillConvex({a - side, b - side, b + side, a + side});
    }
    fillDisc(a, half);
  }
}

bool GlCanvas::mitredLooksRound(const std::vector<Vec2>& vertices, double half) const {
  if (vertices.size() < 3) return false;
  // a polygon a few pixels across: a round join's corner differs by a fifth of a pixel's area
  Bounds extent;
  for (const Vec2& v : vertices) extent.add(v);
  if (extent.size().maxCoeff() < kSmallOutlinePx * px_) return true;
  // a larger one whose every mitred corner lies within half a pixel of its round join (a box's
  // corners under an outline up to 2.4 px wide: 720p's 2 px, not 1080p's 3)
  const size_t n = vertices.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 &prev = vertices[(i + n - 1) % n], &v = vertices[i], &next = vertices[(i + 1) % n];
    // a repeated vertex has no corner to mitre (mitres() would pinch the outline there)
    if (!((v - prev).norm() > 1e-9 * px_)) return false;
    // the corner's point lies half / cos(turn / 2) out, cos²(turn / 2) = (1 + cos turn) / 2
    const double cosTurn = (v - prev).normalized().dot((next - v).normalized());
    if (!(half <= (half + kMitreReachPx * px_) * std::sqrt(0.5 * (1.0 + cosTurn)))) return false;
  }
  return true;
}

std::vector<Vec2> GlCanvas::mitres(const std::vector<Vec2>& vertices, double half) {
  // each vertex's move to the outline's outer corner (its inner corner the opposite way): along
  // its corner's bisector by half / cos(half the turn), whichever way the polygon winds (the
  // signed area's sign)
  const size_t n = vertices.size();
  double area = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 &a = vertices[i], &b = vertices[(i + 1) % n];
    area += a.x() * b.y() - b.x() * a.y();
  }
  const double outward = area >= 0.0 ? -1.0 : 1.0;
  std::vector<Vec2> out(n);
  for (size_t i = 0; i < n; ++i) {
    const Vec2 &prev = vertices[(i + n - 1) % n], &v = vertices[i], &next = vertices[(i + 1) % n];
    const Vec2 d0 = (v - prev).normalized(), d1 = (next - v).normalized();
    // each edge's outward normal, and their mean scaled to reach both offset edges
    const Vec2 n0 = perpendicular(d0) * outward, n1 = perpendicular(d1) * outward;
    const Vec2 mean = n0 + n1;
    const double c = mean.dot(n0);
    // a corner sharper than about 30° (never in a body) keeps a bounded spike
    out[i] = mean.allFinite() && c > 0.07 ? mean * (half / c) : n0 * half;
  }
  return out;
}

void GlCanvas::strokeMitred(const std::vector<Vec2>& vertices, double half) {
  const std::vector<Vec2> miter = mitres(vertices, half);
  shape(GL_TRIANGLE_STRIP);
  for (size_t k = 0; k <= vertices.size(); ++k) {
    const size_t i = k % vertices.size();
    vertex(vertices[i] + miter[i]);
    vertex(vertices[i] - miter[i]);
  }
  endShape();
}

bool GlCanvas::fillOutlined(const std::vector<Vec2>& vertices, const Color& fill, const Color& stroke, double width) {
  const double half = 0.5 * width * px_;
  if (!mitredLooksRound(vertices, half)) return false;
  // a larger body's fill and strip: its area filled twice at each sample position costs more than
  // the strip's six triangles save (the two-body poll's 200 px bodies: 0.42 against 0.37 s for 2 s
  // at 720p; the 210-box pile's 30 px boxes: 1.22 against 1.31 s the other way)
  Bounds extent;
  for (const Vec2& v : vertices) extent.add(v);
  if (!(extent.size().maxCoeff() < kTwoFillsPx * px_)) return false;
  // the inner corners must not cross over: the polygon wider than its outline everywhere (its
  // width across each edge, convex)
  for (size_t k = 0; k < vertices.size(); ++k) {
    const Vec2 e = vertices[(k + 1) % vertices.size()] - vertices[k];
    if (!(e.norm() > 1e-9 * px_)) return false;
    const Vec2 n = perpendicular(e.normalized());
    double lo = n.dot(vertices[0]), hi = lo;
    for (const Vec2& q : vertices) lo = std::min(lo, n.dot(q)), hi = std::max(hi, n.dot(q));
    if (!(hi - lo > 2.0 * half)) return false;
  }
  const std::vector<Vec2> miter = mitres(vertices, half);
  std::vector<Vec2> outer(vertices.size()), inner(vertices.size());
  for (size_t i = 0; i < vertices.size(); ++i) outer[i] = vertices[i] + miter[i], inner[i] = vertices[i] - miter[i];
  // the outline's outer polygon in its color, the inner one over it in the fill's: the same samples
  // as the fill and the mitred strip over it (the inner edge is the strip's, each sample on it
  // given to one side), in 2 (n − 2) triangles rather than n − 2 + 2n
  beginPrimitive(stroke, 1.0, false, false);
  fillConvex(outer);
  beginPrimitive(fill, 1.0, false, false);
  fillConvex(inner);
  return true;
}

void GlCanvas::strokeArrow(const Vec2& tail, const Vec2& head, double width, double outline) {
  const Vec2 d = head - tail;
  const double length = d.norm();
  if (!(length > 1e-9 * px_)) return;
  const Vec2 u = d / length, side = perpendicular(u);
  // the head: long enough to read at a glance, shortened on arrows too short to carry it
  const double headLength = std::min(std::max(10.0, 5.0 * width) * px_, length / 1.5);
  const double headHalfWidth = 0.45 * headLength;
  const Vec2 base = head - u * headLength;
  const double grow = outline * px_, half = 0.5 * width * px_ + grow;
  const Vec2 shaftEnd = head - u * (0.9 * headLength);
  fillConvex({tail - side * half, shaftEnd - side * half, shaftEnd + side * half, tail + side * half});
  fillDisc(tail, half);
  // the head grown by `grow` on every side: its tip moves out by grow / sin of its half angle
  const double tip = grow * std::hypot(headLength, headHalfWidth) / headHalfWidth;
  const double spread = headHalfWidth + grow * (headLength + std::hypot(headLength, headHalfWidth)) / headLength;
  fillConvex({head + u * tip, base - u * grow + side * spread, base - u * grow - side * spread});
}

void GlCanvas::hatch(const Bounds& box, const Color& c, double opacity) {
  // only what the frame shows is hatched: the shape's box cut to the view, grown by a stripe's
  // half width so that no stripe ends inside the frame
  const Bounds view = camera_.view();
  const double half = 0.3 * style_.lineWidth * px_;
  Bounds area;
  area.add(box.min.cwiseMax(view.min - Vec2(half, half)));
  area.add(box.max.cwiseMin(view.max + Vec2(half, half)));
  if (box.empty() || area.empty()) return;
  // only over the pixels the primitive just drawn has marked in the stencil
  glStencilFunc(GL_EQUAL, stencil_, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  keyed({-2.0, c.r, c.g, c.b, c.a * std::clamp(opacity * 0.8, 0.0, 1.0)});
  glColor4d(c.r, c.g, c.b, c.a * std::clamp(opacity * 0.8, 0.0, 1.0));
  // lines rising at 45°, fixed in the world so that they do not crawl when the view changes
  const Vec2 along = Vec2(1.0, 1.0).normalized(), across = perpendicular(along);
  double lo = INFINITY, hi = -INFINITY, from = INFINITY, to = -INFINITY;
  for (const Vec2& corner : {area.min, area.max, Vec2(area.min.x(), area.max.y()), Vec2(area.max.x(), area.min.y())}) {
    lo = std::min(lo, corner.dot(across)), hi = std::max(hi, corner.dot(across));
    from = std::min(from, corner.dot(along)), to = std::max(to, corner.dot(along));
  }
  // stripes at least a pixel apart, and no more of them than the frame is wide and high (a line
  // width of 1e-6 would otherwise ask for billions)
  const double maxStripes = static_cast<double>(camera_.widthPx() + camera_.heightPx());
  double spacing = std::max(5.0 * style_.lineWidth, 1.0) * px_;
  spacing = std::max(spacing, (hi - lo) / maxStripes);
  if (!(spacing > 0.0) || !std::isfinite(hi - lo)) return;
  // counted in whole stripes from the first: k·spacing stays exact and the count is bounded, even
  // where k itself is past 2⁵³ and k + 1 == k
  const double first = std::floor(lo / spacing);
  const long count = static_cast<long>(std::min(std::floor((hi - lo) / spacing) + 2.0, maxStripes + 2.0));
  // every stripe in one call: each quad as the two triangles its fan would make
  shape(GL_TRIANGLES);
  for (long i = 0; i < count; ++i) {
    const double offset = (first + static_cast<double>(i)) * spacing;
    if (offset > hi) break;
    const Vec2 o = across * offset;
    const Vec2 a = o + along * from, b = o + along * to;
    const Vec2 triangles[6] = {a - across * half, b - across * half, b + across * half,
                               a - across * half, b + across * half, a + across * half};
    for (const Vec2& v : triangles) vertex(v);
  }
  endShape();
  glStencilFunc(GL_NOTEQUAL, stencil_, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
}

}  // namespace render::draw
