// The drawing interface implemented with OpenGL 1.x (fixed function, through OSMesa): world
// coordinates, y up, sizes of lines, dots and arrow heads in output pixels whatever the zoom.
// Text is queued and blended in after the GL frame is read back (FreeType, see text.h), so it
// always lies on top; so are the contact dots of a dense frame (DotLayer), under the text, unless
// GL draws after them.
//
// Each translucent call is one "primitive" under a fresh stencil value: a pixel is written at most
// once per primitive, so the overlapping parts of an outline (edge quads and round joins) blend once,
// and a static body's hatching stays inside its shape. Opaque calls leave the stencil alone and are
// batched: their triangles gather in one vertex array, drawn in one call when a translucent one
// comes or the frame ends, so that a frame of many bodies costs a few calls, not a few per body.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "render/draw/camera.h"
#include "render/draw/gl_context.h"
#include "render/draw/style.h"
#include "render/draw/text.h"
#include "render/draw/canvas.h"
#include "render/draw/dot_layer.h"

namespace render::draw {

class GlCanvas final : public Canvas {
 public:
  // are two colours hard to tell apart (an arrow over a body of its hue: it is outlined then)?
  static bool alike(const Color& a, const Color& b);
  GlCanvas(GlContext& gl, TextRenderer& text, const Style& style);

  // start a frame: clear to the background and look through `camera`
  void begin(const Camera& camera);
  // draw over what the frame holds already (a 3D frame's solids), through `camera`
  void beginOverlay(const Camera& camera);
  // an overlay's frame: what was drawn under it lies within `pixels` (output pixels, as
  // GlContext::drawnWithin), so that the frame is bounded by that and the overlay's own drawing
  void drawnUnder(const Bounds& pixels) { under_ = pixels; }
  // the frame, with the queued text on top
  Image finish();
  // the same into `frame`, whose storage is reused when it has the frame's size already
  void finish(Image& frame);

  void polygon(const std::vector<sim::core::Vec2>& vertices, const Pen& style) override;
  void circle(const sim::core::Vec2& center, double radius, const Pen& style) override;
  void halfPlane(const sim::core::Vec2& point, const sim::core::Vec2& normal, const Pen& style) override;
  void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const Pen& style) override;
  void point(const sim::core::Vec2& p, const Pen& style) override;
  void arrow(const sim::core::Vec2& tail, const sim::core::Vec2& head, const Pen& style) override;
  void text(const sim::core::Vec2& at, const std::string& text, const Pen& style) override;
  // where it prefers, measured: a frame's labels reach here placed, as text
  void label(const sim::core::Vec2& anchor, const sim::core::Vec2& direction, const std::string& text, const Pen& style) override;
  // many points: contact dots of `dotRadiusPx` blended in after the GL frame (DotLayer), unless GL
  // draws over them; other points as discs with chords within a quarter pixel, not a twentieth (a
  // 720p frame of 800 contact dots drew 10 triangles a dot instead of 21: its drawing took half the time)
  void manyPoints(double dotRadiusPx) override { manyDotRadius_ = dotRadiusPx; }

  // the GL draw calls of the frame so far (begin() starts the count): one per batch of opaque
  // primitives and one per translucent primitive, however many bodies the opaque ones draw
  int drawCalls() const { return drawCalls_; }
  // the batch drawn now, in one glDrawArrays of its triangles, and emptied (finish() does it; an
  // overlay read without finish() needs it)
  void flush();

 private:
  struct QueuedText {
    sim::core::Vec2 pixel;
    std::string text;
    Anchor anchor;
    Color color;
  };
  void start(const Camera& camera, bool clear);
  // a call in `role` begins: the static part (static bodies, drawn first) ends at the first other
  // role that draws with GL (GlContext::endStaticPart)
  void enter(Role role);
  // whether this canvas began the frame (not an overlay), and the world points it has drawn, all
  // and those after the static part
  bool bounded_ = false;
  Bounds drawn_, moving_;
  std::optional<Bounds> under_;  // an overlay's: what drawnUnder() said
  // the frame's static part: still being drawn, every value its GL calls took (its key), and whether
  // a static body came after it ended (then the frame has no static part to keep)
  bool inStatic_ = false, staticLate_ = false, staticDrew_ = false;
  std::vector<double> key_;
  void keyed(std::initializer_list<double> values) {
    if (inStatic_) key_.insert(key_.end(), values);
  }
  // colors of a role: a fill (for shapes) and a stroke
  Color fillColor(const Pen& s) const;
  Color strokeColor(const Pen& s) const;
  // a stroke's width in output pixels
  double strokeWidth(Role role) const;

  // the GL work, vertices relative to the camera center. A primitive in color c at `opacity`: one
  // that `marks` its pixels (for hatching), or a translucent one whose pieces may `overlap` (a
  // stroke's quads and round joins), under a fresh stencil value, so that no pixel blends twice
  void beginPrimitive(const Color& c, double opacity, bool marks = false, bool overlaps = true);
  void vertex(const sim::core::Vec2& world);
  // glBegin(mode), the mode in the static part's key; endShape() is its glEnd. An opaque
  // primitive's fans and strips go into the batch instead, as the triangles GL would make of them
  void shape(unsigned mode);
  void endShape();
  // the unit circle's n + 1 points (the last is the first), shared by every disc of n segments
  const std::vector<sim::core::Vec2>& unitCircle(int n);
  void fillConvex(const std::vector<sim::core::Vec2>& vertices);
  // a disc of at least `least` segments (chords within `tolerance` pixels)
  void fillDisc(const sim::core::Vec2& center, double radius, double tolerance = 0.05, int least = 8);
  void ring(const sim::core::Vec2& center, double radius, double width);
  void strokeSegment(const sim::core::Vec2& a, const sim::core::Vec2& b, double width);
  void strokeClosed(const std::vector<sim::core::Vec2>& vertices, double width);
  // a closed convex outline with mitred corners, `half` its half width in world units
  void strokeMitred(const std::vector<sim::core::Vec2>& vertices, double half);
  // each vertex's move to its mitred outline's outer corner, `half` the outline's width away
  static std::vector<sim::core::Vec2> mitres(const std::vector<sim::core::Vec2>& vertices, double half);
  // an opaque polygon filled and outlined (mitred) as two fills; false (nothing drawn) when it is
  // kTwoFillsPx across or more, its outline not mitred, or it is narrower than its outline
  bool fillOutlined(const std::vector<sim::core::Vec2>& vertices, const Color& fill, const Color& stroke, double width);
  // whether an outline `half` wide on each side is drawn mitred (strokeMitred, one strip) rather
  // than with a round join at each vertex: the polygon is under kSmallOutlinePx across, or every
  // mitred corner lies within kMitreReachPx of where the round join reaches
  bool mitredLooksRound(const std::vector<sim::core::Vec2>& vertices, double half) const;
  static constexpr double kSmallOutlinePx = 16.0;
  static constexpr double kMitreReachPx = 0.5;
  static constexpr double kTwoFillsPx = 64.0;
  // a frame of at least this many moving bodies, every one under kSmallOutlinePx across, is dense:
  // drawn at two samples a pixel, not four (GlContext::fewerSamples; the look measured alike there)
  static constexpr int kDenseBodies = 200;
  // the fewest chords of a dot among many (manyPoints): a dot under about 1.5 px across is a square
  static constexpr int kLeastManyDotSegments = 4;
  int smallBodies_ = 0, largeBodies_ = 0;  // the moving bodies drawn this frame, by size
  // a moving body `extent` world units across counted as small or large
  void countBody(double extent);
  // `outline` px of the arrow's own shape added around it (0: the arrow itself)
  void strokeArrow(const sim::core::Vec2& tail, const sim::core::Vec2& head, double width, double outline = 0.0);
  // diagonal lines over the pixels of the primitive just drawn, within `box` (its bounds) and the view
  void hatch(const Bounds& box, const Color& c, double opacity);
  // the segments of a disc of `radius`: chords within `tolerance` pixels of the circle
  int discSegments(double radius, double tolerance = 0.05, int least = 8) const;
  double manyDotRadius_ = 0.0;  // px; 0: points drawn as usual
  // the contact dots among many, kept for the DotLayer at finish() while nothing is drawn over them
  struct LateDot {
    sim::core::Vec2 at;  // world
    double radiusPx;     // from its center to its corners
    int corners;
    Color color;  // its alpha the opacity
  };
  std::vector<LateDot> lateDots_;
  // the kept dots drawn with GL after all, in order, since GL draws over them now
  void drawLateDots();
  // a dot among many of `radiusPx`: its corners and its radius to them, a polygon of chords within
  // a quarter pixel grown to the disc's area
  std::pair<int, double> manyDot(double radiusPx);
  std::pair<double, double> manyDot_{-1.0, -1.0};  // the radius (px) and pixel size it was last worked out for
  std::pair<int, double> manyDotShape_{};

  GlContext& gl_;
  TextRenderer& textRenderer_;
  const Style& style_;
  Camera camera_{sim::core::Vec2::Zero(), 1.0, 1, 1};
  double px_ = 1.0;     // world length of one output pixel
  int stencil_ = -1;    // the stencil value of the primitive being drawn, 0 for none
  int glStencil_ = -1;  // the stencil value GL's stencil test is set to (-1: unknown)
  // the batch: opaque triangles and translucent ones that cover no pixel twice, each vertex with its
  // color, as GL takes them, in the context's store from batchFirst_ on
  using BatchVertex = TriangleVertex;
  std::vector<BatchVertex>& batch_;
  size_t batchFirst_ = 0;
  bool batching_ = false;         // the primitive being drawn goes into the batch
  std::array<float, 4> color_{};  // its color
  unsigned shapeMode_ = 0;        // its fan or strip, and its vertices so far
  int shapeCount_ = 0;
  BatchVertex shapeFirst_{}, shapePrevious_{};
  // a primitive drawn with GL calls under a stencil value of its own, not marking: its shape's
  // triangles as GL makes them, given to the context (GlContext::drawnOnce) at the shape's end
  bool once_ = false;
  std::vector<BatchVertex> onceShape_;
  // v added to the shape being drawn: its triangles, as GL makes them of a fan or strip, into `out`
  void shapeVertex(const BatchVertex& v, std::vector<BatchVertex>& out);
  int drawCalls_ = 0;
  std::map<int, std::vector<sim::core::Vec2>> unitCircles_;
  std::vector<QueuedText> texts_;
};

}  // namespace render::draw
