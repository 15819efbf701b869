#pragma once
/// \file
/// Spherical harmonics as a basis of the frame loop (basis/frame_light.h). The transport is
/// precompute/'s Transport: per vertex and channel the transfer vector T_k of bands 0..lmax
/// (precompute/transport.h), and with a glossy material the lobe's vectors G toward a fixed eye
/// or the transfer matrices of an orbiting camera. A frame:
///
///   light     the environment's SH coefficients L_k (precompute/light.h), bands beyond the
///             transport's dropped, turned about the axis by the band rotations
///             (sh/axis_rotation.h): L'_k = sum_j R(a)_kj L_j;
///   shading   each vertex  albedo * sum_k L'_k T_k  per channel (precompute/shade.h), plus the
///             lobe's term; with clustered PCA (cpca/cpca_transfer.h) the lobe comes from the
///             compressed matrices instead of transport.matrices;
///   kept      the light as the bands keep it, sum_k L'_k Y_k(d) (the light view);
///   view      the transport view shows T_k of the first channel.

#include <memory>

#include <glm/vec3.hpp>

#include "basis/frame_light.h"
#include "cpca/cpca_transfer.h"
#include "precompute/transport.h"
#include "sh/coeffs.h"

namespace prt {

/// SH: `transport` with `light` (bands beyond the transport's dropped), turned about `axis`. With
/// `cpca`, a glossy material's lobe comes from those compressed matrices (cpca/cpca_transfer.h)
/// instead of transport.matrices; `transport` and `cpca` must outlive the result.
std::unique_ptr<FrameLight> MakeShFrameLight(const Transport& transport, const ShRgb& light, const glm::dvec3& axis,
                                             const CpcaTransfer* cpca = nullptr);

}  // namespace prt
