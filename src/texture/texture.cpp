#include "texture/texture.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/hash.h"

namespace prt {
namespace {

// The next level: each side halved rounding up, each texel the mean of its 2 x 2 parents (the
// edge texel repeated where an odd side has no partner).
ImageF HalfLevel(const ImageF& a) {
  ImageF b(std::max(1, (a.width + 1) / 2), std::max(1, (a.height + 1) / 2));
  for (int y = 0; y < b.height; ++y) {
    const int y0 = std::min(2 * y, a.height - 1), y1 = std::min(2 * y + 1, a.height - 1);
    for (int x = 0; x < b.width; ++x) {
      const int x0 = std::min(2 * x, a.width - 1), x1 = std::min(2 * x + 1, a.width - 1);
      b.at(x, y) = 0.25f * (a.at(x0, y0) + a.at(x1, y0) + a.at(x0, y1) + a.at(x1, y1));
    }
  }
  return b;
}

// i modulo n, in [0, n).
int Wrap(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace

Texture::Texture(ImageF image, std::string name) : name_(std::move(name)) {
  hash_ = Fnv1a(&image.width, sizeof image.width);
  hash_ = Fnv1a(&image.height, sizeof image.height, hash_);
  hash_ = Fnv1a(image.pixels.data(), image.pixels.size() * sizeof(glm::vec3), hash_);
  for (const glm::vec3& p : image.pixels)
    if (p.x != p.y || p.y != p.z) {
      grey_ = false;
      break;
    }
  levels_.push_back(std::move(image));
  while (levels_.back().width > 1 || levels_.back().height > 1) levels_.push_back(HalfLevel(levels_.back()));
}

Texture Texture::Solid(const glm::vec3& albedo, std::string name) {
  ImageF one(1, 1);
  one.pixels[0] = albedo;
  return Texture(std::move(one), std::move(name));
}

glm::vec3 Texture::Bilinear(const ImageF& level, glm::vec2 uv) const {
  // Texel centres sit at (i + 1/2) / width; v runs up, rows run down.
  const float x = uv.x * static_cast<float>(level.width) - 0.5f;
  const float y = (1.f - uv.y) * static_cast<float>(level.height) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  const int x0 = Wrap(static_cast<int>(fx), level.width), x1 = Wrap(static_cast<int>(fx) + 1, level.width);
  const int y0 = Wrap(static_cast<int>(fy), level.height), y1 = Wrap(static_cast<int>(fy) + 1, level.height);
  const glm::vec3 top = level.at(x0, y0) + tx * (level.at(x1, y0) - level.at(x0, y0));
  const glm::vec3 bottom = level.at(x0, y1) + tx * (level.at(x1, y1) - level.at(x0, y1));
  return top + ty * (bottom - top);
}

glm::vec3 Texture::Sample(glm::vec2 uv, float lod) const {
  // Coordinates far outside [0, 1] lose float precision in x * width: bring them back first.
  uv -= glm::vec2(std::floor(uv.x), std::floor(uv.y));
  const int last = level_count() - 1;
  if (!(lod > 0.f)) return Bilinear(levels_.front(), uv);  // NaN lod too: the finest level
  if (lod >= static_cast<float>(last)) return Bilinear(levels_.back(), uv);
  const int k = static_cast<int>(lod);
  const float t = lod - static_cast<float>(k);
  const glm::vec3 fine = Bilinear(levels_[k], uv);
  return fine + t * (Bilinear(levels_[k + 1], uv) - fine);
}

float Texture::LodOf(glm::vec2 duv_dx, glm::vec2 duv_dy) const {
  const glm::vec2 size(static_cast<float>(width()), static_cast<float>(height()));
  const glm::vec2 a = duv_dx * size, b = duv_dy * size;
  const float longer_sq = std::max(a.x * a.x + a.y * a.y, b.x * b.x + b.y * b.y);
  return longer_sq > 1.f ? 0.5f * std::log2(longer_sq) : 0.f;
}

}  // namespace prt
