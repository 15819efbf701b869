#include "raster/basis_chart.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "raster/annotate.h"
#include "sh/basis.h"

namespace prt {

const char* const kBasisPoleCaption = "pole (m = 0 axis): world +Z; scenes are Y-up";

namespace {
const char* const kTitle = "real SH basis: red > 0, blue < 0, +Z up";
}  // namespace

Image8 DrawBasisChart(int lmax, int cell) {
  // Two caption lines of 12 font pixels above the grid.
  const int columns = 2 * lmax + 1, label_w = 40, label_h = 30;
  const int caption_w = 8 + std::max(TextSize(kTitle).x, TextSize(kBasisPoleCaption).x);
  Image8 image(std::max(label_w + columns * cell, caption_w), label_h + (lmax + 1) * cell);
  std::fill(image.rgb.begin(), image.rgb.end(), std::uint8_t(24));
  // View frame: looking at the sphere from direction `eye` (unit), +Z up on screen.
  const glm::dvec3 eye = glm::normalize(glm::dvec3(0.8, -1.0, 0.45));
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), eye));
  const glm::dvec3 up = glm::cross(eye, right);
  const glm::dvec3 light_dir = glm::normalize(eye + 0.6 * up - 0.3 * right);
  std::vector<double> y(CoeffCount(lmax));

  for (int l = 0; l <= lmax; ++l) {
    // Normalise each band by its largest value, sqrt((2l+1)/(4 pi)) (reached at the poles by m = 0).
    const double band_max = std::sqrt((2.0 * l + 1.0) / (4.0 * kPi));
    for (int m = -l; m <= l; ++m) {
      const int cx = label_w + (m + lmax) * cell + cell / 2, cy = label_h + l * cell + cell / 2;
      const double radius = 0.45 * cell;
      for (int py = cy - cell / 2; py < cy + cell / 2; ++py)
        for (int px = cx - cell / 2; px < cx + cell / 2; ++px) {
          const double sx = (px + 0.5 - cx) / radius, sy = (cy - py - 0.5) / radius;
          const double r2 = sx * sx + sy * sy;
          if (r2 >= 1.0) continue;
          // The visible point of the unit sphere under this pixel (orthographic view).
          const glm::dvec3 d = sx * right + sy * up + std::sqrt(1.0 - r2) * eye;
          EvalBasis(l, d, y.data());
          const glm::vec3 base = DivergingColor(y[ShIndex(l, m)] / band_max);
          const float shade = static_cast<float>(0.55 + 0.45 * std::max(0.0, glm::dot(d, light_dir)));
          for (int c = 0; c < 3; ++c)
            image.rgb[3 * (static_cast<std::size_t>(py) * image.width + px) + c] =
                static_cast<std::uint8_t>(std::lround(std::clamp(base[c] * shade, 0.0f, 1.0f) * 255.0f));
        }
      DrawText(image, cx - 10, cy + cell / 2 - 10, "m=" + std::to_string(m), glm::vec3(0.7f));
    }
    DrawText(image, 4, label_h + l * cell + cell / 2 - 4, "l=" + std::to_string(l), glm::vec3(0.9f));
  }
  DrawText(image, 4, 4, kTitle, glm::vec3(0.9f));
  DrawText(image, 4, 16, kBasisPoleCaption, glm::vec3(0.9f));
  return image;
}

}  // namespace prt
