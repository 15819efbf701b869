#pragma once
/// \file
/// The glossy section of `prt report` (with `--material phong:N,KS`): how many SH bands a Phong
/// lobe needs, and how far the two glossy paths of precompute/ (the fixed-camera vector G of
/// transport.h, the transfer matrices of transfer_matrix.h) are from each other and from the
/// ground truth.
///
/// For each exponent N of the sweep (10, 100, 1000 and the user's N, all with the user's KS), seen
/// from the report's picture camera:
///   - the vector path's transport (T and G) is computed and timed at each lmax, and its
///     per-vertex radiance B = albedo (L.T) + L.G compared with prt reference's
///     (precompute/reference.h, same material, same eye): `total` error. The lobe's part alone,
///     L.G, is compared with the reference's lobe part (the glossy reference minus the diffuse
///     one: the reference draws the lobe's samples from a stream of their own, so the difference
///     holds the lobe's estimate and nothing else): `lobe` error. This runs twice: unshadowed,
///     where the lobe alone filters the light, so its error is what the bands do to the lobe
///     (the rule of thumb lmax ~ sqrt(N) is about this), and shadowed, the scene as rendered,
///     where visibility adds edges (a small sun's shadows) that no lobe smooths. The lmax an
///     exponent needs is the smallest whose lobe error is at most kLobeTarget, in each mode;
///   - shadowed, the transfer matrices are computed once per lmax (they do not depend on the
///     lobe) and shaded for each N; their radiance is compared with the vector path's (the
///     diffuse parts are identical, so the difference is all in the lobe) and with the
///     reference. The matrices truncate V L cos to lmax before the lobe is applied, the vector
///     only L: that is the difference measured.
/// The light is projected once at the sweep's highest lmax and each run shades with its first
/// (lmax+1)^2 coefficients. Times are the fastest of repeats (report_sweep.h, TimedTransport).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/image.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/error_metrics.h"
#include "precompute/transport.h"
#include "report/report_cpca.h"

namespace prt {

/// The lmax an exponent needs: the smallest of the sweep whose lobe error is at most this.
constexpr double kLobeTarget = 0.10;

struct GlossyConfig {
  std::vector<int> exponents = {10, 100, 1000};  ///< sorted, distinct
  double ks = 0.5;
  std::vector<int> vector_lmax = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32};  ///< ascending
  std::vector<int> matrix_lmax = {1, 2, 3, 4, 6, 8};  ///< ascending, each also in vector_lmax
  int samples = 2048;          ///< pool directions per vertex (fibonacci)
  int lobe_samples = 1024;     ///< lobe rays per vertex of the vector path
  int reference_samples = 8192;
  std::uint64_t seed = 1;
  /// The CPCA rows (report_cpca.h): the shadowed matrices at this lmax (when the matrix sweep has
  /// it) compressed by each cluster count x term count, shaded with the user's exponent.
  int cpca_lmax = 4;
  int cpca_exponent = 0;
  std::vector<int> cpca_clusters = {16, 64, 256}, cpca_terms = {1, 2, 4, 8};
  int cpca_views = 8;
};

/// The sweep `prt report` runs: `quick` keeps it to a few seconds (lmax to 8, fewer directions).
/// `user_exponent` joins the three fixed exponents.
GlossyConfig MakeGlossyConfig(bool quick, int user_exponent, double ks, std::uint64_t seed);

/// One (mode, N, lmax) of the vector path.
struct GlossyVectorRow {
  TransportMode mode = TransportMode::kShadowed;  ///< unshadowed or shadowed
  int exponent = 0, lmax = 0;
  double seconds = 0;         ///< transport (T and G) precompute, fastest of repeats
  VertexError total, lobe;    ///< against the reference (see above)
  double band_share = 0;      ///< LobeBandShare(lobe, lmax), material/lobe.h
};

/// One (N, lmax) of the matrix path (shadowed), beside the vector path's row of the same (N, lmax).
struct GlossyMatrixRow {
  int exponent = 0, lmax = 0;
  double seconds = 0;          ///< transport with matrices (T and M), fastest of repeats
  std::uint64_t bytes = 0;     ///< the matrices' memory
  VertexError total, lobe;     ///< against the reference
  VertexError vs_vector;       ///< matrix radiance against the vector path's (relative to its RMS)
  VertexError lobe_vs_vector;  ///< the lobe parts alone
};

/// Per exponent and mode: the reference and the lmax the lobe needs.
struct GlossyNeed {
  double reference_seconds = 0;
  double reference_rms_error = 0;   ///< the glossy reference's own noise, relative to its RMS
  double lobe_share = 0;            ///< RMS of the reference's lobe part over the RMS of its radiance
  int needed_lmax = -1;             ///< smallest lmax of the sweep with lobe error <= kLobeTarget; -1: none
  int best_lmax = 0;                ///< where the lobe error was lowest
  double best_lobe_error = 0;
};

struct GlossyExponent {
  int exponent = 0;
  GlossyNeed unshadowed, shadowed;
  int share_lmax = -1;              ///< smallest lmax keeping 90% of the lobe's energy (LobeBandShare)
};

struct GlossyStudy {
  double ks = 0;
  glm::dvec3 eye{0.0};
  int samples = 0, lobe_samples = 0, reference_samples = 0;
  std::vector<GlossyExponent> exponents;
  std::vector<GlossyVectorRow> vector_rows;
  std::vector<GlossyMatrixRow> matrix_rows;
  std::optional<CpcaStudy> cpca;
};

/// Runs the study on `mesh` under `env` seen from `eye` (progress on the run summary).
GlossyStudy RunGlossyStudy(const Mesh& mesh, const Environment& env, const glm::dvec3& eye, const GlossyConfig& config);

/// The report.md section (heading, how to read it, three tables).
std::string GlossyMarkdown(const GlossyStudy& study);
/// report.csv rows in Csv's columns (report_write.cpp), material and path filled in.
std::string GlossyCsvRows(const GlossyStudy& study);
/// glossy_error_vs_lmax.png: lobe error against lmax, a line per exponent and path.
Image8 GlossyPlot(const GlossyStudy& study);

}  // namespace prt
