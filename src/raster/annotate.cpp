#include "raster/annotate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/common.hpp>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace prt {
namespace {

void FillRect(Image8& image, int x0, int y0, int x1, int y1, glm::vec3 color) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c)
        image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x) + c] =
            static_cast<std::uint8_t>(std::lround(std::clamp(color[c], 0.0f, 1.0f) * 255.0f));
}

// The legend panel takes at most this fraction of the image width while the text can shrink.
constexpr double kMaxLegendWidth = 0.5;

// Quads stb_easy_font draws for one character at most ('X': 11, counted over all printable
// ASCII), each 4 vertices of 16 bytes. stb's own "about 270 bytes a character" is an average:
// a buffer sized by it cut the last stroke off a lone "8" (the lower left one), which then read
// as a 9 on the glossy plot's lmax axis.
constexpr std::size_t kMaxQuadsPerChar = 11, kQuadBytes = 64;

// The ink rectangles of `text` at `scale`, relative to its top-left corner (stb_easy_font's
// quads have whole-pixel corners).
std::vector<PixelRect> Glyphs(const std::string& text, int scale) {
  std::vector<char> buffer(text.begin(), text.end());
  buffer.push_back('\0');
  std::vector<unsigned char> quads((text.size() + 1) * kMaxQuadsPerChar * kQuadBytes);
  unsigned char rgba[4] = {255, 255, 255, 255};
  const int n = stb_easy_font_print(0, 0, buffer.data(), rgba, quads.data(), static_cast<int>(quads.size()));
  std::vector<PixelRect> rects;
  rects.reserve(static_cast<std::size_t>(std::max(n, 0)));
  const float f = static_cast<float>(scale);
  for (int q = 0; q < n; ++q) {
    const float* v = reinterpret_cast<const float*>(quads.data() + q * 64);  // 4 vertices of 16 bytes
    rects.push_back({static_cast<int>(v[0] * f), static_cast<int>(v[1] * f), static_cast<int>(v[8] * f),
                     static_cast<int>(v[9] * f)});
  }
  return rects;
}

// An end label of the legend.
std::string Label(double value) {
  char label[32];
  std::snprintf(label, sizeof label, "%+.3g", value);
  return label;
}

}  // namespace

glm::vec3 DivergingColor(double t) {
  t = std::clamp(t, -1.0, 1.0);
  const glm::vec3 white(0.97f, 0.97f, 0.97f), blue(0.23f, 0.30f, 0.75f), red(0.71f, 0.02f, 0.15f);
  const float s = static_cast<float>(std::abs(t));
  return t < 0 ? white + (blue - white) * s : white + (red - white) * s;
}

void DrawText(Image8& image, int x, int y, const std::string& text, glm::vec3 color, int scale) {
  for (const PixelRect& q : Glyphs(text, scale))
    FillRect(image, x + q.x0, y + q.y0, x + q.x1, y + q.y1, color);
}

glm::ivec2 TextSize(const std::string& text, int scale) {
  glm::ivec2 size(0);
  for (const PixelRect& q : Glyphs(text, scale)) size = glm::max(size, glm::ivec2(q.x1, q.y1));
  return size;
}

std::optional<LegendLayout> LayoutDivergingLegend(int width, int height, double max_abs,
                                                  const std::string& title) {
  const std::string texts[3] = {Label(max_abs), "0", Label(-max_abs)};
  // Text scale from the height: 1 at 480, 2 at 1080 (height / 540, rounded).
  for (int s = std::max(1, (height + 270) / 540); s >= 1; --s) {
    LegendLayout l;
    l.text_scale = s;
    // Margin to the image edges, padding of the panel, gap between bar and labels.
    const int margin = 6 * s, pad = 2 * s, gap = 3 * s;
    glm::ivec2 label[3];
    int column = 0, label_h = 0;
    for (int i = 0; i < 3; ++i) {
      label[i] = TextSize(texts[i], s);
      column = std::max(column, label[i].x), label_h = std::max(label_h, label[i].y);
    }
    const glm::ivec2 title_size = TextSize(title, s);
    const int bar_w = std::max(6 * s, width / 40);
    // Right to left: labels against the right margin, the bar, the title above both.
    const int right = width - margin;
    l.bar.x1 = right - column - gap, l.bar.x0 = l.bar.x1 - bar_w;
    const int title_x = std::min(l.bar.x0, right - title_size.x);
    l.title = {title_x, margin, title_x + title_size.x, margin + title_size.y};
    // Top to bottom: the title, then the bar, whose end rows carry the centres of the end labels.
    l.bar.y0 = l.title.y1 + gap + (label_h + 1) / 2;
    l.bar.y1 = height - margin - (label_h + 1) / 2;
    const int rows[3] = {l.bar.y0, (l.bar.y0 + l.bar.y1 - 1) / 2, l.bar.y1 - 1};
    for (int i = 0; i < 3; ++i) {
      const int y = rows[i] - label[i].y / 2;
      l.labels[i] = {l.bar.x1 + gap, y, l.bar.x1 + gap + label[i].x, y + label[i].y};
    }
    l.panel = {std::min(l.bar.x0, title_x) - pad, margin - pad, width, height - margin + pad};
    // Fits: inside the image, a bar tall enough to keep the labels apart, and at most
    // kMaxLegendWidth of the width unless the text is already at its smallest.
    const bool inside = l.panel.x0 >= 0 && l.panel.y0 >= 0 && l.panel.y1 <= height;
    const bool tall = l.bar.y1 - l.bar.y0 >= std::max(20, 2 * (label_h + s));
    const bool narrow = width - l.panel.x0 <= kMaxLegendWidth * width || s == 1;
    if (inside && tall && narrow) return l;
  }
  return std::nullopt;
}

void DrawDivergingLegend(Image8& image, double max_abs, const std::string& title) {
  const std::optional<LegendLayout> l = LayoutDivergingLegend(image.width, image.height, max_abs, title);
  if (!l) return;
  const PixelRect& p = l->panel;
  FillRect(image, p.x0, p.y0, p.x1, p.y1, glm::vec3(0.1f));
  // The bar: +1 at its top row, -1 at its bottom row.
  const int rows = l->bar.y1 - l->bar.y0;
  for (int y = l->bar.y0; y < l->bar.y1; ++y) {
    const double t = 1.0 - 2.0 * (y - l->bar.y0) / double(std::max(rows - 1, 1));
    FillRect(image, l->bar.x0, y, l->bar.x1, y + 1, DivergingColor(t));
  }
  const std::string texts[3] = {Label(max_abs), "0", Label(-max_abs)};
  for (int i = 0; i < 3; ++i)
    DrawText(image, l->labels[i].x0, l->labels[i].y0, texts[i], glm::vec3(1.0f), l->text_scale);
  DrawText(image, l->title.x0, l->title.y0, title, glm::vec3(1.0f), l->text_scale);
}

}  // namespace prt
