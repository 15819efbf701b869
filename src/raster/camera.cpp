#include "raster/camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/constants.h"
#include "core/error.h"
#include "core/text.h"

namespace prt {
namespace {

constexpr float kPiF = static_cast<float>(kPi);
constexpr float kDegToRad = kPiF / 180.f;

constexpr double kInf = std::numeric_limits<double>::infinity();

// FramePoints keeps the eye at least this fraction of the set's size before the nearest point:
// a set with no extent across the view (one point, a segment along the view axis) would
// otherwise put the eye on a point.
constexpr double kMinStandoff = 0.05;

// The view direction (from the scene towards the eye) of the automatic cameras: 30 degrees
// around Y from the front (+Z), 20 degrees above the horizon.
glm::dvec3 ThreeQuarterDirection() {
  const double azimuth = 30.0 * double(kDegToRad), elevation = 20.0 * double(kDegToRad);
  return glm::dvec3(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                    std::cos(azimuth) * std::cos(elevation));
}

// Diagonal of the points' bounding box, or 1 when they all coincide.
double Size(const std::vector<glm::vec3>& points) {
  glm::dvec3 lo(kInf), hi(-kInf);
  for (const glm::vec3& p : points) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
  const double size = glm::length(hi - lo);
  return size > 0.0 && std::isfinite(size) ? size : 1.0;
}

// The lateral eye offset e that centres the image of points (lateral l_i, depth d_i > 0 from
// the eye) on one axis: max_i (l_i - e) / d_i = -min_i (l_i - e) / d_i. Their sum falls as e
// grows, is >= 0 at e = min l and <= 0 at e = max l, so bisection finds it; the fixed number
// of halvings (down to adjacent doubles) keeps the result deterministic.
double CentreOffset(const std::vector<double>& lateral, const std::vector<double>& depth) {
  double lo = *std::min_element(lateral.begin(), lateral.end());
  double hi = *std::max_element(lateral.begin(), lateral.end());
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    double most = -kInf, least = kInf;
    for (std::size_t i = 0; i < lateral.size(); ++i) {
      const double t = (lateral[i] - mid) / depth[i];
      most = std::max(most, t), least = std::min(least, t);
    }
    (most + least > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

bool Finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

void CheckCamera(const Camera& c) {
  if (!Finite(c.eye) || !Finite(c.target) || !Finite(c.up))
    throw Error("camera: non-finite coordinates (expected finite --eye, --target, --up)");
  const glm::vec3 view = c.target - c.eye;
  if (glm::length(view) <= 0.f)
    throw Error("--eye: equals --target (expected two different points)");
  if (glm::length(c.up) <= 0.f ||
      glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-6f)
    throw Error("--up: parallel to the view direction (expected a vector not along --target - --eye)");
  if (!(c.fov_deg > 0.f && c.fov_deg < 180.f))
    throw Error("--fov: " + std::to_string(c.fov_deg) + " degrees (expected between 0 and 180)");
  if (!(c.near_plane > 0.f && c.far_plane > c.near_plane))
    throw Error("camera: bad clip planes (expected 0 < near < far)");
}

glm::mat4 ViewMatrix(const Camera& c) { return glm::lookAt(c.eye, c.target, c.up); }

glm::mat4 ProjectionMatrix(const Camera& c, float aspect) {
  return glm::perspective(c.fov_deg * kDegToRad, aspect, c.near_plane, c.far_plane);
}

glm::vec3 ViewRays::Direction(float ndc_x, float ndc_y) const {
  return glm::normalize(forward + ndc_x * right + ndc_y * up);
}

ViewRays MakeViewRays(const Camera& c, float aspect) {
  // Same basis as glm::lookAt: forward f, right s, true up u; the image plane at distance 1.
  const glm::vec3 f = glm::normalize(c.target - c.eye);
  const glm::vec3 s = glm::normalize(glm::cross(f, c.up));
  const glm::vec3 u = glm::cross(s, f);
  const float t = std::tan(0.5f * c.fov_deg * kDegToRad);
  ViewRays rays;
  rays.forward = f;
  rays.right = (t * aspect) * s;
  rays.up = t * u;
  return rays;
}

glm::vec3 ViewDirection(const Camera& c, float aspect, float ndc_x, float ndc_y) {
  return MakeViewRays(c, aspect).Direction(ndc_x, ndc_y);
}

Camera FitClipPlanes(Camera camera, const glm::vec3& min, const glm::vec3& max) {
  const glm::vec3 centre = 0.5f * (min + max), half = 0.5f * (max - min);
  float radius = glm::length(half);
  if (!(radius > 0.f)) radius = 1.f;
  const glm::vec3 f = glm::normalize(camera.target - camera.eye);
  // Depth (along the view axis) of the box centre and of its nearest corner.
  const float depth = glm::dot(centre - camera.eye, f);
  const float nearest = depth - (std::abs(half.x * f.x) + std::abs(half.y * f.y) + std::abs(half.z * f.z));
  camera.near_plane = std::max(0.5f * nearest, 1e-3f * radius);
  camera.far_plane = std::max(depth + 2.f * radius, 2.f * camera.near_plane);
  return camera;
}

Camera FrameBounds(const glm::vec3& min, const glm::vec3& max, float aspect) {
  Camera c;
  const glm::vec3 centre = 0.5f * (min + max);
  float radius = 0.5f * glm::length(max - min);
  if (!(radius > 0.f)) radius = 1.f;
  // 3/4 view: 30 degrees around Y from the front (+Z), 20 degrees above the horizon (computed
  // in float as always, so that cameras and golden images stay bit for bit the same).
  const float azimuth = 30.f * kDegToRad, elevation = 20.f * kDegToRad;
  const glm::vec3 dir(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                      std::cos(azimuth) * std::cos(elevation));
  // The sphere fits when distance * sin(half angle) >= radius for the narrower half angle.
  const float half_v = 0.5f * c.fov_deg * kDegToRad;
  const float half_h = std::atan(std::tan(half_v) * std::max(aspect, 1e-3f));
  const float distance = 1.05f * radius / std::sin(std::min(half_v, half_h));
  c.target = centre;
  c.eye = centre + distance * dir;
  c.up = glm::vec3(0.f, 1.f, 0.f);
  return FitClipPlanes(c, min, max);
}

Camera FramePoints(const std::vector<glm::vec3>& points, float aspect, float fov_deg) {
  const std::vector<glm::vec3> origin{glm::vec3(0.f)};
  const std::vector<glm::vec3>& pts = points.empty() ? origin : points;
  const std::size_t n = pts.size();
  // Camera basis as glm::lookAt builds it: forward f, right s, true up u.
  const glm::dvec3 f = -ThreeQuarterDirection();
  const glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 u = glm::cross(s, f);
  const double tv = std::tan(0.5 * double(fov_deg) * double(kDegToRad)) / (1.0 + double(kFrameMargin));
  const double th = tv * double(std::max(aspect, 1e-6f));

  // Points in the camera basis, and the closed form of camera.h for each axis.
  std::vector<double> x(n), y(n), z(n);
  double a = -kInf, b = -kInf, c = -kInf, d = -kInf, z_min = kInf, z_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 p(pts[i]);
    x[i] = glm::dot(p, s), y[i] = glm::dot(p, u), z[i] = glm::dot(p, f);
    a = std::max(a, x[i] - th * z[i]), b = std::max(b, -x[i] - th * z[i]);
    c = std::max(c, y[i] - tv * z[i]), d = std::max(d, -y[i] - tv * z[i]);
    z_min = std::min(z_min, z[i]), z_sum += z[i];
  }
  const double z_x = -(a + b) / (2.0 * th), z_y = -(c + d) / (2.0 * tv);
  // The farther depth; never nearer than kMinStandoff of the set's size to the nearest point.
  const double z_floor = z_min - kMinStandoff * Size(pts);
  const double z_e = std::min({z_x, z_y, z_floor});

  // Lateral offsets: the closed form on the axis that set the depth, solved again on the other.
  std::vector<double> depth(n);
  for (std::size_t i = 0; i < n; ++i) depth[i] = z[i] - z_e;
  const double x_e = z_e == z_x ? 0.5 * (a - b) : CentreOffset(x, depth);
  const double y_e = z_e == z_y ? 0.5 * (c - d) : CentreOffset(y, depth);

  Camera camera;
  camera.fov_deg = fov_deg;
  camera.up = glm::vec3(0.f, 1.f, 0.f);
  const glm::dvec3 eye = x_e * s + y_e * u + z_e * f;
  camera.eye = glm::vec3(eye);
  camera.target = glm::vec3(eye + (z_sum / double(n) - z_e) * f);
  glm::vec3 lo = pts[0], hi = pts[0];
  for (const glm::vec3& p : pts) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return FitClipPlanes(camera, lo, hi);
}

std::string CameraArgs(const Camera& c) {
  const auto vec = [](const glm::vec3& v) {
    return ShortestFloat(v.x) + "," + ShortestFloat(v.y) + "," + ShortestFloat(v.z);
  };
  return "--eye " + vec(c.eye) + " --target " + vec(c.target) + " --up " + vec(c.up) + " --fov " +
         ShortestFloat(c.fov_deg);
}

Camera Orbit(const Camera& camera, double degrees, const glm::vec3& min, const glm::vec3& max) {
  if (degrees == 0.0) return camera;
  const glm::dvec3 axis = glm::normalize(glm::dvec3(camera.up));
  const glm::dvec3 offset = glm::dvec3(camera.eye - camera.target);
  const double a = degrees * kPi / 180.0;
  // Rodrigues' rotation of the offset about the axis.
  const glm::dvec3 turned = offset * std::cos(a) + glm::cross(axis, offset) * std::sin(a) +
                            axis * glm::dot(axis, offset) * (1.0 - std::cos(a));
  Camera c = camera;
  c.eye = camera.target + glm::vec3(turned);
  return FitClipPlanes(c, min, max);
}

}  // namespace prt
