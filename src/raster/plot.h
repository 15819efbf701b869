#pragma once
/// \file
/// A log-log line plot drawn by the program itself (no plotting library): white canvas, axes
/// with a tick and label at every power of ten (and unlabelled minor ticks at 2..9 times it),
/// axis titles, a title, one polyline with square markers per series, and a legend.
///
/// Data are mapped by u = (log10 x - log10 x_lo) / (log10 x_hi - log10 x_lo), the axis range
/// being the data range widened to whole decades [1]; points with x <= 0 or y <= 0 (or not
/// finite) cannot be shown on log axes and are skipped, which breaks the line there.
///
/// References
/// [1] Cleveland, "The Elements of Graphing Data", Hobart Press 1994, ch. 2 (logarithmic scales,
///     ticks at powers of ten).

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/image.h"

namespace prt {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;  ///< same length
  glm::vec3 color{0.f};      ///< display RGB in [0, 1]
  bool dashed = false;
};

struct PlotOptions {
  int width = 960, height = 640;
  std::string title, x_label, y_label;
};

/// The plot of `series` (see above). Sizes below 200 x 150 are raised to it.
Image8 DrawLogLogPlot(const std::vector<PlotSeries>& series, const PlotOptions& options);

/// A distinguishable colour for series i (a fixed qualitative palette, repeating after 10).
glm::vec3 PlotColor(int i);

}  // namespace prt
