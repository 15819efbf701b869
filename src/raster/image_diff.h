#pragma once
/// \file
/// Comparing two 8-bit images: the metrics `prt diff` prints and golden-image tests check, and
/// an amplified difference picture for eyes.
///
/// All metrics are over the 3 * width * height channel values on the 0..255 scale.
///   mean_abs = mean |a - b|,  rmse = sqrt(mean (a - b)^2),
///   psnr = 20 log10(255 / rmse) dB [1] (infinite for identical images).
///
/// References:
///  [1] Z. Wang, A. Bovik, "Mean squared error: love it or leave it?", IEEE Signal Processing
///      Magazine 26(1), 2009 (the PSNR definition for 8-bit images).

#include <cstddef>
#include <string>

#include "core/image.h"

namespace prt {

/// How far two images of the same size are apart.
struct DiffMetrics {
  int max_abs = 0;                   ///< largest channel difference, 0..255
  double mean_abs = 0.0;             ///< mean channel difference, 0..255
  double rmse = 0.0;                 ///< root mean square channel difference, 0..255
  double psnr = 0.0;                 ///< dB; +infinity when identical
  std::size_t differing_pixels = 0;  ///< pixels with any channel different
  std::size_t pixels_over_one = 0;   ///< pixels with a channel more than one level apart
};

/// Metrics of a against b. Throws Error when the sizes differ or a buffer does not hold
/// 3 * width * height bytes.
DiffMetrics CompareImages(const Image8& a, const Image8& b);

/// Per channel: 0 where equal, else 64 + 191 * |a - b| / max_abs, so that the smallest
/// difference is plainly visible and the largest is full brightness. Same preconditions.
Image8 AmplifiedDifference(const Image8& a, const Image8& b);

/// `max_abs=<n> mean_abs=<x> rmse=<x> psnr=<dB or inf> differing_pixels=<n>` (no newline).
std::string FormatDiffMetrics(const DiffMetrics& metrics);

}  // namespace prt
