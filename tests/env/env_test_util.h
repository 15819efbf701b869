#pragma once
// Helpers for the environment tests: cubemaps and equirects filled from a function, in memory.

#include <array>
#include <cmath>
#include <functional>
#include <memory>

#include <glm/geometric.hpp>

#include "env/cube_faces.h"
#include "env/cubemap.h"
#include "env/equirect.h"

namespace prt::test {

using RadianceFn = std::function<glm::dvec3(const glm::dvec3&)>;

/// A size^2 cubemap whose texel centres hold f(direction), standard layout.
inline std::unique_ptr<CubemapEnvironment> CubemapFrom(const RadianceFn& f, int size,
                                                       CubeLayout layout = CubeLayout::kStandard) {
  std::array<ImageF, 6> faces;
  const auto& frames = FaceFrames(layout);
  for (int k = 0; k < 6; ++k) {
    faces[k] = ImageF(size, size);
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        const double s = -1.0 + (col + 0.5) * 2.0 / size, t = -1.0 + (row + 0.5) * 2.0 / size;
        const glm::dvec3 d = glm::normalize(frames[k].n + s * frames[k].u + t * frames[k].v);
        faces[k].at(col, row) = glm::vec3(f(d));
      }
  }
  return std::make_unique<CubemapEnvironment>(std::move(faces), layout, "test cubemap");
}

/// A width x height equirect whose texel centres hold f(direction).
inline std::unique_ptr<EquirectEnvironment> EquirectFrom(const RadianceFn& f, int width, int height) {
  ImageF image(width, height);
  const double pi = 3.14159265358979323846;
  for (int row = 0; row < height; ++row)
    for (int col = 0; col < width; ++col) {
      const double theta = pi * (row + 0.5) / height, phi = 2 * pi * (col + 0.5) / width - pi;
      const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
      image.at(col, row) = glm::vec3(f(d));
    }
  return std::make_unique<EquirectEnvironment>(std::move(image), "test equirect");
}

}  // namespace prt::test
