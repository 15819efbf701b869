#include "env/equirect.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "core/constants.h"
#include "core/log.h"
#include "io/image_load.h"

namespace prt {

EquirectEnvironment::EquirectEnvironment(ImageF image, std::string description)
    : image_(std::move(image)), description_(std::move(description)) {
  sin_phi_.resize(image_.width);
  cos_phi_.resize(image_.width);
  for (int col = 0; col < image_.width; ++col) {
    const double phi = 2.0 * kPi * (col + 0.5) / image_.width - kPi;
    sin_phi_[col] = std::sin(phi);
    cos_phi_[col] = std::cos(phi);
  }
}

double EquirectEnvironment::TexelSolidAngle(int row, int width, int height) {
  const double t0 = kPi * row / height, t1 = kPi * (row + 1) / height;
  // cos t0 - cos t1 = 2 sin((t0 + t1)/2) sin((t1 - t0)/2): no cancellation near the poles.
  return 2.0 * kPi / width * 2.0 * std::sin(0.5 * (t0 + t1)) * std::sin(0.5 * (t1 - t0));
}

void EquirectEnvironment::Row(std::size_t i, std::vector<Texel>& out) const {
  const int row = static_cast<int>(i);
  const double theta = kPi * (row + 0.5) / image_.height;
  const double st = std::sin(theta), ct = std::cos(theta);
  const double omega = TexelSolidAngle(row, image_.width, image_.height);
  out.resize(image_.width);
  for (int col = 0; col < image_.width; ++col) {
    out[col].dir = {st * sin_phi_[col], ct, -st * cos_phi_[col]};
    out[col].solid_angle = omega;
    out[col].radiance = glm::dvec3(image_.at(col, row));
  }
}

glm::dvec3 EquirectEnvironment::Radiance(const glm::dvec3& d) const {
  const double theta = std::acos(std::clamp(d.y, -1.0, 1.0));
  double phi = std::atan2(d.x, -d.z) + kPi;  // in [0, 2 pi]
  const double x = phi / (2.0 * kPi) * image_.width - 0.5;
  const double y = std::clamp(theta / kPi * image_.height - 0.5, 0.0, image_.height - 1.0);
  // Bilinear, wrapping around in azimuth and clamped at the poles.
  const int w = image_.width;
  const int x0 = static_cast<int>(std::floor(x));
  const double fx = x - x0;
  const int xa = ((x0 % w) + w) % w, xb = (xa + 1) % w;
  const int y0 = static_cast<int>(y), y1 = std::min(y0 + 1, image_.height - 1);
  const double fy = y - y0;
  const glm::dvec3 top = glm::mix(glm::dvec3(image_.at(xa, y0)), glm::dvec3(image_.at(xb, y0)), fx);
  const glm::dvec3 bottom = glm::mix(glm::dvec3(image_.at(xa, y1)), glm::dvec3(image_.at(xb, y1)), fx);
  return glm::mix(top, bottom, fy);
}

ImageF EquirectImage(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, int width, int height) {
  ImageF image(width, height);
  for (int row = 0; row < height; ++row) {
    const double theta = kPi * (row + 0.5) / height;
    for (int col = 0; col < width; ++col) {
      const double phi = 2.0 * kPi * (col + 0.5) / width - kPi;
      const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
      image.at(col, row) = glm::vec3(radiance(d));
    }
  }
  return image;
}

std::unique_ptr<EquirectEnvironment> EquirectFromFunction(const std::function<glm::dvec3(const glm::dvec3&)>& radiance,
                                                         int width, int height) {
  return std::make_unique<EquirectEnvironment>(EquirectImage(radiance, width, height),
                                               "equirect from a function " + std::to_string(width) + "x" +
                                                   std::to_string(height));
}

std::unique_ptr<Environment> LoadEquirect(const std::string& path) {
  ImageF image = LoadImageLinear(path, LdrDecode::kSrgb);
  if (image.width != 2 * image.height)
    Warn(path + ": equirectangular map is " + std::to_string(image.width) + "x" +
         std::to_string(image.height) + ", not 2:1; pixels are stretched to cover the sphere");
  const SanitizeCounts fixed = SanitizeRadiance(image);
  if (fixed.total() > 0) Warn(path + ": " + DescribeSanitized(fixed));
  const std::string description = "equirect " + path + " " + std::to_string(image.width) + "x" +
                                  std::to_string(image.height);
  return std::make_unique<EquirectEnvironment>(std::move(image), description);
}

}  // namespace prt
