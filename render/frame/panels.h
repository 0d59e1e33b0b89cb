// The poll slide: the same instant of every variant on one sheet made for a slide (1920 × 1080 by
// default), in a grid: 2 variants side by side, 3-4 as 2 × 2, more in rows of ⌈√n⌉; each panel
// under its title, one caption shared under the grid, every text at least a 40th of the sheet high.
//
//   ┌──────── title A ───────┬──────── title B ───────┐
//   │        frame A         │        frame B         │
//   ├──────── title C ───────┼────────────────────────┤
//   │        frame C         │                        │
//   └────────────────────────┴────────────────────────┘
//     the caption, once
#pragma once

#include <string>
#include <vector>

#include "render/draw/image.h"
#include "render/draw/style.h"
#include "render/draw/text.h"
#include "render/frame/pixel_draw_list.h"

namespace render::frame {

// the default sheet, px: a 1080p slide
inline constexpr int kSheetWidth = 1920, kSheetHeight = 1080;

// where each panel goes on a sheet, px
struct PanelGrid {
  int sheetWidth = 0, sheetHeight = 0;
  int columns = 0, rows = 0;
  int frameWidth = 0, frameHeight = 0;  // of each panel's frame (even)
  int textSize = 0;                     // every text of the sheet, px: at least sheetHeight / 40
  int titleStrip = 0;                   // the band above each frame holding its title
  int gap = 0;                          // between panels, with a rule in it
  int captionBand = 0;                  // under the grid (0 without a caption)
  int captionLines = 2;                 // the caption's lines in it
  bool captionInCell = false;           // the caption in the grid's first empty cell instead (no band)
  // the top-left corner of panel i's frame
  int frameX(size_t i) const;
  int frameY(size_t i) const;
};

// the grid of `count` panels on a `width` × `height` sheet, with `caption` the caption in the grid's
// first empty cell (three variants in 2 × 2) or else in a band of `captionLines` lines under it, in `columns` columns (0: 2 side
// by side, 3-4 as 2 × 2, more in rows of ⌈√n⌉). Throws render::jobs::UsageError when a panel's frame would be under 16 px a side
PanelGrid panelGrid(size_t count, int width, int height, bool caption, int columns = 0, int captionLines = 2);
// the lines a sheet `width` px wide needs for the whole of `caption` at its text size (at least 1, at
// most kMostCaptionLines: a caption longer than that ends in "…")
inline constexpr int kMostCaptionLines = 4;
int sheetCaptionLines(const std::string& caption, int width, int height, render::draw::TextRenderer& text);

// the frames in the grid, each under its title, the caption under them all (wrapped to the sheet,
// at most two lines), on the style's background with thin rules between the panels; every frame
// must be the grid's frame size
render::draw::Image composePanels(const std::vector<render::draw::Image>& frames, const PanelGrid& grid,
                                  const std::vector<std::string>& titles, const std::string& caption,
                                  const render::draw::Style& style, render::draw::TextRenderer& text);

// a text the sheet writes itself, its top-center point in sheet pixels: the panels' titles, then the
// caption's lines
struct SheetText {
  std::string text;
  sim::core::Vec2 at;
};
std::vector<SheetText> sheetTexts(const PanelGrid& grid, size_t count, const std::vector<std::string>& titles,
                                  const std::string& caption, render::draw::TextRenderer& text);

// the sheet's draw list: each panel's (`cells`, in its frame's pixels) moved to its place in the grid,
// then the titles and the caption as composePanels writes them
PixelDrawList sheetDrawList(const std::vector<PixelDrawList>& cells, const PanelGrid& grid,
                            const std::vector<std::string>& titles, const std::string& caption, const render::draw::Style& style,
                            render::draw::TextRenderer& text);

// "A", "B", …, "Z", "AA", … : the letter of the i-th panel (from 0)
std::string panelLetter(size_t i);

}  // namespace render::frame
