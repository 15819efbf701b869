#pragma once
/// \file
/// The CPCA rows of `prt report --material phong:N,KS`: how far the clustered transfer matrices
/// (cpca/cpca_transfer.h) are from the full ones, by cluster count C and term count K, and what
/// memory they take. For each (C, K) the study compresses the shadowed matrices once and measures
///   - `frobenius`: sqrt(sum_v ||M_v - M^_v||_F^2 / sum_v ||M_v||_F^2) over every vertex and channel;
///   - `glossy`: the lobe's radiance from the compressed matrices against the full matrices' over
///     `eyes` (an orbit about the target), every vertex of every view in one relative RMS;
///   - `total`: the same for the rendered radiance (diffuse part included, which CPCA leaves alone);
///   - bytes (clusters' means and directions, per row K weights and a cluster index) and their
///     ratio to the full matrices', and the compression's time.
/// The errors are against the full matrices, not the ground truth: what compression adds.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "precompute/error_metrics.h"
#include "precompute/transport.h"
#include "sh/coeffs.h"

namespace prt {

struct CpcaStudyRow {
  int clusters = 0, terms = 0;
  double seconds = 0;        ///< the compression
  double frobenius = 0;      ///< relative Frobenius error of the matrices
  VertexError glossy, total; ///< shaded over the views, against the full matrices
  std::uint64_t bytes = 0;
  double memory_ratio = 0;   ///< bytes / the full matrices' bytes
};

struct CpcaStudy {
  int lmax = 0, channels = 1, views = 0, exponent = 0;
  std::size_t vertices = 0;
  std::uint64_t full_bytes = 0;
  std::vector<CpcaStudyRow> rows;
};

/// `count` eyes on the circle through `eye` about the vertical axis through `target`, the first `eye`.
std::vector<glm::dvec3> OrbitEyes(const glm::dvec3& eye, const glm::dvec3& target, int count);

/// Compresses `transport`'s matrices (glossy material set) for each of `clusters` x `terms` and
/// measures them under `light` from `eyes`.
CpcaStudy RunCpcaStudy(const Mesh& mesh, const Transport& transport, const ShRgb& light,
                       const std::vector<glm::dvec3>& eyes, const std::vector<int>& clusters,
                       const std::vector<int>& terms);

/// The report.md section.
std::string CpcaMarkdown(const CpcaStudy& study);
/// report.csv rows (path glossy-cpca-CxK) in Csv's columns, material `material` (already quoted).
std::string CpcaCsvRows(const CpcaStudy& study, int samples, const std::string& material);

}  // namespace prt
