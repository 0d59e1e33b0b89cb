#include "render/frame/label_place.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <numbers>
#include <span>

#include "render/draw/text.h"
#include "render/jobs/interrupt.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
// what covering each thing costs, in lines of text: another body more than any move (text across a
// body hides what the frame is about), a line, an arrow or a dot more than a move too (a text crossed
// by an arrow reads as neither), a static body's hatching or a trail (which a backing or a halo reads
// over) less than a third of a line. So a text covers a body or crosses a line only where no spot
// within reach is free
constexpr double kBody = 12.0, kCovers = 8.0, kFaint = 0.3;
// the least space between two labels, in em: a word's space
constexpr double kWordSpace = 0.35;
// how far a label may move (in lines), its steps (in lines), and from how far it gets a leader line
constexpr double kMaxMove = 4.0, kStep = 0.5, kLeaderFrom = 1.0;
// a contact point's dot and an arrow's head (10 px long, 9 wide: gl_canvas.cpp) as discs, px
constexpr double kDotPx = 4.0, kHeadPx = 5.0;

PixelBox boundsOf(std::span<const Vec2> points, double grow) {
  PixelBox b{kNever, kNever, -kNever, -kNever};
  for (const Vec2& p : points) {
    b.left = std::min(b.left, p.x()), b.right = std::max(b.right, p.x());
    b.top = std::min(b.top, p.y()), b.bottom = std::max(b.bottom, p.y());
  }
  return b.grown(grow);
}

PixelBox boundsOf(const Vec2& p, double grow) { return boundsOf(std::span<const Vec2>(&p, 1), grow); }

Vec2 closestInBox(const PixelBox& b, const Vec2& p) {
  return {std::clamp(p.x(), b.left, b.right), std::clamp(p.y(), b.top, b.bottom)};
}

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double length2 = d.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + s * d)).norm();
}

// does segment ab cross the box? (Liang–Barsky clipping)
bool segmentCrossesBox(const Vec2& a, const Vec2& b, const PixelBox& box) {
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - box.left, box.right - a.x(), a.y() - box.top, box.bottom - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

// a convex polygon against a box: separated along an axis of either (separating axis theorem)
bool polygonOverlapsBox(const std::vector<Vec2>& polygon, const PixelBox& box) {
  const Vec2 corners[4] = {{box.left, box.top}, {box.right, box.top}, {box.right, box.bottom}, {box.left, box.bottom}};
  std::vector<Vec2> axes = {Vec2::UnitX(), Vec2::UnitY()};
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 e = polygon[(i + 1) % polygon.size()] - polygon[i];
    if (e.squaredNorm() > 0.0) axes.emplace_back(-e.y(), e.x());
  }
  for (const Vec2& axis : axes) {
    double lo = kNever, hi = -kNever, boxLo = kNever, boxHi = -kNever;
    for (const Vec2& v : polygon) lo = std::min(lo, v.dot(axis)), hi = std::max(hi, v.dot(axis));
    for (const Vec2& c : corners) boxLo = std::min(boxLo, c.dot(axis)), boxHi = std::max(boxHi, c.dot(axis));
    if (hi <= boxLo || boxHi <= lo) return false;
  }
  return true;
}

// how much covering a shape of `role` costs, in lines, as opaque as `opacity`
double weightOf(Role role, double opacity) {
  double w = kCovers;
  switch (role) {
    case Role::Body:
    case Role::BodyPart: w = kBody; break;
    case Role::StaticBody:
    case Role::Trail:
    case Role::Path: w = kFaint; break;
    case Role::Panel: return kNever;  // the energy panel: its rows are its own
    case Role::Backing: return 0.0;
    case Role::KineticBar:
    case Role::RotationalBar:
    case Role::PotentialBar:
    case Role::TotalBar: return 0.0;  // inside the panel
    default: break;
  }
  return w * std::clamp(opacity, 0.0, 1.0);
}

// a body's or an obstacle's area, drawn solid: a text over it gets a backing
bool solidRole(const Pen& pen) {
  return (pen.role == Role::Body || pen.role == Role::BodyPart || pen.role == Role::StaticBody) && pen.opacity >= 0.5;
}

Vec2 rotated(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// what covers more cells than this is listed apart (a half-plane, a long line), tested always
constexpr long kManyCells = 64;

}  // namespace

LabelPlacer::Grid::Grid(double widthPx, double heightPx, double cellPx)
    : cell_(cellPx),
      columns_(std::max(1, static_cast<int>(std::ceil(std::min(widthPx, 1e5) / cellPx)))),
      rows_(std::max(1, static_cast<int>(std::ceil(std::min(heightPx, 1e5) / cellPx)))),
      cells_(static_cast<size_t>(columns_) * static_cast<size_t>(rows_)) {}

bool LabelPlacer::Grid::cellsOf(const PixelBox& b, int& x0, int& y0, int& x1, int& y1) const {
  // clamped to the edge cells as doubles first (a box off the frame lands on its edge; NaN nowhere)
  if (!(b.left <= b.right && b.top <= b.bottom)) return false;
  const auto at = [&](double v, int n) { return static_cast<int>(std::clamp(std::floor(v / cell_), 0.0, n - 1.0)); };
  x0 = at(b.left, columns_), x1 = at(b.right, columns_), y0 = at(b.top, rows_), y1 = at(b.bottom, rows_);
  return true;
}

void LabelPlacer::Grid::add(const PixelBox& box, size_t index) {
  int x0, y0, x1, y1;
  if (!cellsOf(box, x0, y0, x1, y1) || static_cast<long>(x1 - x0 + 1) * (y1 - y0 + 1) > kManyCells) {
    everywhere_.push_back(index);
    return;
  }
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) cells_[static_cast<size_t>(y) * columns_ + x].push_back(index);
}

const std::vector<size_t>& LabelPlacer::Grid::near(const PixelBox& box) const {
  found_ = everywhere_;
  int x0, y0, x1, y1;
  if (cellsOf(box, x0, y0, x1, y1)) {
    ++query_;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        for (size_t i : cells_[static_cast<size_t>(y) * columns_ + x]) {
          if (i >= stamp_.size()) stamp_.resize(2 * i + 16, 0);
          if (stamp_[i] == query_) continue;
          stamp_[i] = query_;
          found_.push_back(i);
        }
  }
  std::sort(found_.begin(), found_.end());
  return found_;
}

LabelPlacer::LabelPlacer(Canvas& target, const Camera& camera, int fontPx, TextWidth width)
    : target_(target),
      camera_(camera),
      fontPx_(fontPx),
      width_(width ? std::move(width) : TextWidth([fontPx](const std::string& s) {
        return static_cast<int>(std::ceil(approximateWidth(s, fontPx)));
      })),
      line_(lineHeightPx(fontPx)),
      pad_(std::max(1.0, std::round(fontPx / 10.0))),
      // cells two lines of text square: a label's box and its clearance cover a few
      obstacleGrid_(camera.widthPx(), camera.heightPx(), std::max(16.0, 2.0 * line_)),
      placedGrid_(obstacleGrid_),
      anchorGrid_(obstacleGrid_) {}

void LabelPlacer::addObstacle(Obstacle o) {
  // anything but a segment ends a polyline
  if (o.group < 0) lastSegment_.reset();
  if (!(o.weight > 0.0)) return;
  // what lies wholly off the frame is under no label's box (every box lies in the frame)
  const PixelBox frame{0, 0, static_cast<double>(camera_.widthPx()), static_cast<double>(camera_.heightPx())};
  if (o.bounds.left <= o.bounds.right && !o.bounds.overlaps(frame)) return;
  if (gridded_) obstacleGrid_.add(o.bounds, obstacles_.size());
  obstacles_.push_back(std::move(o));
}

const std::vector<size_t>& LabelPlacer::obstaclesNear(const PixelBox& box) const {
  // A frame whose only text is its clock asks once or twice, and gridding the 20,000 obstacles of
  // a 5,050-box pile with its contact dots cost more than scanning them (a few % of its render):
  // the first few asks scan, later ones use the grid, made then. Either way every obstacle whose
  // bounds overlap the box comes out, in ascending order, and the callers skip the rest.
  constexpr int kScansBeforeGrid = 8;
  if (!gridded_ && ++scans_ > kScansBeforeGrid) {
    for (size_t i = 0; i < obstacles_.size(); ++i) obstacleGrid_.add(obstacles_[i].bounds, i);
    gridded_ = true;
  }
  if (gridded_) return obstacleGrid_.near(box);
  scanned_.clear();
  for (size_t i = 0; i < obstacles_.size(); ++i)
    if (obstacles_[i].bounds.overlaps(box)) scanned_.push_back(i);
  return scanned_;
}

void LabelPlacer::polygon(const std::vector<Vec2>& vertices, const Pen& pen) {
  target_.polygon(vertices, pen);
  std::vector<Vec2> px;
  for (const Vec2& v : vertices) px.push_back(camera_.toPixel(v));
  // the pixel frame flips y, which turns the polygon's winding but not its convexity
  const PixelBox bounds = boundsOf(px, 0.0);
  addObstacle({Obstacle::Shape::Polygon,
               {},
               std::move(px),
               0.0,
               bounds,
               pen.body,
               weightOf(pen.role, pen.opacity),
               true,
               -1,
               solidRole(pen)});
}

void LabelPlacer::circle(const Vec2& center, double radius, const Pen& pen) {
  target_.circle(center, radius, pen);
  const Vec2 c = camera_.toPixel(center);
  const double r = radius / camera_.pixelSize();
  addObstacle({Obstacle::Shape::Disc,
               {c, c},
               {},
               r,
               boundsOf(c, r),
               pen.body,
               weightOf(pen.role, pen.opacity),
               true,
               -1,
               solidRole(pen)});
}

void LabelPlacer::halfPlane(const Vec2& point, const Vec2& normal, const Pen& pen) {
  target_.halfPlane(point, normal, pen);
  if (!(normal.norm() > 0.0)) return;
  const Vec2 p = camera_.toPixel(point), n = Vec2(normal.x(), -normal.y()).normalized();
  const PixelBox frame{0, 0, static_cast<double>(camera_.widthPx()), static_cast<double>(camera_.heightPx())};
  addObstacle(
      {Obstacle::Shape::HalfPlane, {p, n}, {}, 0.0, frame, pen.body, weightOf(pen.role, pen.opacity), true, -1, solidRole(pen)});
  // its boundary is a line like any other
  const Vec2 along(-n.y(), n.x());
  const double reach = camera_.widthPx() + camera_.heightPx();
  const std::array<Vec2, 2> ends = {p - reach * along, p + reach * along};
  addObstacle({Obstacle::Shape::Stroke, ends, {}, 1.0, boundsOf(ends, 1.0), -1, kCovers * std::clamp(pen.opacity, 0.0, 1.0)});
}

void LabelPlacer::segment(const Vec2& a, const Vec2& b, const Pen& pen) {
  target_.segment(a, b, pen);
  const std::array<Vec2, 2> ends = {camera_.toPixel(a), camera_.toPixel(b)};
  const bool continues = lastSegment_ && lastSegment_->role == pen.role && lastSegment_->body == pen.body &&
                         lastSegment_->opacity == pen.opacity && lastSegment_->color == pen.color;
  if (!continues) ++groups_;
  addObstacle(
      {Obstacle::Shape::Stroke, ends, {}, 1.5, boundsOf(ends, 1.5), pen.body, weightOf(pen.role, pen.opacity), false, groups_});
  lastSegment_ = pen;
}

void LabelPlacer::point(const Vec2& p, const Pen& pen) {
  target_.point(p, pen);
  const Vec2 c = camera_.toPixel(p);
  addObstacle({Obstacle::Shape::Disc, {c, c}, {}, kDotPx, boundsOf(c, kDotPx), -1, weightOf(pen.role, pen.opacity)});
}

void LabelPlacer::arrow(const Vec2& tail, const Vec2& head, const Pen& pen) {
  target_.arrow(tail, head, pen);
  const std::array<Vec2, 2> ends = {camera_.toPixel(tail), camera_.toPixel(head)};
  const double w = weightOf(pen.role, pen.opacity);
  addObstacle({Obstacle::Shape::Stroke, ends, {}, 1.5, boundsOf(ends, 1.5), pen.body, w});
  // the head: a disc over its barbs, behind the tip
  const Vec2 d = ends[1] - ends[0];
  if (d.norm() > kHeadPx) {
    const Vec2 barbs = ends[1] - (kHeadPx / d.norm()) * d;
    addObstacle({Obstacle::Shape::Disc, {barbs, barbs}, {}, kHeadPx, boundsOf(barbs, kHeadPx), pen.body, w});
  }
}

void LabelPlacer::text(const Vec2& at, const std::string& text, const Pen& pen) {
  pending_.push_back({camera_.toPixel(at), Vec2::Zero(), text, pen, true, static_cast<double>(width_(text))});
}

void LabelPlacer::label(const Vec2& anchor, const Vec2& direction, const std::string& text, const Pen& pen) {
  // in pixels y points down
  const Vec2 d(direction.x(), -direction.y());
  const Vec2 at = camera_.toPixel(anchor);
  anchorGrid_.add({at.x(), at.y(), at.x(), at.y()}, pending_.size());
  pending_.push_back(
      {at, d.norm() > 0.0 ? Vec2(d.normalized()) : Vec2::Zero(), text, pen, false, static_cast<double>(width_(text))});
}

void LabelPlacer::labelNearby(const Vec2& anchor, const Vec2& direction, const std::string& text, const Pen& pen) {
  label(anchor, direction, text, pen);
  pending_.back().nearby = true;
}

PixelBox LabelPlacer::boxAt(const Vec2& center, const Pending& p) const {
  const double w = p.width;
  // a caption's point is its top-left corner; a label's, its center (as GlCanvas draws them)
  if (p.pen.role == Role::Caption) return {center.x(), center.y(), center.x() + w, center.y() + line_};
  return {center.x() - 0.5 * w, center.y() - 0.5 * line_, center.x() + 0.5 * w, center.y() + 0.5 * line_};
}

bool LabelPlacer::hits(const Obstacle& o, const PixelBox& box) {
  switch (o.shape) {
    case Obstacle::Shape::Polygon: return polygonOverlapsBox(o.vertices, box);
    case Obstacle::Shape::Disc: return (closestInBox(box, o.at[0]) - o.at[0]).norm() < o.radius;
    case Obstacle::Shape::Stroke: {
      const Vec2 &a = o.at[0], &b = o.at[1];
      if (segmentCrossesBox(a, b, box)) return true;
      double d = std::min((closestInBox(box, a) - a).norm(), (closestInBox(box, b) - b).norm());
      for (const Vec2& c :
           {Vec2(box.left, box.top), Vec2(box.right, box.top), Vec2(box.right, box.bottom), Vec2(box.left, box.bottom)})
        d = std::min(d, distanceToSegment(c, a, b));
      return d < o.radius;
    }
    case Obstacle::Shape::HalfPlane: {
      // the solid side is n·(r − p) ≤ 0
      const Vec2 &q = o.at[0], &n = o.at[1];
      double least = kNever;
      for (const Vec2& c :
           {Vec2(box.left, box.top), Vec2(box.right, box.top), Vec2(box.right, box.bottom), Vec2(box.left, box.bottom)})
        least = std::min(least, n.dot(c - q));
      return least <= 0.0;
    }
  }
  return false;
}

double LabelPlacer::cost(const PixelBox& box, const Pending& p, size_t self) const {
  // possible: inside the frame, clear of the texts placed (of text fixed to the frame, the clock and
  // the caption, by half a line: a label beside a caption's line reads as part of it) and of the
  // other labels' anchors
  if (box.left < 0.0 || box.top < 0.0 || box.right > camera_.widthPx() || box.bottom > camera_.heightPx()) return kNever;
  // two labels a word's space apart at least, so that "bar" and "v = 0 m/s" never read as one
  const PixelBox clear = box.grown(pad_), spaced = box.grown(std::max(pad_, kWordSpace * fontPx_)),
                 apart = box.grown(std::max(pad_, 0.5 * line_));
  for (size_t k : placedGrid_.near(apart))
    if ((placed_[k].anchor ? spaced : apart).overlaps(placed_[k].box)) return kNever;
  // a label beyond its anchor never covers it either (one on its anchor does, by design); an anchor
  // it shares (a zero-length arrow at a body's center, labelled beyond it) is its own
  for (size_t i : anchorGrid_.near(clear))
    if (!pending_[i].fixed && (i != self || !p.direction.isZero()) && clear.contains(pending_[i].anchor) &&
        (i == self || (pending_[i].anchor - p.anchor).norm() > 1.0))
      return kNever;
  // what it covers, each polyline once (in the order drawn, as the pieces of a polyline come)
  double covered = 0.0;
  int lastGroup = -1;
  for (size_t k : obstaclesNear(box)) {
    const Obstacle& o = obstacles_[k];
    if (o.group >= 0 && o.group == lastGroup) continue;
    if (!o.bounds.overlaps(box)) continue;
    // a label may lie on its own body. One written on what it names (a body's name, a separation)
    // reads over lines and arrows with its halo and stays put, so that names do not hop from frame
    // to frame as arrows turn and fade: only areas move it
    if (o.body >= 0 && o.body == p.pen.body && o.area && o.weight < kNever) continue;
    if (p.direction.isZero() && !o.area) continue;
    if (hits(o, box)) {
      if (o.weight == kNever) return kNever;
      covered += o.weight;
      lastGroup = o.group;
    }
  }
  return covered * line_;
}

bool LabelPlacer::overSolid(const PlacedText& t) const {
  for (size_t k : obstaclesNear(t.box)) {
    const Obstacle& o = obstacles_[k];
    // a body's name on its own body reads with its halo over the body's light fill
    if (!o.solid || (o.body >= 0 && o.body == t.pen.body && t.anchor)) continue;
    if (o.bounds.overlaps(t.box) && hits(o, t.box)) return true;
  }
  return false;
}

void LabelPlacer::place(const Pending& p, size_t self) {
  const double halfWidth = 0.5 * p.width, halfHeight = 0.5 * line_, gap = fontPx_ / 3.0;
  const Vec2 preferred = p.fixed ? p.anchor : labelCenter(p.anchor, p.direction, halfWidth, halfHeight, gap);
  PlacedText out{p.text, p.pen, boxAt(preferred, p), p.fixed ? std::nullopt : std::optional<Vec2>(p.anchor), false};
  if (p.fixed) {
    // text fixed to the frame moves for nothing; it only must not land on another (rows a line apart
    // touch, and the round trip through world units leaves them a hair's breadth over: no overlap)
    for (const PlacedText& t : placed_)
      if (out.box.grown(-1e-6).overlaps(t.box)) {
        dropped_.push_back(out);
        return;
      }
    placedGrid_.add(out.box, placed_.size());
    placed_.push_back(out);
    return;
  }
  // the candidates, half a line apart: the preferred spot slid in the eight compass directions, and
  // for a label beyond its anchor, the spot swung around the anchor by 45° steps and out from there
  struct Candidate {
    Vec2 center;
    double moved;
  };
  std::vector<Candidate> candidates;
  const int steps = static_cast<int>(kMaxMove / kStep);
  const auto along = [&](const Vec2& start, const Vec2& u, int from) {
    for (int k = from; k <= steps; ++k) {
      const Vec2 c = start + (k * kStep * line_) * u;
      candidates.push_back({c, (c - preferred).norm()});
    }
  };
  for (int turn = 0; turn < 8; ++turn) along(preferred, rotated(Vec2::UnitX(), turn * 0.25 * std::numbers::pi), 1);
  if (!p.direction.isZero())
    for (int turn = 1; turn < 8; ++turn) {
      // +45°, −45°, +90°, … , 180°: the nearest turns first
      const Vec2 u = rotated(p.direction, (turn + 1) / 2 * (turn % 2 ? 1.0 : -1.0) * 0.25 * std::numbers::pi);
      along(labelCenter(p.anchor, u, halfWidth, halfHeight, gap), u, 0);
    }
  candidates.insert(candidates.begin(), {preferred, 0.0});
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.moved < b.moved; });
  // the cheapest: a candidate that moved further than the best cost so far cannot beat it
  double best = kNever;
  Vec2 at = preferred;
  // a label kept near its anchor moves less than a leader line's distance
  const double reach = p.nearby ? kLeaderFrom * line_ : kMaxMove * line_ + 2.0 * halfWidth;
  for (const Candidate& c : candidates) {
    // a frame of many bodies takes long: Ctrl-C ends it here (a flag read, no more)
    render::jobs::checkInterrupted();
    if (c.moved >= best || c.moved > reach) break;
    const double total = c.moved + cost(boxAt(c.center, p), p, self);
    if (total < best) best = total, at = c.center;
  }
  if (best == kNever) {
    dropped_.push_back(out);
    return;
  }
  out.box = boxAt(at, p);
  out.leader = (at - preferred).norm() > kLeaderFrom * line_ && !out.box.contains(p.anchor);
  placedGrid_.add(out.box, placed_.size());
  placed_.push_back(out);
}

void LabelPlacer::finish() {
  // fixed texts first, as they were asked for; then labels on their anchors (bodies' names,
  // separations), then labels beyond their anchors (values of arrows and impacts), each in call order
  std::vector<size_t> order;
  for (int pass = 0; pass < 3; ++pass)
    for (size_t i = 0; i < pending_.size(); ++i) {
      const Pending& p = pending_[i];
      const int group = p.fixed ? 0 : p.direction.isZero() ? 1 : 2;
      if (group == pass) order.push_back(i);
    }
  for (size_t i : order) place(pending_[i], i);
  // a backing under each text over hatching or another body, so that it reads from the back row
  for (const PlacedText& t : placed_) {
    if (!overSolid(t)) continue;
    const PixelBox b = t.box.grown(pad_);
    target_.polygon({camera_.toWorld({b.left, b.top}), camera_.toWorld({b.right, b.top}), camera_.toWorld({b.right, b.bottom}),
                     camera_.toWorld({b.left, b.bottom})},
                    {Role::Backing, -1, t.pen.opacity});
  }
  // leader lines under the texts, then the texts where they were placed
  for (const PlacedText& t : placed_) {
    if (!t.leader) continue;
    const Vec2 a = *t.anchor, b = closestInBox(t.box, a);
    const Vec2 d = b - a;
    // from a little off the anchor to the box's edge
    const Vec2 from = a + std::min(0.3 * d.norm(), 3.0) * d.normalized();
    target_.segment(camera_.toWorld(from), camera_.toWorld(b), {Role::Label, t.pen.body, 0.6 * t.pen.opacity});
  }
  for (const PlacedText& t : placed_) {
    const Vec2 at = t.pen.role == Role::Caption ? Vec2(t.box.left, t.box.top)
                                                : Vec2(0.5 * (t.box.left + t.box.right), 0.5 * (t.box.top + t.box.bottom));
    target_.text(camera_.toWorld(at), t.text, t.pen);
  }
  pending_.clear();
}

namespace {

// a label as a warning names it: its first 60 bytes, cut before a UTF-8 sequence, and "…" (a label
// of a megabyte is not repeated on the terminal)
std::string cutText(const std::string& text) {
  constexpr size_t kMost = 60;
  if (text.size() <= kMost) return text;
  size_t end = kMost;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  return text.substr(0, end) + "… (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace

DroppedLabels::DroppedLabels(std::function<void(const std::string&)> sink)
    : sink_(sink ? std::move(sink) : [](const std::string& m) { std::cerr << "rigidreel: warning: " << m << '\n'; }) {}

void DroppedLabels::report(const std::vector<PlacedText>& dropped, double t) {
  // at most this many named per run
  constexpr int kNamed = 5;
  for (const PlacedText& d : dropped) {
    std::string shape = d.text;
    for (char& c : shape)
      if (c >= '0' && c <= '9') c = '#';
    // and a power of ten's superscript digits ("× 10⁻¹⁶"), so that round-off is one label too
    for (const char* digit : {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹", "⁻"})
      for (size_t at = shape.find(digit); at != std::string::npos; at = shape.find(digit, at + 1))
        shape.replace(at, std::string(digit).size(), 1, '#');
    if (std::find(seen_.begin(), seen_.end(), shape) != seen_.end()) continue;
    seen_.push_back(shape);
    if (told_ == kNamed) sink_("more labels dropped; not named");
    if (told_++ >= kNamed) continue;
    char when[32];
    std::snprintf(when, sizeof when, "%.3f", t);
    sink_("label '" + cutText(d.text) + "' dropped at t = " + when + " s: no free spot for it in the frame");
  }
}

sim::core::Vec2 directionOr(const sim::core::Vec2& v, const sim::core::Vec2& fallback) {
  const double n = v.norm();
  return n > 0.0 ? sim::core::Vec2(v / n) : fallback;
}

}  // namespace render::frame
