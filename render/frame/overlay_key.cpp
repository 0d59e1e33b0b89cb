#include "render/frame/overlay_key.h"

#include <algorithm>

#include "render/draw/text.h"
#include "render/frame/caption.h"

namespace render::frame {

using namespace render::draw;
using sim::core::Vec2;
namespace {

const char* const kReferenceEdge = "reference edge";
const char* const kIncidentVertex = "incident vertex";
const char* const kNormal = "contact normal n̂";
const char* const kImpulse = "impulse j";
// a row's sample, in line heights
constexpr double kSample = 1.5;

}  // namespace

int keyFirstRow(const render::scene::RenderDef& r) {
  if (r.overlay) return 4;
  return !r.slowMotion.empty() ? 2 : r.time ? 1 : 0;
}

std::vector<std::string> possibleKeyRows(const render::scene::RenderDef& r, bool impacts) {
  std::vector<std::string> rows;
  if (!r.key) return rows;
  if (r.sat || r.overlays.satAxes) rows.push_back(kIncidentVertex), rows.push_back(kReferenceEdge);
  if (impacts && r.contacts && !r.overlays.impactValues) rows.push_back(kNormal), rows.push_back(kImpulse);
  return rows;
}

std::vector<std::string> overlayKeyRows(const OverlaysSeen& seen, bool labelled) {
  std::vector<std::string> rows;
  if (seen.seen(Role::ReferenceEdge)) rows.push_back(kReferenceEdge);
  if (seen.seen(Role::IncidentVertex)) rows.push_back(kIncidentVertex);
  // the normal and the impulse side by side along one line: which is which is the key's to say
  if (!labelled && seen.seen(Role::ContactNormal) && seen.seen(Role::Impulse)) {
    rows.push_back(kNormal);
    rows.push_back(kImpulse);
  }
  return rows;
}

void drawOverlayKey(const std::vector<std::string>& rows, const Camera& camera, int fontPx, int firstRow, Canvas& draw) {
  const CaptionLayout layout = captionLayout(fontPx);
  const double sample = kSample * layout.line;
  // rows at least a pixel more than a line of text apart: boxes rounded to whole pixels never touch
  const double pitch = std::max(layout.line, render::draw::lineHeightPx(fontPx) + 1.0);
  for (size_t i = 0; i < rows.size(); ++i) {
    const double top = layout.inset + (firstRow + static_cast<double>(i)) * pitch;
    const double middle = top + 0.5 * layout.line;
    const Vec2 a = camera.toWorld({layout.inset, middle}), b = camera.toWorld({layout.inset + sample, middle});
    const std::string& row = rows[i];
    // the mark as the frame draws it
    if (row == kReferenceEdge) draw.segment(a, b, {Role::ReferenceEdge, -1, 1.0});
    else if (row == kIncidentVertex) draw.point(0.5 * (a + b), {Role::IncidentVertex, -1, 1.0});
    else draw.arrow(a, b, {row == kNormal ? Role::ContactNormal : Role::Impulse, -1, 1.0});
    draw.text(camera.toWorld({layout.inset + sample + 0.5 * layout.line, top}), row, {Role::Caption, -1, 1.0});
  }
}

}  // namespace render::frame
