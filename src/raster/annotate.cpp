#include "raster/annotate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

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

}  // namespace

glm::vec3 DivergingColor(double t) {
  t = std::clamp(t, -1.0, 1.0);
  const glm::vec3 white(0.97f, 0.97f, 0.97f), blue(0.23f, 0.30f, 0.75f), red(0.71f, 0.02f, 0.15f);
  const float s = static_cast<float>(std::abs(t));
  return t < 0 ? white + (blue - white) * s : white + (red - white) * s;
}

void DrawText(Image8& image, int x, int y, const std::string& text, glm::vec3 color, int scale) {
  std::vector<char> buffer(text.begin(), text.end());
  buffer.push_back('\0');
  std::vector<unsigned char> quads(text.size() * 270 + 256);  // stb: about 270 bytes a character
  unsigned char rgba[4] = {255, 255, 255, 255};
  const int n = stb_easy_font_print(0, 0, buffer.data(), rgba, quads.data(), static_cast<int>(quads.size()));
  for (int q = 0; q < n; ++q) {
    const float* v = reinterpret_cast<const float*>(quads.data() + q * 64);  // 4 vertices of 16 bytes
    const float qx0 = v[0], qy0 = v[1], qx1 = v[8], qy1 = v[9];
    const float f = static_cast<float>(scale);
    FillRect(image, x + static_cast<int>(qx0 * f), y + static_cast<int>(qy0 * f), x + static_cast<int>(qx1 * f),
             y + static_cast<int>(qy1 * f), color);
  }
}

void DrawDivergingLegend(Image8& image, double max_abs, const std::string& title) {
  const int bar_w = std::max(6, image.width / 40), margin = 6;
  const int top = margin + 14, bottom = image.height - margin - 14;
  const int x0 = image.width - margin - bar_w - 44;
  if (bottom - top < 20 || x0 < 0) return;
  FillRect(image, x0 - 2, top - 16, image.width, bottom + 14, glm::vec3(0.1f));
  for (int y = top; y < bottom; ++y) {
    const double t = 1.0 - 2.0 * (y - top) / double(bottom - top - 1);
    FillRect(image, x0, y, x0 + bar_w, y + 1, DivergingColor(t));
  }
  char label[32];
  std::snprintf(label, sizeof label, "%+.3g", max_abs);
  DrawText(image, x0 + bar_w + 3, top - 3, label, glm::vec3(1.0f));
  DrawText(image, x0 + bar_w + 3, (top + bottom) / 2 - 3, "0", glm::vec3(1.0f));
  std::snprintf(label, sizeof label, "%+.3g", -max_abs);
  DrawText(image, x0 + bar_w + 3, bottom - 6, label, glm::vec3(1.0f));
  DrawText(image, x0, top - 13, title, glm::vec3(1.0f));
}

}  // namespace prt
