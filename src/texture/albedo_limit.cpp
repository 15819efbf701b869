#include "texture/albedo_limit.h"

#include <algorithm>
#include <utility>

#include <glm/common.hpp>

namespace prt {

std::optional<Texture> LimitAlbedo(const Texture& texture, float limit, std::size_t& scaled) {
  const auto above = [limit](const glm::vec3& p) { return std::max({p.x, p.y, p.z}) > limit; };
  const auto& texels = texture.level(0).pixels;
  if (std::none_of(texels.begin(), texels.end(), above)) {
    scaled = 0;
    return std::nullopt;
  }
  ImageF image = texture.level(0);
  scaled = 0;
  for (glm::vec3& p : image.pixels) {
    const float m = std::max({p.x, p.y, p.z});
    if (m <= limit) continue;
    // Scaled, then clipped: the product can round a hair above the limit.
    p = glm::min(p * (limit / m), glm::vec3(limit));
    ++scaled;
  }
  return Texture(std::move(image), texture.name());
}

}  // namespace prt
