#pragma once
/// \file
/// Golden-image checks. A golden is a committed PNG under tests/golden/. On a mismatch the test
/// writes actual, expected and an amplified difference image to out/test-failures/ and prints
/// their paths. `PRT_UPDATE_GOLDEN=1` (re)writes the goldens instead; a missing golden fails with
/// that hint.

#include <string>

#include "core/image.h"

namespace prt::test {

/// Limits of an acceptable difference, as in `prt diff`.
struct GoldenLimits {
  int max_abs = 2;          ///< largest channel difference (0..255)
  double mean_abs = 0.05;   ///< mean channel difference
};

/// Checks `actual` against tests/golden/<name>.png (a doctest CHECK with a message).
void CheckGolden(const std::string& name, const Image8& actual, const GoldenLimits& limits = {});

}  // namespace prt::test
