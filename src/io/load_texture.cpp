#include "io/load_texture.h"

#include <cmath>

#include "core/error.h"
#include "io/image_load.h"

namespace prt {

Texture LoadTexture(const std::string& path, std::vector<std::string>& warnings) {
  ImageF image = LoadImageLinear(path, LdrDecode::kSrgb);
  std::size_t above = 0, below = 0;
  for (glm::vec3& p : image.pixels)
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(p[c]))
        throw Error(path + ": a texel is NaN or infinite (expected a reflectance from 0 to 1 in every texel)");
      if (p[c] > 1.f) p[c] = 1.f, ++above;
      if (p[c] < 0.f) p[c] = 0.f, ++below;
    }
  if (above + below > 0)
    warnings.push_back(path + ": " + std::to_string(above + below) +
                       " texel channels outside [0, 1] clamped (a texture is a reflectance: 1 reflects all the light)");
  return Texture(std::move(image), path);
}

}  // namespace prt
