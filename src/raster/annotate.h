#pragma once
/// \file
/// Drawing on finished 8-bit frames for teaching views: text (stb_easy_font's quad font), a
/// diverging false-colour scale for signed quantities, and its legend.
///
/// The diverging map sends -1 to blue, 0 to near-white and +1 to red through smooth ramps
/// (in the spirit of Moreland's "cool to warm" map [1]), so the sign of a value reads at a
/// glance and its magnitude as saturation.
///
/// References
/// [1] Moreland, "Diverging Color Maps for Scientific Visualization", ISVC 2009.

#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/image.h"

namespace prt {

/// Display (sRGB-encoded, 0..1) colour of t in [-1, 1] on the diverging scale.
glm::vec3 DivergingColor(double t);

/// Writes `text` with its top-left corner at (x, y), each font pixel `scale` pixels wide.
void DrawText(Image8& image, int x, int y, const std::string& text, glm::vec3 color, int scale = 1);

/// Width and height in pixels of the ink DrawText puts down for `text` at `scale`, measured
/// from its top-left corner (x, y): every drawn pixel lies in [x, x + w) x [y, y + h).
glm::ivec2 TextSize(const std::string& text, int scale = 1);

/// An axis-aligned pixel rectangle [x0, x1) x [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// Where DrawDivergingLegend puts things. Everything it draws lies inside `panel`.
struct LegendLayout {
  int text_scale = 1;   ///< font pixel size of the labels and title
  PixelRect panel;      ///< dark background behind bar, labels and title
  PixelRect bar;        ///< the colour bar: +max_abs at its top row, -max_abs at its bottom row
  PixelRect title;      ///< ink box of the title
  PixelRect labels[3];  ///< ink boxes of the labels +max_abs, 0, -max_abs (top to bottom)
};

/// The legend's layout on a width x height image, or nothing when the image is too small even
/// at text scale 1. Sizes follow the image: the text scale is height / 540 rounded (1 at 480,
/// 2 at 1080, never below 1), the bar is 1/40 of the width (at least 6 text pixels) and the
/// label column is as wide as the widest label's ink. When the panel does not fit (at most half
/// the width, a bar at least 20 pixels tall), the text shrinks one step at a time before giving
/// up.
std::optional<LegendLayout> LayoutDivergingLegend(int width, int height, double max_abs,
                                                  const std::string& title);

/// A vertical colour bar at the right edge from -max_abs (bottom) to +max_abs (top), labelled
/// with its ends, zero and `title`, laid out by LayoutDivergingLegend (nothing drawn when it
/// does not fit).
void DrawDivergingLegend(Image8& image, double max_abs, const std::string& title);

}  // namespace prt
