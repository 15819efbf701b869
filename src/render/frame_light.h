#pragma once
/// \file
/// The light of one frame as the vertices receive it, per basis: what the frame loop
/// (render_frames.h) needs from a transport, whichever basis stores it.
///
///   sh        the light's SH coefficients turned by the frame's rotation (sh/axis_rotation.h),
///             each vertex a dot product with its transfer vector (precompute/shade.h);
///   wavelet   the environment turned and resampled onto the wavelet cube, its Haar coefficients
///             (optionally only the K most important: Ng's non-linear approximation), each vertex
///             a sparse dot product; bounced light through the SH light (precompute/shade_wavelet.h).
///
/// Turn(angle) is called once per frame with the absolute angle (no accumulated drift); the
/// other calls read the light it left.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "cpca/cpca_transfer.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/shade_wavelet.h"
#include "precompute/transport.h"
#include "precompute/transport_wavelet.h"
#include "sh/axis_rotation.h"
#include "sh/coeffs.h"
#include "wavelet/light_cube.h"

namespace prt {

class FrameLight {
 public:
  virtual ~FrameLight() = default;
  /// Turns the light by `angle` radians about the axis it was made with: L'(d) = L(R^T d).
  virtual void Turn(double angle) = 0;
  /// Per-vertex linear RGB radiance toward `eye`, as ShadeVertices gives it (without `albedo`:
  /// as if every albedo were 1 and the material diffuse).
  virtual std::vector<glm::vec3> Shade(const Mesh& mesh, bool albedo, const glm::dvec3* eye) const = 0;
  /// The same into `out`, which a frame loop keeps between frames; a basis that can shade
  /// without allocating overrides it.
  virtual void ShadeInto(const Mesh& mesh, bool albedo, const glm::dvec3* eye, std::vector<glm::vec3>& out) const {
    out = Shade(mesh, albedo, eye);
  }
  /// A glossy material's lobe term alone (ShadeGlossy); 0 where the basis has none.
  virtual std::vector<glm::vec3> Glossy(const Mesh& mesh, const glm::dvec3* eye) const = 0;
  /// The light as the basis keeps it, arriving from unit direction `d` (the light view).
  virtual glm::vec3 Kept(const glm::dvec3& d) const = 0;
  /// The SH transport, for the views that show SH coefficients; null for other bases.
  virtual const Transport* ShTransport() const = 0;
};

/// SH: `transport` with `light` (bands beyond the transport's dropped), turned about `axis`. With
/// `cpca`, a glossy material's lobe comes from those compressed matrices (cpca/cpca_transfer.h)
/// instead of transport.matrices; `transport` and `cpca` must outlive the result.
std::unique_ptr<FrameLight> MakeShFrameLight(const Transport& transport, const ShRgb& light, const glm::dvec3& axis,
                                             const CpcaTransfer* cpca = nullptr);

/// Wavelets: `transport` under `env` turned about `axis`, `sh_light` lighting its bounces (may
/// be empty without them); `light_terms` > 0 keeps only that many light coefficients per frame,
/// chosen by `selection`. `env` and `transport` must outlive the result.
std::unique_ptr<FrameLight> MakeWaveletFrameLight(const WaveletTransport& transport, const Environment& env,
                                                  const ShRgb& sh_light, const glm::dvec3& axis, int light_terms,
                                                  Selection selection);

}  // namespace prt
