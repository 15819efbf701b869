#pragma once
/// \file
/// `prt report`'s visible-noise study: how far frame 0 of a render lies from a converged frame,
/// per way of spending the transport's directions, against its time.
///
/// The error a viewer sees is not the RMS of vertex radiance: a smooth truncation error is
/// invisible, while independent per-vertex noise of the same RMS shows as blotches. So each
/// method is scored by its picture: frame 0 (the render's camera, supersampling and tone curve,
/// at the converged frame's automatic exposure) against the same frame of a transport with
/// `converged_samples` directions at every vertex, as the largest per-pixel difference in 8-bit
/// levels and the share of pixels more than one level apart; beside it the relative RMS error of
/// the radiance of the vertices the camera sees, and the transport's time (median of
/// `repeats` runs, interleaved across methods).
///
/// The methods: one set of the sampler per vertex from a pool of 64 at 1024 directions (prt's
/// default before the camera was taken into account), the same with one set shared by every
/// vertex (the error correlated between neighbours), four times the directions everywhere,
/// the sample rule's default (sample_rule.h: more directions for the vertices the frames show),
/// and 16384 directions everywhere; those with more than a quarter of the converged count are
/// left out.

#include <optional>
#include <string>
#include <vector>

#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "raster/image_diff.h"
#include "render/render_options.h"

namespace prt {

/// One way of spending directions.
struct NoiseMethod {
  std::string name;
  int samples = 0;         ///< directions per vertex the camera sees
  int hidden_samples = 0;  ///< directions per vertex it does not
  int direction_sets = 64;
};

struct NoiseRow {
  NoiseMethod method;
  double seconds = 0.0;       ///< median transport time
  std::uint64_t rays = 0;
  double rms_error = 0.0;     ///< relative RMS of seen vertices' radiance against the converged
  DiffMetrics frame;          ///< frame 0 against the converged frame 0 (max_abs, pixels_over_one)
};

struct NoiseConfig {
  TransportMode mode = TransportMode::kInterreflection;
  int lmax = 4;
  int converged_samples = 65536;
  int repeats = 3;
  std::uint64_t seed = 1;
  int bounces = 1;
};

struct NoiseStudy {
  NoiseConfig config;
  std::size_t vertices = 0, seen_vertices = 0;
  double exposure = 0.0;  ///< the EV every frame is tone-mapped with
  std::size_t pixels = 0; ///< pixels of a frame
  std::vector<NoiseRow> rows;
};

/// The methods above for `lmax` and the fibonacci sampler, the sample rule's default among them.
std::vector<NoiseMethod> NoiseMethods(int lmax);

/// Frame 0 of a render of `mesh` with `transport` under `light` (projected from `env`) as
/// `picture` draws it, tone-mapped at exposure `ev`; when `ev` is empty, measured on this frame
/// and stored there.
Image8 NoiseFrame(const Mesh& mesh, const Transport& transport, const ShRgb& light, const Environment& env,
                  const RenderOptions& picture, std::optional<double>& ev);

/// Runs every method of NoiseMethods(config.lmax) on `mesh` under `env`, frames as `picture`.
NoiseStudy RunNoiseStudy(const Mesh& mesh, const Environment& env, const NoiseConfig& config,
                         const RenderOptions& picture);

/// The study as a Markdown section (heading, what was measured, the table).
std::string NoiseMarkdown(const NoiseStudy& study);

}  // namespace prt
