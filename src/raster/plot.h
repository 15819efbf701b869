#pragma once
/// \file
/// A log-log line plot drawn by the program itself (no plotting library): white canvas, axes
/// with a tick and label at every power of ten (and unlabelled minor ticks at 2..9 times it),
/// axis titles, a title, one polyline with markers per series, and a legend. A series is told
/// apart by its colour and its marker's shape (and may be dashed, or hollow-marked for points
/// that stand for something else, e.g. a time borrowed from another run); a point may carry a
/// horizontal range (its x's min and max), drawn as a bar with end caps.
///
/// Data are mapped by u = (log10 x - log10 x_lo) / (log10 x_hi - log10 x_lo). The axis range is
/// the data range widened only to the nearest ticks m 10^e (m = 1..9) outside it, so it begins
/// less than a factor 2 before the first point and ends less than a factor 2 after the last
/// (widening to whole decades could leave nine tenths of an axis empty) [1]; powers of ten are
/// labelled, and 2 and 5 times them too when the axis spans under two decades [2]. The range's
/// ends sit a few pixels inside the axis lines, so that a point on either end is drawn whole
/// inside the axes. Points with x <= 0 or y <= 0 (or not finite) cannot be shown on log axes
/// and are skipped, which breaks the line there.
///
/// References
/// [1] Cleveland, "The Elements of Graphing Data", Hobart Press 1994, ch. 2 (logarithmic scales;
///     the data should fill the scale region).
/// [2] Heckbert, "Nice Numbers for Graph Labels", Graphics Gems, 1990 (labels at 1, 2, 5 times
///     powers of ten).

#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/image.h"

namespace prt {

enum class PlotMarker { kSquare, kCircle, kTriangle, kDiamond };

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;  ///< same length
  glm::vec3 color{0.f};      ///< display RGB in [0, 1]
  bool dashed = false;
  PlotMarker marker = PlotMarker::kSquare;
  bool hollow = false;       ///< markers drawn as outlines
  /// Empty, or one [x_min, x_max] per point: a horizontal bar through the marker.
  std::vector<double> x_min, x_max;
};

struct PlotOptions {
  int width = 960, height = 640;
  std::string title, x_label, y_label;
  /// Lines of text under the legend (what the markers mean, where a value comes from).
  std::vector<std::string> notes;
};

/// The range [lo, hi] of a log axis holding `values` (those > 0 and finite; [1, 10] if none):
/// lo the largest m 10^e (m = 1..9) not above the smallest value, hi the smallest not below the
/// largest (the next tick up when they meet).
struct LogRange {
  double lo = 1.0, hi = 10.0;
};
LogRange LogAxisRange(const std::vector<double>& values);

/// The labelled ticks of a log axis over `range`, in increasing order: (value, text). Powers of
/// ten always; 2 and 5 times them under two decades; every tick under a factor 3; and each end
/// of the axis when its label would not crowd a neighbour's (`min_gap` in units of the axis,
/// 0..1, measured in log10 of the value over log10 of the range).
std::vector<std::pair<double, std::string>> LogAxisLabels(const LogRange& range, double min_gap);

/// The plot of `series` (see above). Sizes below 200 x 150 are raised to it.
Image8 DrawLogLogPlot(const std::vector<PlotSeries>& series, const PlotOptions& options);

/// `panels` one above the other on a white canvas as wide as the widest (e.g. one plot per
/// transport mode in one file).
Image8 StackVertically(const std::vector<Image8>& panels);

/// A distinguishable colour for series i (a fixed qualitative palette, repeating after 10).
glm::vec3 PlotColor(int i);

}  // namespace prt
