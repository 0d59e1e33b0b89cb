// Where the texts of a frame go: one placer for all of them, so that no two ever overlap.
//
// LabelPlacer is a Canvas between the painter and the canvas that draws. Shapes pass straight
// through and are remembered, in pixels, as what a label should not cover. Text fixed to the frame
// (Canvas::text: the clock, the caption, the energy panel's rows) keeps its place and is taken
// first. Labels (Canvas::label: a body's name, an arrow's value, an impact's n̂ and v_n, the
// simulator's separations) wait until finish(), then each, in turn, goes to the cheapest spot: its
// preferred one (on its anchor, or just beyond it along its direction), else the nearest free one
// along its allowed directions (out along its direction and swung around its anchor by 45° steps;
// the eight compass directions for a label centered on its anchor), where
//
//   cost = distance moved + Σ (line heights) over what the box covers: another body 3, an arrow,
//          a segment or a contact point 1.5, a static body 0.3, a trail 0.3
//
// (a label written on what it names, a body's name or a separation, counts areas only: it reads
// over lines with its halo, and stays put rather than hop as arrows turn and fade)
//
// and a spot is possible only inside the frame, clear of every text already placed (by the halo's
// width; of text fixed to the frame by half a line), of every other label's anchor and of the energy
// panel. A text placed over hatching or another body gets a backing of the background under it. A label moved more than a line
// gets a thin leader line back to its anchor; one with no possible spot within four lines is dropped and reported, never drawn
// over another.
//
//            ┌─────────┐  ← swung 45° when the first spot is taken
//     ●──────▶ label   │  ← preferred: beyond the head, a third of a line clear
//  anchor    └─────────┘     then further out along the direction, half a line at a time
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/draw/camera.h"
#include "render/draw/canvas.h"
#include "render/frame/caption.h"

namespace render::frame {

// a box in pixels, y down
struct PixelBox {
  double left = 0, top = 0, right = 0, bottom = 0;
  bool overlaps(const PixelBox& o) const { return left < o.right && o.left < right && top < o.bottom && o.top < bottom; }
  bool contains(const sim::core::Vec2& p) const { return p.x() >= left && p.x() <= right && p.y() >= top && p.y() <= bottom; }
  PixelBox grown(double by) const { return {left - by, top - by, right + by, bottom + by}; }
};

// a text as the placer put it (or would have: a dropped one keeps its preferred box)
struct PlacedText {
  std::string text;
  render::draw::Pen pen;
  PixelBox box;                           // px
  std::optional<sim::core::Vec2> anchor;  // px: the point a label names; none for text fixed to the frame
  bool leader = false;                    // moved far: a leader line joins it to its anchor
};

class LabelPlacer final : public render::draw::Canvas {
 public:
  // `target` draws; texts are `fontPx` high and `width` wide in pixels (an estimate without fonts)
  LabelPlacer(render::draw::Canvas& target, const render::draw::Camera& camera, int fontPx, TextWidth width);

  void polygon(const std::vector<sim::core::Vec2>& vertices, const render::draw::Pen& pen) override;
  void circle(const sim::core::Vec2& center, double radius, const render::draw::Pen& pen) override;
  void halfPlane(const sim::core::Vec2& point, const sim::core::Vec2& normal, const render::draw::Pen& pen) override;
  void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const render::draw::Pen& pen) override;
  void point(const sim::core::Vec2& p, const render::draw::Pen& pen) override;
  void arrow(const sim::core::Vec2& tail, const sim::core::Vec2& head, const render::draw::Pen& pen) override;
  void text(const sim::core::Vec2& at, const std::string& text, const render::draw::Pen& pen) override;
  void label(const sim::core::Vec2& anchor, const sim::core::Vec2& direction, const std::string& text,
             const render::draw::Pen& pen) override;
  // a label that stays near its anchor, so that it never needs a leader line: at its preferred spot
  // or moved less than a line, else dropped (a body's name in a frame of many bodies)
  void labelNearby(const sim::core::Vec2& anchor, const sim::core::Vec2& direction, const std::string& text,
                   const render::draw::Pen& pen);

  // places every text and label and draws them into the target (leader lines, then texts as
  // Canvas::text at their places); call once, after the last shape
  void finish();
  const std::vector<PlacedText>& placed() const { return placed_; }
  // labels (or fixed texts over fixed texts) that found no free spot, not drawn
  const std::vector<PlacedText>& dropped() const { return dropped_; }

 private:
  // something on screen a label should not cover, in pixels
  struct Obstacle {
    enum class Shape { Polygon, Disc, Stroke, HalfPlane } shape;
    // a disc's center (first); a stroke's ends; a point on a half-plane's boundary and its outward
    // normal: kept in place, so that a frame's thousands of contact dots allocate nothing
    std::array<sim::core::Vec2, 2> at;
    std::vector<sim::core::Vec2> vertices;  // a polygon's
    double radius = 0.0;                    // a disc's radius, a stroke's half width
    PixelBox bounds;                        // around it all (the whole frame for a half-plane)
    int body = -1;                          // whose it is: a body's area is free to its labels, its marks to its name
    double weight = 0.0;                    // what covering it costs, in lines; infinity: never
    bool area = false;                      // a body's area rather than a mark drawn for it
    int group = -1;                         // the pieces of one polyline (a trail, an arc) share one: covered once
    bool solid = false;                     // a body's or a static body's area: a text over it gets a backing
  };
  struct Pending {
    sim::core::Vec2 anchor;     // px
    sim::core::Vec2 direction;  // px, unit, y down; zero: centered on the anchor
    std::string text;
    render::draw::Pen pen;
    bool fixed;           // Canvas::text: stays where it was asked for (top-left for a caption)
    double width;         // px
    bool nearby = false;  // labelNearby: moved less than a line or not at all
  };
  // the frame cut into square cells, each listing what lies over it (obstacles, placed texts, label
  // anchors by index), so that a candidate box is tested against what is near it, not against all:
  // placing stays linear in the labels and shapes. What covers too many cells is listed apart, and
  // tested always
  class Grid {
   public:
    Grid(double widthPx, double heightPx, double cellPx);
    void add(const PixelBox& box, size_t index);
    // every index over `box`, ascending, each once
    const std::vector<size_t>& near(const PixelBox& box) const;

   private:
    bool cellsOf(const PixelBox& box, int& x0, int& y0, int& x1, int& y1) const;
    double cell_;
    int columns_, rows_;
    std::vector<std::vector<size_t>> cells_;
    std::vector<size_t> everywhere_;
    mutable std::vector<size_t> found_;
    mutable std::vector<unsigned> stamp_;  // by index: the query that found it last
    mutable unsigned query_ = 0;
  };
  PixelBox boxAt(const sim::core::Vec2& center, const Pending& p) const;
  // does the obstacle's shape meet the box?
  static bool hits(const Obstacle& o, const PixelBox& box);
  // does a placed text stand over hatching or another body (and so need a backing)?
  bool overSolid(const PlacedText& t) const;
  double cost(const PixelBox& box, const Pending& p, size_t self) const;  // infinity: not possible
  void place(const Pending& p, size_t self);
  void addObstacle(Obstacle o);
  // the obstacles whose bounds may overlap `box`, ascending (each loop tests the overlap itself)
  const std::vector<size_t>& obstaclesNear(const PixelBox& box) const;

  render::draw::Canvas& target_;
  render::draw::Camera camera_;
  int fontPx_;
  TextWidth width_;
  double line_, pad_;  // a line of text and the clearance between texts, px
  std::vector<Obstacle> obstacles_;
  std::optional<render::draw::Pen> lastSegment_;  // consecutive segments in one pen are one polyline
  int groups_ = 0;
  std::vector<Pending> pending_;
  std::vector<PlacedText> placed_, dropped_;
  // the obstacles are gridded only once they have been asked for more than a few times
  // (obstaclesNear): until then, and in a frame with no more to place than its clock, a scan
  mutable Grid obstacleGrid_;
  Grid placedGrid_, anchorGrid_;
  mutable bool gridded_ = false;
  mutable int scans_ = 0;
  mutable std::vector<size_t> scanned_;
};

// the dropped labels of a run, said once each on standard error (or to `sink`): a label whose
// numbers change from frame to frame is one label ("E = #.## J"), and at most a few are named
class DroppedLabels {
 public:
  explicit DroppedLabels(std::function<void(const std::string&)> sink = {});
  void report(const std::vector<PlacedText>& dropped, double t);

 private:
  std::function<void(const std::string&)> sink_;
  std::vector<std::string> seen_;
  int told_ = 0;
};

// a unit vector along v, or `fallback` when v has no length
sim::core::Vec2 directionOr(const sim::core::Vec2& v, const sim::core::Vec2& fallback);

}  // namespace render::frame
