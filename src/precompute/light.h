#pragma once
/// \file
/// Projecting an environment onto real SH: L_k = integral of L(w) Y_k(w) dw, bands 0..lmax.
///
/// The integral is the environment's own quadrature (exact texel solid angles for images, a
/// Gauss rule for procedural skies) plus its analytic terms (environment.h). Sums are taken in
/// three levels (texels of a row, rows of a chunk, chunks in order), so a 4K map's 33 million
/// terms lose no more than about 1e-15 relative, and the chunking depends only on the map, so
/// the result is bit-identical for any thread count.

#include "env/environment.h"
#include "sh/coeffs.h"
#include "sh/window.h"

namespace prt {

/// SH coefficients (linear RGB) of the radiance of `env`, bands 0..lmax.
ShRgb ProjectLight(const Environment& env, int lmax);

}  // namespace prt
