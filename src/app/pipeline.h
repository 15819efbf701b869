#pragma once
/// \file
/// The stages of prt as the commands chain them (docs/ARCHITECTURE.md):
///
///   args -> SceneOptions -> LoadEnvironment -> Environment -> ProjectLight(lmax) -> light SH
///
/// Each stage is a function from const inputs to a returned value and reports what it did (and
/// what it left out, and why) on the run summary.

#include <memory>

#include "app/scene_options.h"
#include "env/environment.h"
#include "sh/coeffs.h"

namespace prt {

/// The environment named by the options, described on the run summary.
std::unique_ptr<Environment> LoadSceneEnvironment(const SceneOptions& options);

/// The environment's SH coefficients for bands 0..options.lmax, windowed as asked
/// (`auto` picks the mildest window that keeps the reconstruction non-negative and says why).
ShRgb ComputeLight(const Environment& env, const SceneOptions& options);

}  // namespace prt
