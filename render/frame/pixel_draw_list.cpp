#include "render/frame/pixel_draw_list.h"

#include <cmath>

#include "render/jobs/json_writer.h"

namespace render::frame {
using sim::core::Vec2;
using namespace render::draw;

PixelBox textBox(const Vec2& at, Anchor anchor, int width, int lineHeight) {
  double left = at.x(), top = at.y();
  if (anchor == Anchor::Center || anchor == Anchor::TopCenter) left -= 0.5 * width;
  if (anchor == Anchor::Center) top -= 0.5 * lineHeight;
  left = std::lround(left), top = std::lround(top);
  return {left, top, left + width, top + lineHeight};
}

PixelDrawList pixelDrawList(const DrawList& list, const Style& style, const Camera& camera, const TextWidth& width, int fontPx) {
  PixelDrawList out{camera.widthPx(), camera.heightPx(), {}};
  const double px = camera.pixelSize();
  for (const DrawList::Call& c : list.calls()) {
    PixelCall call{DrawList::kindName(c.kind), penName(c.style), style.penColor(c.style).hex(), c.text, {}, {}, c.style};
    const auto add = [&call](const Vec2& p) { call.numbers.push_back(p.x()), call.numbers.push_back(p.y()); };
    switch (c.kind) {
      case DrawList::Kind::HalfPlane:
        // its point, and its normal turned as y turns down
        add(camera.toPixel(c.points[0]));
        add(Vec2(c.points[1].x(), -c.points[1].y()).normalized());
        break;
      case DrawList::Kind::Label:
        // a label not yet placed (a canvas that draws it where it prefers): its anchor and direction
        add(camera.toPixel(c.points[0]));
        add(Vec2(c.points[1].x(), -c.points[1].y()));
        break;
      default:
        for (const Vec2& p : c.points) add(camera.toPixel(p));
    }
    if (c.kind == DrawList::Kind::Circle) call.numbers.push_back(c.radius / px);
    if (c.kind == DrawList::Kind::Text)
      call.box = textBox(camera.toPixel(c.points[0]), c.style.role == Role::Caption ? Anchor::TopLeft : Anchor::Center,
                         width(c.text), lineHeightPx(fontPx));
    out.calls.push_back(std::move(call));
  }
  return out;
}

void addMoved(PixelDrawList& sheet, const PixelDrawList& cell, double dx, double dy) {
  for (PixelCall c : cell.calls) {
    // points are pairs, a circle's radius last and a half-plane's normal or a label's direction second: not moved
    const size_t moved = c.kind == "halfplane" || c.kind == "label" ? 2 : c.numbers.size() - (c.kind == "circle" ? 1 : 0);
    for (size_t k = 0; k + 1 < moved; k += 2) c.numbers[k] += dx, c.numbers[k + 1] += dy;
    if (c.box) *c.box = {c.box->left + dx, c.box->top + dy, c.box->right + dx, c.box->bottom + dy};
    sheet.calls.push_back(std::move(c));
  }
}

void addText(PixelDrawList& image, const std::string& text, const Vec2& at, Anchor anchor, int width, int lineHeight,
             const Color& color) {
  const Pen pen{Role::Caption, -1, 1.0};
  image.calls.push_back({"text", penName(pen), color.hex(), text, {at.x(), at.y()}, textBox(at, anchor, width, lineHeight), pen});
}

void writePixelDrawList(std::ostream& out, const PixelDrawList& list) {
  render::jobs::JsonWriter j(out);
  j.beginObject().field("width", static_cast<long>(list.width)).field("height", static_cast<long>(list.height));
  j.key("calls").beginArray();
  for (const PixelCall& c : list.calls) {
    out << '\n';
    j.beginObject().field("kind", c.kind).field("pen", c.pen).field("color", c.color);
    j.key("numbers").beginArray();
    for (double x : c.numbers) j.value(x);
    j.endArray();
    if (!c.text.empty()) j.field("text", c.text);
    if (c.box) j.key("box").beginArray().value(c.box->left).value(c.box->top).value(c.box->right).value(c.box->bottom).endArray();
    j.endObject();
  }
  j.endArray().endObject();
  out << '\n';
}

std::string drawListPathFor(const std::string& pngPath) {
  const std::string ending = ".png";
  const bool png = pngPath.size() >= ending.size() && pngPath.compare(pngPath.size() - ending.size(), ending.size(), ending) == 0;
  return (png ? pngPath.substr(0, pngPath.size() - ending.size()) : pngPath) + ".json";
}

}  // namespace render::frame
