#pragma once
/// \file
/// A diffuse (albedo) texture: linear RGB reflectance in [0, 1] with its mip pyramid, sampled
/// with trilinear filtering so that a distant textured mesh does not shimmer from frame to frame.
///
/// Coordinates. OBJ texture coordinates (u, v) have v = 0 at the bottom of the picture [1]; the
/// image's row 0 is its top, so texel row = (1 - v) * height. Coordinates outside [0, 1] repeat
/// (the OBJ default, `-clamp off` [1]).
///
/// Mip levels [2]. Level 0 is the image; level k + 1 halves each side (rounding up, at least 1)
/// and each of its texels is the mean of the 2 x 2 texels below it (an odd last row or column
/// repeats the edge texel). Filtering is linear in the reflectance: the pyramid is built after
/// the sRGB decoding, never on the 8-bit codes.
///
/// Sampling. Bilinear within a level between the four nearest texel centres; a level of detail
/// lod = log2(footprint in level-0 texels) blends the two nearest levels (lod <= 0 is level 0,
/// magnified bilinearly; above the last level the 1 x 1 mean of the texture).
///
/// References
///  [1] Wavefront, "MTL material format (Lightwave, OBJ)", Alias|Wavefront, 1995: map_Kd, vt.
///  [2] L. Williams, "Pyramidal Parametrics", SIGGRAPH 1983.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/image.h"

namespace prt {

class Texture {
 public:
  /// Builds the pyramid of `image` (linear RGB, every channel in [0, 1]); `name` says where it came
  /// from in messages (a path, or a material's Kd).
  Texture(ImageF image, std::string name);
  /// A 1 x 1 texture of one colour (a material without map_Kd in a textured mesh).
  static Texture Solid(const glm::vec3& albedo, std::string name);

  /// The filtered albedo at (u, v) for a footprint of 2^lod level-0 texels.
  glm::vec3 Sample(glm::vec2 uv, float lod) const;
  /// The level of detail of a pixel whose texture coordinates change by `duv_dx` and `duv_dy`
  /// from one pixel to the next across and down: log2 of the longer of the two steps in level-0
  /// texels (the isotropic approximation of [2]).
  float LodOf(glm::vec2 duv_dx, glm::vec2 duv_dy) const;

  int width() const { return levels_.front().width; }
  int height() const { return levels_.front().height; }
  int level_count() const { return static_cast<int>(levels_.size()); }
  const ImageF& level(int k) const { return levels_[static_cast<std::size_t>(k)]; }
  /// The mean albedo of the whole texture (the last level's one texel).
  const glm::vec3& mean() const { return levels_.back().pixels.front(); }
  /// True when every texel has R = G = B.
  bool grey() const { return grey_; }
  const std::string& name() const { return name_; }
  /// FNV-1a of the size and level-0 texels (bits): a cache key's share of the texture.
  std::uint64_t content_hash() const { return hash_; }

 private:
  glm::vec3 Bilinear(const ImageF& level, glm::vec2 uv) const;

  std::vector<ImageF> levels_;
  std::string name_;
  bool grey_ = true;
  std::uint64_t hash_ = 0;
};

}  // namespace prt
