#pragma once
/// \file
/// A chart of the real SH basis: one row per band l, one sphere per order m (m = -l..l from
/// left to right), each sphere painted with Y_lm on its surface in the diverging false colour
/// (red positive, blue negative, white zero) and lightly shaded so it reads as a ball. Seen
/// from slightly above the equator, +Z (the SH polar axis) up, so the zonal m = 0 functions
/// show their rings and the sectoral |m| = l ones their lobes around the equator.

#include "core/image.h"

namespace prt {

/// The chart for bands 0..lmax with spheres of `cell` pixels; labels included.
Image8 DrawBasisChart(int lmax, int cell);

}  // namespace prt
