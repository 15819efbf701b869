#include "env/procedural.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/constants.h"
#include "sh/basis.h"
#include "sh/quadrature.h"

namespace prt {
namespace {

/// A Gauss product rule whose polar axis is world +Y, one row per latitude.
class GaussRows {
 public:
  explicit GaussRows(int n) : n_(n) { GaussLegendre(n, nodes_, weights_); }
  std::size_t count() const { return static_cast<std::size_t>(n_); }
  template <class RadianceFn>
  void Row(std::size_t i, std::vector<Texel>& out, const RadianceFn& radiance) const {
    const int nphi = 2 * n_;
    const double y = nodes_[i], s = std::sqrt((1.0 - y) * (1.0 + y));
    out.resize(nphi);
    for (int j = 0; j < nphi; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / nphi;
      out[j].dir = {s * std::sin(phi), y, -s * std::cos(phi)};
      out[j].solid_angle = weights_[i] * 2.0 * kPi / nphi;
      out[j].radiance = radiance(out[j].dir);
    }
  }

 private:
  int n_;
  std::vector<double> nodes_, weights_;
};

class Furnace : public Environment {
 public:
  // 101 latitudes: exact for every band up to 201 > kMaxBasisLmax, so no band but 0 picks up
  // quadrature error.
  explicit Furnace(double c) : c_(c), rows_(101) {}
  glm::dvec3 Radiance(const glm::dvec3&) const override { return glm::dvec3(c_); }
  std::size_t RowCount() const override { return rows_.count(); }
  void Row(std::size_t i, std::vector<Texel>& out) const override {
    rows_.Row(i, out, [this](const glm::dvec3&) { return glm::dvec3(c_); });
  }
  std::string Describe() const override { return "furnace (constant radiance " + Fmt(c_) + ")"; }

 private:
  static std::string Fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
  }
  double c_;
  GaussRows rows_;
};

double SmoothStep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

class Sky : public Environment {
 public:
  explicit Sky(const SkyParams& p)
      : p_(p), sun_dir_(SunDirection(p)), cos_radius_(std::cos(p.radius * kPi / 180.0)), rows_(96) {
    const double disk = 2.0 * kPi * (1.0 - cos_radius_);
    sun_radiance_ = glm::dvec3(1.0, 0.93, 0.82) * (p.sun / disk);
  }

  /// Everything but the disk: smooth, so the Gauss rule integrates it to spectral accuracy.
  glm::dvec3 Smooth(const glm::dvec3& d) const {
    const glm::dvec3 zenith(0.22, 0.42, 0.95), horizon(0.85, 0.88, 0.95), ground(0.42, 0.40, 0.37);
    const double up = std::max(d.y, 0.0);
    const glm::dvec3 sky = glm::mix(horizon, zenith, std::pow(up, 0.6));
    const double cos_sun = glm::dot(d, sun_dir_);
    const glm::dvec3 glow = glm::dvec3(1.0, 0.85, 0.6) * (1.2 * std::exp((cos_sun - 1.0) / 0.03));
    const double above = SmoothStep(-0.06, 0.06, d.y);  // soft horizon over about 7 degrees
    return glm::mix(ground, sky + glow, above);
  }

  glm::dvec3 Radiance(const glm::dvec3& d) const override {
    return Smooth(d) + (glm::dot(d, sun_dir_) >= cos_radius_ ? sun_radiance_ : glm::dvec3(0.0));
  }
  std::size_t RowCount() const override { return rows_.count(); }
  void Row(std::size_t i, std::vector<Texel>& out) const override {
    rows_.Row(i, out, [this](const glm::dvec3& d) { return Smooth(d); });
  }
  void AddAnalyticProjection(int lmax, ShRgb& coeffs) const override {
    const std::vector<double> cap = CapLegendreIntegrals(lmax, cos_radius_);
    const std::vector<double> y = EvalBasis(lmax, sun_dir_);
    for (int l = 0; l <= lmax; ++l)
      for (int k = l * l; k < (l + 1) * (l + 1); ++k) coeffs[k] += 2.0 * kPi * cap[l] * y[k] * sun_radiance_;
  }
  std::vector<LightDisk> Disks() const override { return {{sun_dir_, cos_radius_, sun_radiance_}}; }
  glm::dvec3 RadianceWithoutDisks(const glm::dvec3& d) const override { return Smooth(d); }
  std::string Describe() const override {
    char b[160];
    std::snprintf(b, sizeof b, "sky (sun=%g elevation=%g azimuth=%g radius=%g)", p_.sun, p_.elevation,
                  p_.azimuth, p_.radius);
    return b;
  }

 private:
  SkyParams p_;
  glm::dvec3 sun_dir_;
  double cos_radius_;
  glm::dvec3 sun_radiance_;
  GaussRows rows_;
};

}  // namespace

std::vector<double> CapLegendreIntegrals(int lmax, double x) {
  std::vector<double> p(lmax + 2);  // P_0 .. P_{lmax+1} at x
  p[0] = 1.0;
  if (lmax + 1 >= 1) p[1] = x;
  for (int l = 2; l <= lmax + 1; ++l) p[l] = ((2.0 * l - 1.0) * x * p[l - 1] - (l - 1.0) * p[l - 2]) / l;
  std::vector<double> integral(lmax + 1);
  integral[0] = 1.0 - x;
  for (int l = 1; l <= lmax; ++l) integral[l] = (p[l - 1] - p[l + 1]) / (2.0 * l + 1.0);
  return integral;
}

glm::dvec3 SunDirection(const SkyParams& p) {
  const double el = p.elevation * kPi / 180.0, az = p.azimuth * kPi / 180.0;
  return {std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az)};
}

std::unique_ptr<Environment> MakeFurnace(double c) { return std::make_unique<Furnace>(c); }
std::unique_ptr<Environment> MakeSky(const SkyParams& params) { return std::make_unique<Sky>(params); }

}  // namespace prt
