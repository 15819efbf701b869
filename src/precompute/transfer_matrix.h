#pragma once
/// \file
/// Transfer matrices for glossy materials seen from any view (Sloan, Kautz, Snyder 2002 [1],
/// sec. 6). Per vertex an n x n matrix, n = (lmax+1)^2, maps the light's coefficients L to those
/// of the transferred incident radiance with the cosine folded in:
///
///   M_ij = integral Y_i(s) Y_j(s) V(s) max(0, n.s) ds,      L'(s) cos ~ sum_i (M L)_i Y_i(s),
///
/// plus, with interreflection, the light of what blocks s (its hit point h treated as diffuse,
/// as in transport.h): M_ij += integral over blocked s of Y_i(s) albedo(h) T_j(h) max(0, n.s) ds
/// (per colour channel when the albedo is coloured), T(h) the diffuse transfer at h through
/// bounce B - 1. The glossy radiance toward any view v is then the lobe about r = reflect(-v, n)
/// applied to M L by the Funk–Hecke formula (material/lobe.h):
///
///   B_glossy(v) = KS sum_l h_l sum_m (M L)_lm Y_lm(r).
///
/// This truncates the product V L cos to lmax before the lobe is applied, so it differs from the
/// fixed-camera vector (transport.h), which truncates only L; it is exact when the lobe is
/// band-limited to lmax too (tests/precompute/test_transfer_matrix.cpp), and `prt report`
/// measures the difference for the Phong lobe.
///
/// Estimator: the unshadowed matrix by a Gauss product rule about the normal (exact: Y_i Y_j z
/// is a polynomial of degree 2 lmax + 1, integrated by lmax + 1 Gauss–Legendre nodes in z and
/// 2 lmax + 2 azimuths), minus the Monte Carlo estimate over the pool's blocked directions (the
/// same control variate as the diffuse transfer: unoccluded vertices get the exact matrix). The
/// blocked directions are those the direct pass records (transport_direct.h): no second tracing.
///
/// References
/// [1] Sloan, Kautz, Snyder, "Precomputed Radiance Transfer for Real-Time Rendering in Dynamic,
///     Low-Frequency Lighting Environments", SIGGRAPH 2002.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/bvh.h"
#include "geometry/mesh.h"
#include "precompute/direction_pool.h"
#include "precompute/transport_types.h"
#include "sh/coeffs.h"

namespace prt {

struct DirectResult;  // transport_direct.h

/// Bytes the matrices of `vertices` vertices take at `lmax` with `channels` channels (floats).
std::uint64_t TransferMatrixBytes(std::size_t vertices, int lmax, int channels);

/// The unshadowed matrix integral Y_i Y_j max(0, n.s) ds (n x n, row-major) into `out`.
void UnshadowedTransferMatrix(const glm::dvec3& normal, int lmax, double* out);

/// The lobe toward `eye` as a row over the coefficients: hy_lm = h_l Y_lm(r), r = LobeAxis(normal,
/// position, eye) (material/lobe_transfer.h), h = the lobe's zonal coefficients (KS not
/// included), into `hy` (CoeffCount(lmax) doubles). The glossy radiance of a vertex whose
/// transferred light is y = M L is KS hy . y: GlossyFromMatrices applies it to M, the clustered
/// matrices (cpca/cpca_transfer.h) to y.
void LobeRow(const glm::dvec3& normal, const glm::dvec3& position, const glm::dvec3& eye, int lmax,
             const std::vector<double>& h, double* hy);

/// LobeRow of vertices [begin, end) of `mesh` into rows[(v - begin) * CoeffCount(lmax) + k], the
/// basis evaluated several vertices at a time (sh/basis.h, EvalBasisBatch; it rounds unlike
/// EvalBasis, within a few ulps). `rows` is resized to fit.
void LobeRows(const Mesh& mesh, std::size_t begin, std::size_t end, const glm::dvec3& eye, int lmax,
              const std::vector<double>& h, std::vector<double>& rows);

/// Linear RGB glossy radiance KS sum_l h_l sum_m (M L)_lm Y_lm(r) of every vertex seen from
/// `eye` (h = the lobe's zonal coefficients, material/lobe.h); added to the diffuse part by
/// ShadeVerticesFromMatrices (shade.h).
std::vector<glm::vec3> GlossyFromMatrices(const Mesh& mesh, const Transport& transport, const Material& material,
                                          const ShRgb& light, const glm::dvec3& eye);

/// The transfer matrices of every vertex into transport.matrices (above), from the
/// blocked directions and hits `direct` recorded (null: unshadowed, no pool); `hit_transfer`
/// (BounceResult::before_last, transport.channels channels) with interreflection, else null.
void ComputeTransferMatrices(const Mesh& mesh, const DirectionPlan* plan, const DirectResult* direct, int lmax,
                             const std::vector<double>* hit_transfer, Transport& transport,
                             const VertexBlock& block = {});

}  // namespace prt
