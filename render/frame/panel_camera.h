// The one camera of a sheet of poll panels (panels.h): fitted over every variant's run, as a
// variant's own camera is, then grown until everything each panel draws lies inside its frame at
// every instant of the run it is fitted over (48 evenly spaced ones and each impact): bodies, arrows
// (whose length follows the view's height), dots. Like the bodies' camera it is the run's, not a
// shot's, so a sheet at one time is the same picture whatever other times were asked with it.
// Texts and labels are placed inside the frame by the label placer, and are not fitted.
#pragma once

#include <vector>

#include "render/draw/camera.h"
#include "render/draw/draw_list.h"
#include "render/frame/survey.h"

namespace render::frame {

// the world box of what `list` draws in the scene (not texts, labels, the energy panel or
// half-planes, which reach the frame's edges by design)
render::draw::Bounds drawnBounds(const render::draw::DrawList& list);

// the instants a variant's panel is fitted over: 48 evenly spaced over its duration, and its impacts
std::vector<double> fittingInstants(const render::scene::Scene& scene, const RunSurvey& survey);

// the camera for `scenes` side by side (each at the panel's frame size); `widest` is the variant
// beside the widest energy panel. Throws sim::core::Diverged
render::draw::Camera panelCamera(const std::vector<render::scene::Scene>& scenes, const std::vector<RunSurvey>& surveys,
                                 size_t widest);

}  // namespace render::frame
