#pragma once
/// \file
/// What every basis gives the frame loop (render/render_frames.h): the light of one frame as
/// the vertices receive it. A basis is a folder of src/ that stores per-vertex transport in its
/// own coefficients and implements this interface; app/basis_table.h lists them.
///
///   sh        (sh_basis/frame_light.h) the light's SH coefficients turned by the frame's
///             rotation, each vertex a dot product with its transfer vector;
///   wavelet   (wavelet/frame_light.h) the environment turned and resampled onto the wavelet
///             cube, its Haar coefficients, each vertex a sparse dot product.
///
/// Turn(angle) is called once per frame with the absolute angle (no accumulated drift); the
/// other calls read the light it left. SetAxis changes the axis of the turns that follow, keeping
/// what the light keeps of its environment: the next Turn gives the bytes of a light made with
/// that axis (prt view's drag turns about a new axis every move).

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"

namespace prt {

/// What a frame light may trade for time. kStill is the light `prt render` draws with; kInteractive
/// is prt view's while the light or the camera moves, followed by a still frame once they stop: a
/// basis may keep its light coarser then (the wavelets gather the environment into fewer cells,
/// wavelet/light_cube.h), never with less energy.
enum class LightQuality { kStill, kInteractive };

class FrameLight {
 public:
  virtual ~FrameLight() = default;
  /// Turns the light by `angle` radians about the axis it was made with: L'(d) = L(R^T d).
  virtual void Turn(double angle) = 0;
  /// The turns that follow go about `axis` (non-zero); call Turn before reading the light again.
  virtual void SetAxis(const glm::dvec3& axis) = 0;
  /// Per-vertex linear RGB radiance toward `eye` (without `albedo`: as if every albedo were 1 and
  /// the material diffuse).
  virtual std::vector<glm::vec3> Shade(const Mesh& mesh, bool albedo, const glm::dvec3* eye) const = 0;
  /// The same into `out`, which a frame loop keeps between frames; a basis that can shade
  /// without allocating overrides it.
  virtual void ShadeInto(const Mesh& mesh, bool albedo, const glm::dvec3* eye, std::vector<glm::vec3>& out) const {
    out = Shade(mesh, albedo, eye);
  }
  /// True when the material has a glossy lobe, which Glossy() gives apart.
  virtual bool HasGlossy() const = 0;
  /// A glossy material's lobe term alone; 0 where there is none.
  virtual std::vector<glm::vec3> Glossy(const Mesh& mesh, const glm::dvec3* eye) const = 0;
  /// The light as the basis keeps it, arriving from unit direction `d` (the light view).
  virtual glm::vec3 Kept(const glm::dvec3& d) const = 0;
  /// Transfer coefficients per vertex that the transport view can show (its first channel's);
  /// 0 for a basis whose coefficients are not one fixed function each.
  virtual int ViewCoefficients() const = 0;
  /// Vertex `v`'s transfer coefficient `k` < ViewCoefficients(), first channel.
  virtual double Coefficient(std::size_t v, int k) const = 0;
};

}  // namespace prt
