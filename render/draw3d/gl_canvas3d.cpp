#include "render/draw3d/gl_canvas3d.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>

namespace render::draw3d {
using namespace render::draw;
using sim::core::Vec2;
using sim::world3d::Mat3;
using sim::world3d::Vec3;

namespace {

const Color kWhite{1.0, 1.0, 1.0, 1.0};
const Color kBlack{0.0, 0.0, 0.0, 1.0};

// a solid's face as its 2D fill is (its color lightened, then shaded); its edges darker than a 2D
// outline, so that they stay darker than a face turned away from the light (ambient alone)
constexpr double kFillLighten = 0.35, kEdgeDarken = 0.55;
// outline widths in line widths: creases and the silhouette, and the thinner surface curves
constexpr double kEdgeWidth = 0.75, kCurveWidth = 0.5;

}  // namespace

Color shade(const Color& base, const Vec3& normal, const Camera3d& camera, const Lighting& light) {
  const double lit = light.ambient + light.diffuse * std::max(0.0, (camera.basis() * normal).dot(light.toLight));
  return {base.r * lit, base.g * lit, base.b * lit, base.a};
}

GlCanvas3d::GlCanvas3d(GlContext& gl, TextRenderer& text, const Style& style)
    : gl_(gl),
      style_(style),
      camera_(Vec3(0, -1, 0), Vec3::Zero(), Vec3::UnitZ(), 40.0, gl.width(), gl.height(), Vec2::Zero(), 0.1, 10.0),
      overlay_(gl, text, style) {}

void GlCanvas3d::begin(const Camera3d& camera) {
  // recorded, to be drawn at each sample position (the overlay is part of the same frame)
  gl_.beginFrame();
  camera_ = camera;
  overlaid_ = false;
  drawn_ = render::draw::Bounds();
  unbounded_ = false;
  // opaque solids with a depth test, in clip coordinates: GL's matrices are the identity
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  // triangles are counter-clockwise seen from outside, and a solid is closed: its back faces never show
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glShadeModel(GL_SMOOTH);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gl_.clearFrame(style_.background, true);
}

Canvas& GlCanvas3d::overlay() {
  if (!overlaid_) {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    overlay_.beginOverlay(overlayCamera(camera_.widthPx(), camera_.heightPx()));
    overlaid_ = true;
  }
  return overlay_;
}

Image GlCanvas3d::finish() {
  Image frame;
  finish(frame);
  return frame;
}

void GlCanvas3d::finish(Image& frame) {
  overlay();
  // a triangle with its vertices in front of the eye projects within them (clipping only cuts it)
  if (!unbounded_) overlay_.drawnUnder(drawn_);
  overlay_.finish(frame);
}

void GlCanvas3d::vertex(const Vec4& c) {
  if (c.w() > 0.0)
    drawn_.add(Vec2((c.x() / c.w() + 1.0) * 0.5 * camera_.widthPx(), (1.0 - c.y() / c.w()) * 0.5 * camera_.heightPx()));
  else unbounded_ = true;
  glVertex4d(c.x(), c.y(), c.z(), c.w());
}

void GlCanvas3d::solid(const Mesh& mesh, const Vec3& x, const Mat3& rotation, const Pen& pen) {
  if (overlaid_) throw std::logic_error("GlCanvas3d: solids are drawn before the overlay");
  // a plane obstacle in the static bodies' color, as 2D draws its half-planes
  const Color base = pen.role == Role::StaticBody ? style_.role(Role::StaticBody) : style_.body(pen.body);
  const Color fill = base.mixed(kWhite, kFillLighten);
  std::vector<Vec4> clip(mesh.positions.size());
  std::vector<Color> colors(mesh.positions.size());
  // normals turn with R⁻ᵀ: the same as R for a rotation, and right for a stretched drifting q too
  const Mat3 normalMap = rotation.inverse().transpose();
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    clip[i] = camera_.clip(x + rotation * mesh.positions[i]);
    colors[i] = shade(fill, (normalMap * mesh.normals[i]).normalized(), camera_);
  }
  // the faces, pushed back a little in depth so that the outlines on them win
  glEnable(GL_CULL_FACE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 2.0f);
  glBegin(GL_TRIANGLES);
  for (const std::array<int, 3>& t : mesh.triangles)
    for (int k : t) {
      glColor3d(colors[k].r, colors[k].g, colors[k].b);
      vertex(clip[k]);
    }
  glEnd();
  glDisable(GL_POLYGON_OFFSET_FILL);
  // strips face either way
  glDisable(GL_CULL_FACE);

  // the outlines: creases, the silhouette seen from the eye, and the curves on the surface
  const Color edge = base.mixed(kBlack, kEdgeDarken);
  glColor3d(edge.r, edge.g, edge.b);
  auto world = [&](const Vec3& p) { return Vec3(x + rotation * p); };
  const double width = kEdgeWidth * style_.lineWidth;
  for (const std::array<int, 2>& e : mesh.creases) strokeLine(world(mesh.positions[e[0]]), world(mesh.positions[e[1]]), width);
  const Vec3 eyeInBody = rotation.inverse() * (camera_.eye() - x);
  for (const std::array<int, 2>& e : silhouette(mesh, eyeInBody))
    strokeLine(world(mesh.positions[e[0]]), world(mesh.positions[e[1]]), width);
  for (const std::vector<Vec3>& curve : mesh.curves)
    for (size_t i = 0; i < curve.size(); ++i)
      strokeLine(world(curve[i]), world(curve[(i + 1) % curve.size()]), kCurveWidth * style_.lineWidth);
}

void GlCanvas3d::strokeLine(const Vec3& a, const Vec3& b, double widthPx) {
  Vec3 ca = camera_.toCamera(a), cb = camera_.toCamera(b);
  // the part in front of the near plane
  const double near = camera_.nearDepth() * 1.0001;
  if (ca.z() < near && cb.z() < near) return;
  if (ca.z() < near) ca = cb + (ca - cb) * ((cb.z() - near) / (cb.z() - ca.z()));
  if (cb.z() < near) cb = ca + (cb - ca) * ((ca.z() - near) / (ca.z() - cb.z()));
  const Vec2 pa = camera_.pixelOf(ca), pb = camera_.pixelOf(cb);
  const Vec2 d = pb - pa;
  if (!(d.norm() > 1e-9)) return;
  // a strip half the width to each side, lengthened by as much at both ends so that lines meeting
  // at a corner join without a notch
  const double half = 0.5 * widthPx;
  const Vec2 along = d.normalized() * half, side(-along.y(), along.x());
  glBegin(GL_TRIANGLE_STRIP);
  vertex(camera_.clipOf(pa - along - side, ca.z()));
  vertex(camera_.clipOf(pa - along + side, ca.z()));
  vertex(camera_.clipOf(pb + along - side, cb.z()));
  vertex(camera_.clipOf(pb + along + side, cb.z()));
  glEnd();
}

}  // namespace render::draw3d
