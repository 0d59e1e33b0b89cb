// The draw lists of a plan's stills in their images' pixels (render/frame/pixel_draw_list.h): a frame's
// own, or a sheet's, its panels' moved to their cells with its titles and caption. The writer makes
// them beside the frames it paints (`snapshot --draw-list`); the layout tests make them without GL.
#pragma once

#include <functional>
#include <vector>

#include "render/draw/draw_list.h"
#include "render/draw/text.h"
#include "render/frame/pixel_draw_list.h"
#include "render/video/render_plan.h"

namespace render::video {

// variant `variant`'s frame of `stills`, recorded as `list`, in the frame's pixels
render::frame::PixelDrawList frameDrawList(const Stills& stills, size_t variant, const render::draw::DrawList& list,
                                           render::draw::TextRenderer& text);
// the still `shot`'s whole draw list from its frames' (one per variant, in order): the frame's own,
// or the sheet's
render::frame::PixelDrawList stillDrawList(const Stills& stills, const StillOutput& shot,
                                           const std::vector<render::frame::PixelDrawList>& frames,
                                           render::draw::TextRenderer& text);
// every still's draw list, as the writer would make it, without GL: each variant run once through
// the instants, told to `shot` in the stills' order. Throws sim::core::Diverged
void stillDrawLists(const Stills& stills, const std::function<void(size_t shot, const render::frame::PixelDrawList&)>& shot);

}  // namespace render::video
