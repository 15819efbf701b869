#pragma once
/// \file
/// The stages of prt as the commands chain them (docs/ARCHITECTURE.md):
///
///   args -> SceneOptions -> LoadEnvironment -> Environment -> ProjectLight(lmax) -> light SH
///                           LoadSceneMesh -> Mesh -> ComputeTransport (or the cache) -> Transport
///
/// Each stage is a function from const inputs to a returned value and reports what it did (and
/// what it left out, and why) on the run summary.

#include <memory>

#include "app/render_frames.h"
#include "app/scene_options.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "sh/coeffs.h"

namespace prt {

/// The environment named by the options, described on the run summary.
std::unique_ptr<Environment> LoadSceneEnvironment(const SceneOptions& options);

/// The environment's SH coefficients for bands 0..options.lmax, windowed as asked
/// (`auto` picks the mildest window that keeps the reconstruction non-negative and says why).
ShRgb ComputeLight(const Environment& env, const SceneOptions& options);

/// The mesh of `--mesh` (or the embedded demo scene), with `--albedo` applied.
Mesh LoadSceneMesh(const SceneOptions& options);

/// The transport options the scene options ask for.
TransportOptions TransportOptionsOf(const SceneOptions& options);

/// The transport of `mesh`: read from `cache_path` when that file was made from the same mesh
/// and options, else computed (and written there, unless `cache_path` is empty).
Transport ComputeSceneTransport(const Mesh& mesh, const SceneOptions& options, const std::string& cache_path);

/// The whole main job: light, mesh, transport (cached in `cache_path` unless empty), camera, frames;
/// each stage reports on the run summary. Used by `render` and `demo`.
void RenderJob(const SceneOptions& scene, const RenderOptions& render, const std::string& cache_path);

}  // namespace prt
