// A golden frame's draw list as JSON (the middle of the three levels: what is shown, apart from how
// the rasterizer draws it), written beside its PNG and compared call by call with a later run's.
//
//   {"view": {"center": [x, y], "width": w, "height": h},
//    "calls": [{"kind": "polygon", "pen": "Body#0", "color": "#3b6ea5", "points": [[x, y], ...],
//               "radius": 0, "text": ""}, ...]}
//
// `pen` is the draw-list line's role, body, opacity and arrow colour (DrawList::lines); `color` the
// pen's base colour in the scene's style (a body's own colour, a role's colour from render.colors).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "render/draw/camera.h"
#include "render/draw/draw_list.h"
#include "render/draw/style.h"

namespace render::golden {

// one call as compared: its numbers in the order written (the points' coordinates, then the radius)
struct DrawnCall {
  std::string kind, pen, color, text;
  std::vector<double> numbers;
};

struct DrawnFrame {
  double viewWidth = 0.0, viewHeight = 0.0;  // m
  std::vector<DrawnCall> calls;
};

// the frame's calls with their colours in `style`, seen through `camera`
DrawnFrame drawnFrame(const render::draw::DrawList& list, const render::draw::Style& style, const render::draw::Camera& camera);
void writeDrawnFrame(std::ostream& out, const DrawnFrame& frame);
// the JSON of writeDrawnFrame read back; throws sim::yaml::SceneError naming the file
DrawnFrame readDrawnFrame(const std::string& path);

// "" when `actual` makes the same calls as `expected` with every number within `tolerance` of the
// view's larger side (1e-6: a millionth of what the frame shows); else the first difference
std::string compareDrawnFrames(const DrawnFrame& expected, const DrawnFrame& actual, double tolerance = 1e-6);

}  // namespace render::golden
