#pragma once
/// \file
/// Golden-image checks. A golden is a committed PNG under tests/golden/. On a mismatch the test
/// writes actual, expected and an amplified difference image to out/test-failures/ and prints
/// their paths. `PRT_UPDATE_GOLDEN=1` (re)writes the goldens instead; a missing golden fails with
/// that hint.

#include <string>

#include "core/image.h"
#include "render/render_options.h"

namespace prt::test {

/// Limits of an acceptable difference, as in `prt diff`.
struct GoldenLimits {
  int max_abs = 2;          ///< largest channel difference (0..255)
  double mean_abs = 0.05;   ///< mean channel difference
};

/// The frame the goldens are drawn with: 96 x 96, the plain sRGB curve at exposure 0 without
/// supersampling, so a change of render's defaults (tone curve, automatic exposure,
/// supersampling) does not move them: they test shading and rasterizing. The camera looks
/// from (0, 3, 7) at (0, 0.8, 0) with a 40-degree field of view.
RenderOptions GoldenFrame();

/// Checks `actual` against tests/golden/<name>.png (a doctest CHECK with a message).
void CheckGolden(const std::string& name, const Image8& actual, const GoldenLimits& limits = {});

}  // namespace prt::test
