#include "sh/axis_rotation.h"
#include "core/constants.h"

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace prt {
namespace {

/// A rotation taking unit `k` onto +Z (about the axis k x Z; any, if k = -Z).
glm::dmat3 ToPole(const glm::dvec3& k) {
  const glm::dvec3 z(0, 0, 1);
  const glm::dvec3 c = glm::cross(k, z);
  const double s = glm::length(c), cosine = glm::dot(k, z);
  if (s < 1e-15) return cosine > 0 ? glm::dmat3(1.0) : AxisAngle({1, 0, 0}, kPi);
  return AxisAngle(c / s, std::atan2(s, cosine));
}

}  // namespace

AxisRotation::AxisRotation(const glm::dvec3& axis, int lmax)
    : axis_(glm::normalize(axis)),
      polar_(std::abs(axis_.x) < 1e-15 && std::abs(axis_.y) < 1e-15),
      sign_(axis_.z < 0 ? -1.0 : 1.0),
      to_pole_(ToPole(axis_), polar_ ? 0 : lmax) {}

ShRgb AxisRotation::Rotate(const ShRgb& coeffs, double angle) const {
  if (polar_) return RotateAboutZ(coeffs, sign_ * angle);
  return to_pole_.Apply(RotateAboutZ(to_pole_.Apply(coeffs), angle), /*transposed=*/true);
}

std::string AxisRotation::Describe() const {
  char buf[200];
  if (polar_) {
    std::snprintf(buf, sizeof buf, "about the SH polar axis: cos/sin(m a) per band, no matrices");
  } else {
    std::snprintf(buf, sizeof buf,
                  "about (%g, %g, %g): turned onto the SH polar axis once, then cos/sin(m a) per band",
                  axis_.x, axis_.y, axis_.z);
  }
  return buf;
}

}  // namespace prt
