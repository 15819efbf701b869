#pragma once
/// \file
/// The energy rule of a textured mesh under a glossy coat, per texel.
///
/// A Phong coat of weight KS reflects at most KS of the light at normal view, the diffuse base
/// at most its albedo a (material/material.h): the surface keeps energy when a + KS <= 1 in every
/// channel. A painted texture has texels up to 1 (white paper, highlights painted in), so the
/// rule cannot be asked of the whole mesh without refusing every such model; it is kept per
/// texel instead: a texel whose largest channel m exceeds 1 - KS is scaled by (1 - KS) / m in
/// all three channels, so its hue and saturation stay and only its brightness drops to the
/// limit; texels at or below the limit are untouched. The mip pyramid is rebuilt from the scaled
/// texels (texture/texture.h), so every filtered value obeys the limit too.

#include <cstddef>
#include <optional>

#include <glm/vec3.hpp>

#include "texture/texture.h"

namespace prt {

/// One albedo under the rule: scaled by limit / m when its largest channel m exceeds `limit`
/// (then clipped to it, as the product can round a hair above), else unchanged. The report
/// scene applies it per vertex.
glm::vec3 LimitAlbedo(const glm::vec3& albedo, float limit);

/// `texture` with every texel's largest channel at most `limit` (the rule above); `scaled` is
/// set to the number of level-0 texels that were scaled. The name stays the original's. Empty
/// when no texel is above the limit: then the texture serves as it is, and no pyramid is rebuilt.
std::optional<Texture> LimitAlbedo(const Texture& texture, float limit, std::size_t& scaled);

}  // namespace prt
