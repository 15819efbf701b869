#include "texture/albedo_limit.h"

#include <algorithm>
#include <utility>

#include <glm/common.hpp>

namespace prt {

glm::vec3 LimitAlbedo(const glm::vec3& albedo, float limit) {
  const float m = std::max({albedo.x, albedo.y, albedo.z});
  return m <= limit ? albedo : glm::min(albedo * (limit / m), glm::vec3(limit));
}

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
    if (!above(p)) continue;
    p = LimitAlbedo(p, limit);
    ++scaled;
  }
  return Texture(std::move(image), texture.name());
}

}  // namespace prt
