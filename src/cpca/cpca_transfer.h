#pragma once
/// \file
/// Glossy transfer matrices compressed by clustered PCA (Sloan, Hall, Hart, Snyder 2003 [1]),
/// and the orbit frame's shading from them.
///
/// Each vertex-channel matrix M (n x n, n = (lmax+1)^2; precompute/transfer_matrix.h) is one row
/// of n^2 floats for CPCA (cpca.h): M_v ~ M_c + sum_k w_vk P_ck, c the vertex's cluster. The
/// glossy radiance toward the eye, KS hy . (M L) (hy the lobe row, LobeRow), is linear in M, so
/// the light goes through each cluster's matrices once per frame instead of through every
/// vertex's [1, sec. 4]:
///
///   per cluster:  (M_c L) and (P_ck L), k = 1..K, per colour      C (K + 1) n^2 work a frame
///   per vertex:   y = (M_c L) + sum_k w_vk (P_ck L)               n (K + 1) instead of n^2
///                 B_glossy = KS hy . y                            the lobe as for the full matrices
///
/// With one matrix for R, G and B (channels 1) the products are taken for each colour of the
/// light; with coloured bounces (channels 3) each channel has its own rows and uses its colour's.
/// A light of fewer bands uses its first columns, as GlossyFromMatrices does. The per-vertex loop
/// (floats) is compiled for the baseline and for AVX2 (core/simd.h) with the same operations in
/// the same order: the same bits on every instruction set and for any thread count.
///
/// References
/// [1] Sloan, Hall, Hart, Snyder, "Clustered Principal Components for Precomputed Radiance
///     Transfer", SIGGRAPH 2003.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "cpca/cpca.h"
#include "geometry/mesh.h"
#include "material/material.h"
#include "precompute/transport.h"
#include "sh/coeffs.h"

namespace prt {

/// The transfer matrices of a Transport as CPCA keeps them: row v * channels + c of `model`
/// (dim n^2) is the matrix of vertex v, channel c, row-major.
struct CpcaTransfer {
  int lmax = 0, channels = 1;
  std::size_t vertices = 0;
  CpcaModel model;
};

/// Compresses `transport.matrices` (required non-empty) by CPCA with `options`.
CpcaTransfer CompressTransferMatrices(const Transport& transport, const CpcaOptions& options);

/// Every matrix as the compressed form reconstructs it, in Transport::matrices' layout.
std::vector<float> ReconstructMatrices(const CpcaTransfer& cpca);

/// The glossy radiance of every vertex toward `eye` from the compressed matrices: what
/// GlossyFromMatrices gives for the reconstructed ones (up to rounding); 0 for diffuse.
std::vector<glm::vec3> GlossyFromCpca(const Mesh& mesh, const CpcaTransfer& cpca, const Material& material,
                                      const ShRgb& light, const glm::dvec3& eye);

/// ShadeVertices (precompute/shade.h) with the lobe from `cpca` instead of transport.matrices
/// (which may be empty): albedo (L . T) + the lobe toward `eye`; without `albedo`, the
/// diffuse lighting alone.
std::vector<glm::vec3> ShadeVerticesCpca(const Mesh& mesh, const Transport& transport, const CpcaTransfer& cpca,
                                         const ShRgb& light, bool albedo, const glm::dvec3& eye);

}  // namespace prt
