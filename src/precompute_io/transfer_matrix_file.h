#pragma once
/// \file
/// `transfer_matrices.bin`, what `prt precompute --material phong:N,KS` writes: everything needed
/// to shade the mesh's vertices from any view under any light of bands <= lmax, without prt
/// (precompute/transfer_matrix.h):
///
///   B(v) = albedo (T . L) + KS sum_l h_l sum_m (M L)_lm Y_lm(r),   r = 2 (n.v) n - v,
///
/// per colour channel (the channel's T and M when there are three, else the one of both).
///
/// Layout, little-endian, no padding:
///   char[8]  "PRTMATRX"
///   u32      format version (1)
///   u32      lmax; n = (lmax + 1)^2 coefficients, in the order l(l+1) + m
///   u32      channels (1, or 3 for coloured interreflection: R, G, B)
///   u32      Phong exponent N
///   u64      vertex count V
///   f64      KS
///   f64      h[lmax + 1], the lobe's zonal coefficients (material/lobe.h; KS not included)
///   then for each vertex, in the mesh's welded order:
///     f32 position[3], f32 normal[3], f32 albedo[3],
///     f32 T[channels][n]       diffuse transfer, 1/pi included, albedo not
///     f32 M[channels][n][n]    transfer matrix, row-major, cosine included
/// Written atomically (core/atomic_file.h). The reader checks the magic, version, counts and the
/// exact file size, and throws Error naming what is wrong.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "material/material.h"
#include "precompute/transport.h"

namespace prt {

struct TransferMatrixFile {
  int lmax = 0, channels = 1, exponent = 1;
  double ks = 0.0;
  std::vector<double> lobe;                   ///< h_0..h_lmax
  std::vector<glm::vec3> positions, normals, albedo;
  std::vector<float> transfer;                ///< [(v * channels + c) * n + k]
  std::vector<float> matrices;                ///< [((v * channels + c) * n + i) * n + j]
};

/// Writes the matrices of `transport` (computed with TransportOptions::matrices) for `mesh`.
void WriteTransferMatrixFile(const std::string& path, const Mesh& mesh, const Transport& transport);

/// Reads a file written by WriteTransferMatrixFile; throws Error when it is not one or is damaged.
TransferMatrixFile ReadTransferMatrixFile(const std::string& path);

}  // namespace prt
