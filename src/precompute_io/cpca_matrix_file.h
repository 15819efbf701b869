#pragma once
/// \file
/// `transfer_matrices_cpca.bin`, what `prt precompute --material phong:N,KS --cpca C,K` writes
/// beside transfer_matrices.bin: the same content with the matrices compressed by clustered PCA
/// (cpca/cpca_transfer.h), everything needed to shade the vertices from any view under any light
/// of bands <= lmax, without prt:
///
///   M(v, c) = mean[k] + sum_t w[t] principal[k][t],    k = the row's cluster,
///   B(v) = albedo (T . L) + KS sum_l h_l sum_m (M L)_lm Y_lm(r),   r = 2 (n.v) n - v.
///
/// Layout, little-endian, no padding:
///   char[8]  "PRTCPCAM"
///   u32      format version (1)
///   u32      lmax; n = (lmax + 1)^2 coefficients, in the order l(l+1) + m
///   u32      channels (1, or 3 for coloured interreflection: R, G, B)
///   u32      Phong exponent N
///   u64      vertex count V
///   u32      cluster count C (1 .. V channels)
///   u32      terms K (0 .. n^2)
///   f64      KS
///   f64      h[lmax + 1], the lobe's zonal coefficients (material/lobe.h; KS not included)
///   f32      mean[C][n][n]                 each cluster's mean matrix, row-major
///   f32      principal[C][K][n][n]         its K orthonormal principal matrices
///   then for each vertex, in the mesh's welded order:
///     f32 position[3], f32 normal[3], f32 albedo[3],
///     f32 T[channels][n]                   diffuse transfer, 1/pi included, albedo not
///     per channel: u32 cluster (< C), f32 w[K]
/// Written atomically (core/atomic_file.h). The reader checks the magic, version, counts, every
/// cluster index and the exact file size, and throws Error naming what is wrong.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "cpca/cpca_transfer.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"

namespace prt {

struct CpcaMatrixFile {
  int exponent = 1;
  double ks = 0.0;
  std::vector<double> lobe;                   ///< h_0..h_lmax
  std::vector<glm::vec3> positions, normals, albedo;
  std::vector<float> transfer;                ///< [(v * channels + c) * n + k]
  CpcaTransfer cpca;                          ///< lmax, channels, vertices and the model
};

/// Writes `cpca` (compressed from `transport`'s matrices) with `mesh` and `transport`'s diffuse
/// transfer and material.
void WriteCpcaMatrixFile(const std::string& path, const Mesh& mesh, const Transport& transport, const CpcaTransfer& cpca);

/// Reads a file written by WriteCpcaMatrixFile; throws Error when it is not one or is damaged.
CpcaMatrixFile ReadCpcaMatrixFile(const std::string& path);

}  // namespace prt
