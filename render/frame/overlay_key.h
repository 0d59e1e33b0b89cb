// A short key, once per frame in its top-left corner under the clock, to the overlays whose meaning is
// not written beside them: the separating-axis overlay's reference edge and incident vertex, and the
// contact normal against the impulse (unless `impact_values` labels them n̂ and j). Each row a sample
// of the mark drawn as the frame draws it, then its name; only the overlays the frame drew.
//
//   t = 0.800 s
//   ▬▬  reference edge
//    ◯  incident vertex
#pragma once

#include <array>
#include <string>

#include "render/draw/camera.h"
#include "render/draw/canvas.h"
#include "render/scene/render_def.h"

namespace render::frame {

// every call passed on to `target`, the roles drawn noted on the way
class OverlaysSeen final : public render::draw::Canvas {
 public:
  explicit OverlaysSeen(render::draw::Canvas& target) : target_(target) {}
  bool seen(render::draw::Role role) const { return seen_[static_cast<size_t>(role)]; }

  void polygon(const std::vector<sim::core::Vec2>& v, const render::draw::Pen& p) override { note(p), target_.polygon(v, p); }
  void circle(const sim::core::Vec2& c, double r, const render::draw::Pen& p) override { note(p), target_.circle(c, r, p); }
  void halfPlane(const sim::core::Vec2& q, const sim::core::Vec2& n, const render::draw::Pen& p) override {
    note(p), target_.halfPlane(q, n, p);
  }
  void segment(const sim::core::Vec2& a, const sim::core::Vec2& b, const render::draw::Pen& p) override {
    note(p), target_.segment(a, b, p);
  }
  void point(const sim::core::Vec2& q, const render::draw::Pen& p) override { note(p), target_.point(q, p); }
  void arrow(const sim::core::Vec2& t, const sim::core::Vec2& h, const render::draw::Pen& p) override {
    note(p), target_.arrow(t, h, p);
  }
  void text(const sim::core::Vec2& at, const std::string& t, const render::draw::Pen& p) override { target_.text(at, t, p); }
  void label(const sim::core::Vec2& a, const sim::core::Vec2& d, const std::string& t, const render::draw::Pen& p) override {
    target_.label(a, d, t, p);
  }
  void manyPoints(double radius) override { target_.manyPoints(radius); }

 private:
  void note(const render::draw::Pen& p) { seen_[static_cast<size_t>(p.role)] = true; }
  render::draw::Canvas& target_;
  std::array<bool, render::draw::kRoleCount> seen_{};
};

// the row of the top-left corner the key starts at: under the clock, the slow-motion note (where the
// scene slows) and the --overlay legend (two rows), so that it never moves within a video
int keyFirstRow(const render::scene::RenderDef& render);
// the texts it may hold, for a layout made before any frame (the energy panel's); `impacts`: the run
// has impacts, whose normals and impulses it may key
std::vector<std::string> possibleKeyRows(const render::scene::RenderDef& render, bool impacts);

// the key's rows for what `seen` drew, with `labelled` true where n̂ and j are written at each impact
std::vector<std::string> overlayKeyRows(const OverlaysSeen& seen, bool labelled);
// the key drawn from row `firstRow` of the top-left corner's lines down (the clock is row 0), in a
// frame whose text is `fontPx` high; its names as text fixed to the frame
void drawOverlayKey(const std::vector<std::string>& rows, const render::draw::Camera& camera, int fontPx, int firstRow,
                    render::draw::Canvas& draw);

}  // namespace render::frame
