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

#include <string>

#include <glm/vec3.hpp>

#include "core/image.h"

namespace prt {

/// Display (sRGB-encoded, 0..1) colour of t in [-1, 1] on the diverging scale.
glm::vec3 DivergingColor(double t);

/// Writes `text` with its top-left corner at (x, y), each font pixel `scale` pixels wide.
void DrawText(Image8& image, int x, int y, const std::string& text, glm::vec3 color, int scale = 1);

/// A vertical colour bar at the right edge from -max_abs (bottom) to +max_abs (top), labelled
/// with its ends, zero and `title`.
void DrawDivergingLegend(Image8& image, double max_abs, const std::string& title);

}  // namespace prt
