// The drawing interface of 3D frames: solids in perspective, and a 2D canvas over them for
// everything drawn on top (arrows, trails, text, panels), in pixels with y up (overlayPoint).
// GlCanvas3d draws it with OpenGL; DrawList3d records it for tests, as DrawList does in 2D.
#pragma once

#include <string>
#include <vector>

#include "render/draw/camera.h"
#include "render/draw/draw_list.h"
#include "render/draw3d/mesh.h"

namespace render::draw3d {

class Canvas3d {
 public:
  virtual ~Canvas3d() = default;
  // `mesh` (body coordinates) at the pose r = x + R r_b, shaded in its body's color (pen.body), with
  // a depth buffer, its creases, silhouette and curves outlined
  virtual void solid(const Mesh& mesh, const sim::world3d::Vec3& x, const sim::world3d::Mat3& rotation,
                     const render::draw::Pen& pen) = 0;
  // the canvas over the solids: pixels, x to the right and y up from the bottom-left corner
  virtual render::draw::Canvas& overlay() = 0;
};

// a pixel (y down from the top, as Camera3d gives it) in the overlay's coordinates (y up)
inline sim::core::Vec2 overlayPoint(const sim::core::Vec2& pixel, int heightPx) { return {pixel.x(), heightPx - pixel.y()}; }
// the 2D camera whose world is the overlay's: one unit a pixel, y up
render::draw::Camera overlayCamera(int widthPx, int heightPx);

// the calls as text lines: a solid per line, then the overlay's lines (DrawList::lines)
class DrawList3d final : public Canvas3d {
 public:
  void solid(const Mesh& mesh, const sim::world3d::Vec3& x, const sim::world3d::Mat3& rotation,
             const render::draw::Pen& pen) override;
  render::draw::Canvas& overlay() override { return overlay_; }

  // e.g. "solid Body#0 box 0.1 0.4 0.8 x=(0,0,0) R=(1,0,0)(0,1,0)(0,0,1)" (R by its rows)
  std::vector<std::string> lines() const;
  std::string toText() const;
  const render::draw::DrawList& overlayCalls() const { return overlay_; }
  // each solid's call as made (a golden record's draw list compares their numbers)
  struct Solid {
    std::string mesh;
    render::draw::Pen pen;
    sim::world3d::Vec3 x;
    sim::world3d::Mat3 rotation;
  };
  const std::vector<Solid>& solids() const { return solidCalls_; }

 private:
  std::vector<std::string> solids_;
  std::vector<Solid> solidCalls_;
  render::draw::DrawList overlay_;
};

}  // namespace render::draw3d
