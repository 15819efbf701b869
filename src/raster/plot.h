#pragma once
/// \file
/// A log-log line plot drawn by the program itself (no plotting library): white canvas, axes
/// with a tick and label at every power of ten (and unlabelled minor ticks at 2..9 times it),
/// axis titles, a title, one polyline with square markers per series, and a legend.
///
/// Data are mapped by u = (log10 x - log10 x_lo) / (log10 x_hi - log10 x_lo). The axis range is
/// the data range widened only to the nearest ticks m 10^e (m = 1..9) outside it, so it begins
/// less than a factor 2 before the first point and ends less than a factor 2 after the last
/// (widening to whole decades could leave nine tenths of an axis empty) [1]; powers of ten are
/// labelled, and 2 and 5 times them too when the axis spans under two decades [2]. Points with
/// x <= 0 or y <= 0 (or not finite) cannot be shown on log axes and are skipped, which breaks
/// the line there.
///
/// References
/// [1] Cleveland, "The Elements of Graphing Data", Hobart Press 1994, ch. 2 (logarithmic scales;
///     the data should fill the scale region).
/// [2] Heckbert, "Nice Numbers for Graph Labels", Graphics Gems, 1990 (labels at 1, 2, 5 times
///     powers of ten).

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

/// The range [lo, hi] of a log axis holding `values` (those > 0 and finite; [1, 10] if none):
/// lo the largest m 10^e (m = 1..9) not above the smallest value, hi the smallest not below the
/// largest (the next tick up when they meet).
struct LogRange {
  double lo = 1.0, hi = 10.0;
};
LogRange LogAxisRange(const std::vector<double>& values);

/// The plot of `series` (see above). Sizes below 200 x 150 are raised to it.
Image8 DrawLogLogPlot(const std::vector<PlotSeries>& series, const PlotOptions& options);

/// A distinguishable colour for series i (a fixed qualitative palette, repeating after 10).
glm::vec3 PlotColor(int i);

}  // namespace prt
