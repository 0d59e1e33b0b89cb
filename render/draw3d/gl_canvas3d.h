// 3D frames drawn with OpenGL 1.x (fixed function, through OSMesa, 4× multisampled as 2D frames):
// solids as triangles in clip coordinates that Camera3d computes (GL's matrices stay identity), with
// a depth buffer; shaded on the CPU by a diffuse light from the viewer's upper left (Lambert), so
// that a face's brightness tells its slope; creases, silhouettes and surface curves outlined as
// screen-space strips at the depth of their points, over faces pushed back by a polygon offset.
// Then the 2D overlay: render::draw::GlCanvas on the same context, in pixels, over the solids.
#pragma once

#include "render/draw/gl_canvas.h"
#include "render/draw3d/canvas3d.h"

namespace render::draw3d {

// the light of 3D frames: a fraction of each color always, and the rest by the cosine of the angle
// between the surface and the light (from the upper left, behind the viewer)
struct Lighting {
  double ambient = 0.55;
  double diffuse = 0.45;
  sim::world3d::Vec3 toLight = sim::world3d::Vec3(-0.45, 0.6, -1.0).normalized();  // camera coordinates: right, up, forward
};

// the color of a surface of color `base` with outward normal `normal` (world), seen by `camera`
render::draw::Color shade(const render::draw::Color& base, const sim::world3d::Vec3& normal, const Camera3d& camera,
                          const Lighting& light = {});

class GlCanvas3d final : public Canvas3d {
 public:
  GlCanvas3d(render::draw::GlContext& gl, render::draw::TextRenderer& text, const render::draw::Style& style);

  // start a frame: clear color and depth, look through `camera`
  void begin(const Camera3d& camera);
  // the frame, the overlay's text on top
  render::draw::Image finish();
  // the same into `frame`, whose storage is reused when it has the frame's size already
  void finish(render::draw::Image& frame);

  void solid(const Mesh& mesh, const sim::world3d::Vec3& x, const sim::world3d::Mat3& rotation,
             const render::draw::Pen& pen) override;
  render::draw::Canvas& overlay() override;

 private:
  // a line from a to b (world) `widthPx` wide on the frame, at the depth of its points, clipped to
  // the near plane
  void strokeLine(const sim::world3d::Vec3& a, const sim::world3d::Vec3& b, double widthPx);
  // glVertex of a point in clip coordinates, its pixel added to drawn_
  void vertex(const Vec4& clip);

  render::draw::GlContext& gl_;
  const render::draw::Style& style_;
  Camera3d camera_;
  render::draw::GlCanvas overlay_;
  bool overlaid_ = false;  // GL is set up for the overlay
  // the output pixels the solids' vertices fall on (y down), or unbounded when one lies behind the
  // eye (w ≤ 0), where GL clips and its projection says nothing
  render::draw::Bounds drawn_;
  bool unbounded_ = false;
};

}  // namespace render::draw3d
