#pragma once
/// \file
/// The stability cases about awkward inputs (see stability.h):
///   - extreme meshes: zero-area, sliver and duplicated triangles, vertex normals exactly on the
///     axes and grazing ones: every transport value finite, and within the bounds any diffuse
///     transfer obeys (0 <= T_00 <= Y_00, the unshadowed value);
///   - albedo 0.99 in a deep open well under constant light, 64 bounces: the series converges and
///     respects the energy bound of a furnace, radiance <= albedo (incoming radiance never
///     exceeds 1 anywhere, so reflected radiance never exceeds albedo * 1) [1];
///   - NaN, +-Inf, negative and 1e30 texels: sanitised, and no NaN reaches the light coefficients.
///
/// References
/// [1] Kajiya, "The Rendering Equation", SIGGRAPH 1986 (the Neumann series converges for albedo < 1).

#include <vector>

#include "app/stability.h"

namespace prt {

void ExtremeMeshes(std::vector<StabilityCase>& out);
void DeepConcavity(std::vector<StabilityCase>& out);
void BadTexels(std::vector<StabilityCase>& out);

}  // namespace prt
