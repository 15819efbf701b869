#pragma once
// Helpers for the environment tests: environments sampled from a function, in memory.

#include <functional>
#include <memory>

#include "env/cubemap.h"
#include "env/equirect.h"

namespace prt::test {

using RadianceFn = std::function<glm::dvec3(const glm::dvec3&)>;

inline std::unique_ptr<CubemapEnvironment> CubemapFrom(const RadianceFn& f, int size,
                                                       CubeLayout layout = CubeLayout::kStandard) {
  return CubemapFromFunction(f, size, layout);
}

inline std::unique_ptr<EquirectEnvironment> EquirectFrom(const RadianceFn& f, int width, int height) {
  return EquirectFromFunction(f, width, height);
}

}  // namespace prt::test
