#pragma once
/// \file
/// The Haar wavelets on a cube behind the basis interface (basis/basis.h): each vertex's direct
/// light in wavelets (all-frequency: sharp shadows of small bright sources), its bounces in SH.
/// Its own options are --cube-size, --wavelet-terms and --light-terms (wavelet/options.h), read
/// here; its transport comes from wavelet/scene_wavelets.h, its frame light from
/// wavelet/frame_light.h, its study for `prt report --basis wavelet` from wavelet/study.h. It
/// writes no course files, takes no glossy material and keeps no SH transfer per vertex to show.

#include "basis/basis.h"
#include "wavelet/options.h"

namespace prt {

/// The wavelet basis (one instance).
const Basis& WaveletBasis();

/// The wavelet options in `settings` (WaveletBasis's own).
const WaveletOptions& WaveletOptionsOf(const BasisSettings& settings);

}  // namespace prt
