#pragma once
/// \file
/// A chart of the real SH basis: one row per band l, one sphere per order m (m = -l..l from
/// left to right), each sphere painted with Y_lm on its surface in the diverging false colour
/// (red positive, blue negative, white zero) and lightly shaded so it reads as a ball. Seen
/// from slightly above the equator, +Z (the SH polar axis) up, so the zonal m = 0 functions
/// show their rings and the sectoral |m| = l ones their lobes around the equator.
///
/// The pole is not the scenes' up. The SH polar axis, about which the m = 0 (zonal) functions
/// are symmetric, is world +Z (sh/basis.h), while meshes and cameras are Y-up (camera.h). So on
/// an up-facing floor (normal +Y) the unshadowed transport, T_lm = (A_l / pi) Y_lm(n) with A_l > 0 for
/// l <= 2 (sh/zonal.h), follows the basis at a point of the chart's equator, not at its top:
/// T_2 (l = 1, m = 0, proportional to z) is zero there, and T_6 (l = 2, m = 0, proportional to
/// 3 z^2 - 1) is negative. The chart says so in its
/// second caption line, kBasisPoleCaption.

#include <string>

#include "core/image.h"

namespace prt {

/// The caption line that names the SH pole on the chart.
extern const char* const kBasisPoleCaption;

/// The chart for bands 0..lmax with spheres of `cell` pixels; labels and two caption lines
/// included (the image is widened, if needed, so the captions fit).
Image8 DrawBasisChart(int lmax, int cell);

}  // namespace prt
