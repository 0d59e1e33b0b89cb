#include "render/golden/drawn_frame3d.h"

namespace render::golden {

DrawnFrame drawnFrame3d(const render::draw3d::DrawList3d& list, const render::draw::Style& style, int widthPx, int heightPx) {
  DrawnFrame f = drawnFrame(list.overlayCalls(), style, render::draw3d::overlayCamera(widthPx, heightPx));
  std::vector<DrawnCall> solids;
  for (const render::draw3d::DrawList3d::Solid& s : list.solids()) {
    DrawnCall d{"solid", render::draw::penName(s.pen), style.penColor(s.pen).hex(), s.mesh, {s.x.x(), s.x.y(), s.x.z()}};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) d.numbers.push_back(s.rotation(r, c));
    solids.push_back(std::move(d));
  }
  // the solids first, as the frame draws them
  f.calls.insert(f.calls.begin(), solids.begin(), solids.end());
  return f;
}

}  // namespace render::golden
