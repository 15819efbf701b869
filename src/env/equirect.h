#pragma once
/// \file
/// An equirectangular (latitude-longitude) environment, world Y up.
///
/// Pixel (col, row) of a W x H image covers polar angles theta in [pi row/H, pi (row+1)/H]
/// (from +Y; row 0 is the sky straight up) and azimuths phi in [2 pi col/W, 2 pi (col+1)/W],
/// and looks along d = (sin theta sin phi', cos theta, -sin theta cos phi') with
/// phi' = phi - pi, so the centre column looks along -Z and a quarter turn to its right is +X.
/// Its solid angle is exact: (2 pi / W) (cos theta0 - cos theta1); a row's texels sum to the
/// area of its band and all rows to 4 pi.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/image.h"
#include "env/environment.h"

namespace prt {

class EquirectEnvironment : public Environment {
 public:
  EquirectEnvironment(ImageF image, std::string description);

  glm::dvec3 Radiance(const glm::dvec3& dir) const override;
  std::size_t RowCount() const override { return static_cast<std::size_t>(image_.height); }
  void Row(std::size_t i, std::vector<Texel>& out) const override;
  std::string Describe() const override { return description_; }

  /// Exact solid angle of one texel of row `row` in a W x H map.
  static double TexelSolidAngle(int row, int width, int height);

 private:
  ImageF image_;
  std::vector<double> sin_phi_, cos_phi_;  ///< per column centre
  std::string description_;
};

/// The width x height equirect image (the layout above) whose texel centres hold
/// `radiance(direction)`.
ImageF EquirectImage(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, int width, int height);

/// A width x height equirect whose texel centres hold `radiance(direction)`.
std::unique_ptr<EquirectEnvironment> EquirectFromFunction(const std::function<glm::dvec3(const glm::dvec3&)>& radiance,
                                                         int width, int height);

/// Loads an equirectangular .hdr, .exr, .png or .jpg. Throws Error for an unreadable file;
/// warns if the aspect ratio is not 2:1; sanitises non-finite, negative and enormous texels
/// with a warning.
std::unique_ptr<Environment> LoadEquirect(const std::string& path);

}  // namespace prt
