#pragma once
/// \file
/// Plain image containers shared by the loaders, the environments and the rasterizer.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace prt {

/// Linear RGB radiance, row-major, row 0 at the top of the picture.
struct ImageF {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> pixels;  ///< width * height

  ImageF() = default;
  ImageF(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h) {}
  glm::vec3& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const glm::vec3& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// 8-bit RGB, row-major, row 0 at the top: what PNG frames hold.
struct Image8 {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< 3 * width * height

  Image8() = default;
  Image8(int w, int h) : width(w), height(h), rgb(3 * static_cast<std::size_t>(w) * h, 0) {}
};

}  // namespace prt
