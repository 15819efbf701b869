#pragma once
/// \file
/// Luminance of linear sRGB / Rec. 709 colour: Y = 0.2126 R + 0.7152 G + 0.0722 B, the weights
/// of ITU-R BT.709-6, item 3.2 (how the eye weighs the three primaries).

#include <glm/vec3.hpp>

namespace prt {

/// The Rec. 709 luminance weights of R, G and B.
inline constexpr double kLuminanceWeights[3] = {0.2126, 0.7152, 0.0722};

/// Y of a linear Rec. 709 colour.
inline double Luminance(const glm::dvec3& c) {
  return kLuminanceWeights[0] * c.x + kLuminanceWeights[1] * c.y + kLuminanceWeights[2] * c.z;
}

}  // namespace prt
