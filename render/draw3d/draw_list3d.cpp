#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "render/draw3d/canvas3d.h"

namespace render::draw3d {

using render::draw::Pen;
using sim::core::Vec2;
using sim::world3d::Mat3;
using sim::world3d::Vec3;
render::draw::Camera overlayCamera(int widthPx, int heightPx) {
  return render::draw::Camera(Vec2(0.5 * widthPx, 0.5 * heightPx), heightPx, widthPx, heightPx);
}

namespace {

// as DrawList writes numbers: 6 significant digits, round-off around zero written 0
std::string numbers(std::initializer_list<double> values) {
  std::string s = "(";
  for (double x : values) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", std::abs(x) < 1e-12 ? 0.0 : x);
    // appended piece by piece: g++ 12 warns of overlapping copies in ("," or "") + std::string(buf)
    // (GCC bug 105329, a false positive)
    if (s.size() > 1) s += ',';
    s += buf;
  }
  return s + ")";
}

}  // namespace

void DrawList3d::solid(const Mesh& mesh, const Vec3& x, const Mat3& rotation, const Pen& pen) {
  // R by its rows, as it stands: a drifted q's matrix is no rotation, and the list says so
  const Mat3& r = rotation;
  solidCalls_.push_back({mesh.name, pen, x, rotation});
  solids_.push_back("solid " + std::string(render::draw::info(pen.role).name) + "#" + std::to_string(pen.body) + " " + mesh.name +
                    " x=" + numbers({x.x(), x.y(), x.z()}) + " R=" + numbers({r(0, 0), r(0, 1), r(0, 2)}) +
                    numbers({r(1, 0), r(1, 1), r(1, 2)}) + numbers({r(2, 0), r(2, 1), r(2, 2)}));
}

std::vector<std::string> DrawList3d::lines() const {
  std::vector<std::string> out = solids_;
  for (const std::string& line : overlay_.lines()) out.push_back(line);
  return out;
}

std::string DrawList3d::toText() const {
  std::string text;
  for (const std::string& line : lines()) text += line + "\n";
  return text;
}

}  // namespace render::draw3d
