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

/// The tick label of m 10^e: "1e-3", "2e-3", "1", "20".
std::string TickLabel(int m, int e) {
  if (e == 0) return std::to_string(m);
  if (e == 1) return std::to_string(m * 10);
  char b[16];
  std::snprintf(b, sizeof b, "%de%d", m, e);
  return b;
}

/// Every value of `series` on the x (or y) axis that a log axis can show.
std::vector<double> AxisValues(const std::vector<PlotSeries>& series, bool use_x) {
  std::vector<double> values;
  for (const auto& s : series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (s.x[i] > 0 && s.y[i] > 0 && std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
        values.push_back(use_x ? s.x[i] : s.y[i]);
        if (use_x && i < s.x_min.size() && i < s.x_max.size())
          for (double v : {s.x_min[i], s.x_max[i]})
            if (v > 0 && std::isfinite(v)) values.push_back(v);
      }
  return values;
}

/// Calls tick(m, e, value) for every m 10^e (m = 1..9) within `r`, in increasing order.
template <class F>
void ForEachTick(const LogRange& r, F tick) {
  const int e0 = static_cast<int>(std::floor(std::log10(r.lo))) - 1;
  const int e1 = static_cast<int>(std::ceil(std::log10(r.hi))) + 1;
  for (int e = e0; e <= e1; ++e)
    for (int m = 1; m <= 9; ++m) {
      const double v = m * std::pow(10.0, e);
      if (v >= r.lo * (1 - 1e-9) && v <= r.hi * (1 + 1e-9)) tick(m, e, v);
    }
}

/// Which ticks carry a label: powers of ten always; 2 and 5 times them when the axis spans
/// less than two decades; every tick when it spans less than a factor 3 (few ticks then).
bool Labelled(const LogRange& r, int m) {
  const double span = r.hi / r.lo;
  return m == 1 || (span < 100.0 && (m == 2 || m == 5)) || span < 3.0;
}

/// A marker's half size in pixels (its outline reaches one more).
constexpr int kMarkerRadius = 3;
/// The data's ends sit this far inside the axes, so that a point at either end of a range (a
/// value on a tick) is drawn whole inside them, clear of the axis lines and tick labels.
constexpr int kDataInset = kMarkerRadius + 4;

/// A marker of `shape` centred on (x, y), about 7 pixels across; hollow: its outline only.
void Marker(Image8& im, double cx, double cy, PlotMarker shape, bool hollow, glm::vec3 c) {
  const int x = static_cast<int>(std::lround(cx)), y = static_cast<int>(std::lround(cy));
  constexpr int r = kMarkerRadius;
  const auto inside = [shape](int dx, int dy, int rad) {
    switch (shape) {
      case PlotMarker::kSquare: return std::abs(dx) <= rad && std::abs(dy) <= rad;
      case PlotMarker::kCircle: return dx * dx + dy * dy <= rad * rad + rad;
      case PlotMarker::kTriangle: return dy <= rad && dy >= -rad && 2 * std::abs(dx) <= dy + rad + 1;
      case PlotMarker::kDiamond: return std::abs(dx) + std::abs(dy) <= rad + 1;
    }
    return false;
  };
  for (int dy = -r - 1; dy <= r + 1; ++dy)
    for (int dx = -r - 1; dx <= r + 1; ++dx) {
      if (!inside(dx, dy, r)) continue;
      const bool edge = !inside(dx - 1, dy, r) || !inside(dx + 1, dy, r) || !inside(dx, dy - 1, r) ||
                        !inside(dx, dy + 1, r);
      Put(im, x + dx, y + dy, hollow && !edge ? glm::vec3(1.f) : c);
    }
}

}  // namespace

std::vector<std::pair<double, std::string>> LogAxisLabels(const LogRange& r, double min_gap) {
  const double l0 = std::log10(r.lo), span = std::log10(r.hi) - l0;
  const auto pos = [&](double v) { return span > 0 ? (std::log10(v) - l0) / span : 0.0; };
  std::vector<std::pair<double, std::string>> at;
  ForEachTick(r, [&](int m, int e, double v) {
    if (Labelled(r, m)) at.emplace_back(v, TickLabel(m, e));
  });
  // The two ends, where not crowding a label already there.
  ForEachTick(r, [&](int m, int e, double v) {
    const bool end = std::abs(v / r.lo - 1) < 1e-9 || std::abs(v / r.hi - 1) < 1e-9;
    if (!end || Labelled(r, m)) return;
    for (const auto& [w, text] : at)
      if (std::abs(pos(w) - pos(v)) < min_gap) return;
    at.emplace_back(v, TickLabel(m, e));
  });
  std::sort(at.begin(), at.end());
  return at;
}

Image8 StackVertically(const std::vector<Image8>& panels) {
  int width = 1, height = 0;
  for (const Image8& p : panels) width = std::max(width, p.width), height += p.height;
  Image8 out(width, std::max(height, 1));
  std::fill(out.rgb.begin(), out.rgb.end(), std::uint8_t{255});
  int top = 0;
  for (const Image8& p : panels) {
    for (int y = 0; y < p.height; ++y)
      std::copy_n(p.rgb.begin() + 3 * static_cast<std::size_t>(y) * p.width, 3 * static_cast<std::size_t>(p.width),
                  out.rgb.begin() + 3 * (static_cast<std::size_t>(top + y) * width));
    top += p.height;
  }
  return out;
}

glm::vec3 PlotColor(int i) {
  static const glm::vec3 palette[10] = {{0.12f, 0.47f, 0.71f}, {1.00f, 0.50f, 0.05f}, {0.17f, 0.63f, 0.17f},
                                        {0.84f, 0.15f, 0.16f}, {0.58f, 0.40f, 0.74f}, {0.55f, 0.34f, 0.29f},
                                        {0.89f, 0.47f, 0.76f}, {0.50f, 0.50f, 0.50f}, {0.74f, 0.74f, 0.13f},
                                        {0.09f, 0.75f, 0.81f}};
  return palette[((i % 10) + 10) % 10];
}

LogRange LogAxisRange(const std::vector<double>& values) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values)
    if (v > 0 && std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!std::isfinite(lo)) return {};
  // Largest m 10^e at or below lo; smallest at or above hi (m = 1..9, or 10 = the next decade).
  const auto mantissa_step = [](double v, bool down) {
    const double e = std::pow(10.0, std::floor(std::log10(v)));
    const double m = v / e;  // in [1, 10)
    const double tol = 1e-9;
    return (down ? std::floor(m + tol) : std::ceil(m - tol)) * e;
  };
  LogRange r{mantissa_step(lo, true), mantissa_step(hi, false)};
  if (!(r.hi > r.lo)) {  // one value on a tick: the next tick up
    const double e = std::pow(10.0, std::floor(std::log10(r.lo) + 1e-9));
    r.hi = r.lo + e;
  }
  return r;
}

Image8 DrawLogLogPlot(const std::vector<PlotSeries>& series, const PlotOptions& o) {
  Image8 im(std::max(o.width, 200), std::max(o.height, 150));
  std::fill(im.rgb.begin(), im.rgb.end(), std::uint8_t{255});
  const glm::vec3 black(0.f), grey(0.85f);
  // Plot area: room for tick labels and titles on the left and bottom, legend on the right.
  const int left = 70, top = 36, right = im.width - 200, bottom = im.height - 50;
  const LogRange xr = LogAxisRange(AxisValues(series, true)), yr = LogAxisRange(AxisValues(series, false));
  const double xl = std::log10(xr.lo), xh = std::log10(xr.hi), yl = std::log10(yr.lo), yh = std::log10(yr.hi);
  auto px = [&](double x) {
    return left + kDataInset + (std::log10(x) - xl) / (xh - xl) * (right - left - 2 * kDataInset);
  };
  auto py = [&](double y) {
    return bottom - kDataInset - (std::log10(y) - yl) / (yh - yl) * (bottom - top - 2 * kDataInset);
  };

  // Grid, ticks and tick labels: every m 10^e inside the range, powers of ten darker.
  ForEachTick(xr, [&](int m, int, double v) {
    const int x = static_cast<int>(std::lround(px(v)));
    Rect(im, x, top, x + 1, bottom, m == 1 ? grey : glm::vec3(0.94f));
    Rect(im, x, bottom, x + 1, bottom + (m == 1 ? 7 : 4), black);
  });
  for (const auto& [v, text] : LogAxisLabels(xr, 40.0 / (right - left)))
    DrawText(im, static_cast<int>(std::lround(px(v))) - TextWidth(text, 1) / 2, bottom + 10, text, black);
  ForEachTick(yr, [&](int m, int, double v) {
    const int y = static_cast<int>(std::lround(py(v)));
    Rect(im, left, y, right, y + 1, m == 1 ? grey : glm::vec3(0.94f));
    Rect(im, left - (m == 1 ? 7 : 4), y, left, y + 1, black);
  });
  for (const auto& [v, text] : LogAxisLabels(yr, 14.0 / (bottom - top)))
    DrawText(im, left - 10 - TextWidth(text, 1), static_cast<int>(std::lround(py(v))) - 4, text, black);
  // Axes and titles.
  Rect(im, left, top, left + 1, bottom + 1, black);
  Rect(im, left, bottom, right + 1, bottom + 1, black);
  DrawText(im, (left + right - TextWidth(o.x_label, 2)) / 2, im.height - 24, o.x_label, black, 2);
  DrawText(im, 6, top - 22, o.y_label, black, 2);
  DrawText(im, (left + right - TextWidth(o.title, 2)) / 2 + 60, 6, o.title, black, 2);

  // Series: range bars first, then polylines, then markers on top.
  const auto shown = [](double x, double y) { return x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y); };
  for (const auto& s : series)
    for (std::size_t i = 0; i < std::min({s.x.size(), s.y.size(), s.x_min.size(), s.x_max.size()}); ++i) {
      if (!shown(s.x[i], s.y[i]) || !shown(s.x_min[i], s.y[i]) || !shown(s.x_max[i], s.y[i])) continue;
      const double y = py(s.y[i]), x0 = px(s.x_min[i]), x1 = px(s.x_max[i]);
      const int yi = static_cast<int>(std::lround(y));
      Rect(im, static_cast<int>(std::lround(x0)), yi, static_cast<int>(std::lround(x1)) + 1, yi + 1, s.color);
      for (double xe : {x0, x1}) Rect(im, static_cast<int>(std::lround(xe)), yi - 3, static_cast<int>(std::lround(xe)) + 1, yi + 4, s.color);
    }
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
      x0 = x, y0 = y, have_prev = true;
    }
  }
  for (const auto& s : series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (shown(s.x[i], s.y[i])) Marker(im, px(s.x[i]), py(s.y[i]), s.marker, s.hollow, s.color);

  // Legend: a short line with the marker and the label per series, then the notes.
  int ly = top;
  for (const auto& s : series) {
    if (ly > im.height - 16) break;
    Line(im, right + 12, ly + 4, right + 36, ly + 4, s.color, s.dashed);
    Marker(im, right + 24, ly + 5, s.marker, s.hollow, s.color);
    DrawText(im, right + 42, ly, s.label, black);
    ly += 14;
  }
  ly += 8;
  for (const std::string& note : o.notes) {
    if (ly > im.height - 16) break;
    DrawText(im, right + 12, ly, note, black);
    ly += 14;
  }
  return im;
}

}  // namespace prt
