#pragma once
/// \file
/// A distant environment light: linear RGB radiance arriving at the scene from each direction
/// (world frame, Y up). Every kind of environment also says how to integrate it exactly:
///
///   integral of f(w) L(w) dw  =  sum over rows, sum over texels of  f(dir) * solid_angle * L
///
/// For a cubemap the texels are its pixels with their exact solid angles; for an equirect its
/// pixels with exact row solid angles; for a procedural environment a Gauss product rule. What
/// no grid resolves (the small sun disk of `sky`) is added analytically by AddAnalyticProjection.
/// Light projection (precompute/light.h) needs nothing else, so it is one loop for every kind.

#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "sh/coeffs.h"

namespace prt {

/// One quadrature node: a unit direction, the solid angle it stands for, and the radiance there.
struct Texel {
  glm::dvec3 dir;
  double solid_angle;
  glm::dvec3 radiance;
};

/// A disk of uniform radiance that no grid resolves (the sky's sun): every direction w with
/// dot(w, dir) >= cos_radius receives `radiance` on top of RadianceWithoutDisks.
struct LightDisk {
  glm::dvec3 dir;
  double cos_radius;
  glm::dvec3 radiance;
};

class Environment {
 public:
  virtual ~Environment() = default;

  /// Radiance arriving from unit direction `dir` (for backgrounds and ground truth).
  virtual glm::dvec3 Radiance(const glm::dvec3& dir) const = 0;

  /// Rows of the environment's own quadrature; each row is small enough to sit in cache.
  virtual std::size_t RowCount() const = 0;
  /// Fills `out` with the nodes of row `i` (replacing its contents).
  virtual void Row(std::size_t i, std::vector<Texel>& out) const = 0;

  /// Adds the exact projection of whatever the rows leave out. Default: nothing.
  virtual void AddAnalyticProjection(int lmax, ShRgb& coeffs) const { (void)lmax, (void)coeffs; }

  /// The disks the rows leave out (AddAnalyticProjection projects them), for a basis that places
  /// them exactly (wavelet/light_cube.h). Default: none.
  virtual std::vector<LightDisk> Disks() const { return {}; }
  /// Radiance from `dir` without the Disks. Default: Radiance.
  virtual glm::dvec3 RadianceWithoutDisks(const glm::dvec3& dir) const { return Radiance(dir); }

  /// One line for the run summary, e.g. "cubemap GraceCathedral 6x256^2 (sRGB)".
  virtual std::string Describe() const = 0;
};

}  // namespace prt
