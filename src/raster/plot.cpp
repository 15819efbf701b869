#include "raster/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "raster/annotate.h"

namespace prt {
namespace {

void Put(Image8& im, int x, int y, glm::vec3 c) {
  if (x < 0 || y < 0 || x >= im.width || y >= im.height) return;
  std::uint8_t* p = im.rgb.data() + 3 * (static_cast<std::size_t>(y) * im.width + x);
  for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::lround(std::clamp(c[k], 0.f, 1.f) * 255.f));
}

void Rect(Image8& im, int x0, int y0, int x1, int y1, glm::vec3 c) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) Put(im, x, y, c);
}

/// A line two pixels wide from (x0, y0) to (x1, y1); dashed draws 6 on, 4 off.
void Line(Image8& im, double x0, double y0, double x1, double y1, glm::vec3 c, bool dashed) {
  const double len = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
  const int steps = std::max(1, static_cast<int>(std::ceil(len)));
  for (int i = 0; i <= steps; ++i) {
    if (dashed && (i % 10) >= 6) continue;
    const double t = double(i) / steps;
    const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
    const int y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
    Rect(im, x, y, x + 2, y + 2, c);
  }
}

int TextWidth(const std::string& s, int scale) { return static_cast<int>(s.size()) * 6 * scale; }

std::string Decade(int e) {
  if (e == 0) return "1";
  if (e == 1) return "10";
  char b[16];
  std::snprintf(b, sizeof b, "1e%d", e);
  return b;
}

struct Range {
  int lo = 0, hi = 1;  // decades
};

Range DecadeRange(const std::vector<PlotSeries>& series, bool use_x) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& s : series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      const double v = use_x ? s.x[i] : s.y[i];
      if (!(s.x[i] > 0) || !(s.y[i] > 0) || !std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      lo = std::min(lo, std::log10(v));
      hi = std::max(hi, std::log10(v));
    }
  Range r;
  if (!std::isfinite(lo)) return r;
  r.lo = static_cast<int>(std::floor(lo));
  r.hi = static_cast<int>(std::ceil(hi));
  if (r.hi <= r.lo) r.hi = r.lo + 1;
  return r;
}

}  // namespace

glm::vec3 PlotColor(int i) {
  static const glm::vec3 palette[10] = {{0.12f, 0.47f, 0.71f}, {1.00f, 0.50f, 0.05f}, {0.17f, 0.63f, 0.17f},
                                        {0.84f, 0.15f, 0.16f}, {0.58f, 0.40f, 0.74f}, {0.55f, 0.34f, 0.29f},
                                        {0.89f, 0.47f, 0.76f}, {0.50f, 0.50f, 0.50f}, {0.74f, 0.74f, 0.13f},
                                        {0.09f, 0.75f, 0.81f}};
  return palette[((i % 10) + 10) % 10];
}

Image8 DrawLogLogPlot(const std::vector<PlotSeries>& series, const PlotOptions& o) {
  Image8 im(std::max(o.width, 200), std::max(o.height, 150));
  std::fill(im.rgb.begin(), im.rgb.end(), std::uint8_t{255});
  const glm::vec3 black(0.f), grey(0.85f);
  // Plot area: room for tick labels and titles on the left and bottom, legend on the right.
  const int left = 70, top = 36, right = im.width - 200, bottom = im.height - 50;
  const Range xr = DecadeRange(series, true), yr = DecadeRange(series, false);
  auto px = [&](double x) { return left + (std::log10(x) - xr.lo) / (xr.hi - xr.lo) * (right - left); };
  auto py = [&](double y) { return bottom - (std::log10(y) - yr.lo) / (yr.hi - yr.lo) * (bottom - top); };

  // Grid, ticks and tick labels.
  for (int e = xr.lo; e <= xr.hi; ++e)
    for (int m = 1; m <= (e < xr.hi ? 9 : 1); ++m) {
      const int x = static_cast<int>(std::lround(px(m * std::pow(10.0, e))));
      Rect(im, x, top, x + 1, bottom, m == 1 ? grey : glm::vec3(0.94f));
      Rect(im, x, bottom, x + 1, bottom + (m == 1 ? 7 : 4), black);
      if (m == 1) DrawText(im, x - TextWidth(Decade(e), 1) / 2, bottom + 10, Decade(e), black);
    }
  for (int e = yr.lo; e <= yr.hi; ++e)
    for (int m = 1; m <= (e < yr.hi ? 9 : 1); ++m) {
      const int y = static_cast<int>(std::lround(py(m * std::pow(10.0, e))));
      Rect(im, left, y, right, y + 1, m == 1 ? grey : glm::vec3(0.94f));
      Rect(im, left - (m == 1 ? 7 : 4), y, left, y + 1, black);
      if (m == 1) DrawText(im, left - 10 - TextWidth(Decade(e), 1), y - 4, Decade(e), black);
    }
  // Axes and titles.
  Rect(im, left, top, left + 1, bottom + 1, black);
  Rect(im, left, bottom, right + 1, bottom + 1, black);
  DrawText(im, (left + right - TextWidth(o.x_label, 2)) / 2, im.height - 24, o.x_label, black, 2);
  DrawText(im, 6, top - 22, o.y_label, black, 2);
  DrawText(im, (left + right - TextWidth(o.title, 2)) / 2 + 60, 6, o.title, black, 2);

  // Series: polylines with square markers.
  for (const auto& s : series) {
    bool have_prev = false;
    double x0 = 0, y0 = 0;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!(s.x[i] > 0) || !(s.y[i] > 0) || !std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
        have_prev = false;
        continue;
      }
      const double x = px(s.x[i]), y = py(s.y[i]);
      if (have_prev) Line(im, x0, y0, x, y, s.color, s.dashed);
      Rect(im, int(x) - 2, int(y) - 2, int(x) + 3, int(y) + 3, s.color);
      x0 = x, y0 = y, have_prev = true;
    }
  }

  // Legend: a short line and the label per series.
  int ly = top;
  for (const auto& s : series) {
    if (ly > im.height - 16) break;
    Line(im, right + 12, ly + 4, right + 36, ly + 4, s.color, s.dashed);
    DrawText(im, right + 42, ly, s.label, black);
    ly += 14;
  }
  return im;
}

}  // namespace prt
