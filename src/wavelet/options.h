#pragma once
/// \file
/// The wavelet basis's own options (docs/CLI.md: --cube-size, --wavelet-terms, --light-terms):
/// how its transport is sampled and truncated, and how much of each frame's light is kept.
/// The defaults are measured in transport.h.

#include "wavelet/selection.h"

namespace prt {

/// How the wavelet transport is sampled and truncated.
struct WaveletOptions {
  int face_size = 32;   ///< F: the cube's faces are F x F texels
  int budget = 512;     ///< coefficients kept per vertex, the 6 faces' means among them
  int split = 2;        ///< rays per texel: split x split
  /// Which details of what the SH base leaves a vertex keeps: with the smooth part in SH,
  /// magnitude (the least L2 error) beats area at every budget measured (transport.h).
  Selection selection = Selection::kMagnitude;
  Selection light_selection = Selection::kArea;  ///< which light terms --light-terms keeps (area: Ng et al. 2003, sec. 5.2)
  int light_terms = 0;  ///< light coefficients kept per frame (0: all)
  int base_lmax = 4;    ///< the smooth part of the direct transport in SH up to this band (-1: none)
};

/// The largest face size: 6 F^2 indices must fit 16 bits.
inline constexpr int kMaxWaveletFace = 64;

}  // namespace prt
