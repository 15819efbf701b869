#include "raster/camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"

namespace prt {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kDegToRad = kPi / 180.f;

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
  const glm::vec3 centre = 0.5f * (min + max);
  float radius = 0.5f * glm::length(max - min);
  if (!(radius > 0.f)) radius = 1.f;
  const glm::vec3 f = glm::normalize(camera.target - camera.eye);
  // Depth (along the view axis) of the bounding sphere's nearest and farthest points.
  const float depth = glm::dot(centre - camera.eye, f);
  camera.near_plane = std::max(0.5f * (depth - radius), 1e-3f * radius);
  camera.far_plane = std::max(depth + 2.f * radius, 2.f * camera.near_plane);
  return camera;
}

Camera FrameBounds(const glm::vec3& min, const glm::vec3& max, float aspect) {
  Camera c;
  const glm::vec3 centre = 0.5f * (min + max);
  float radius = 0.5f * glm::length(max - min);
  if (!(radius > 0.f)) radius = 1.f;
  // 3/4 view: 30 degrees around Y from the front (+Z), 20 degrees above the horizon.
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

std::string CameraArgs(const Camera& c) {
  // %.9g round-trips every float exactly.
  char buffer[320];
  std::snprintf(buffer, sizeof buffer,
                "--eye %.9g,%.9g,%.9g --target %.9g,%.9g,%.9g --up %.9g,%.9g,%.9g --fov %.9g",
                double(c.eye.x), double(c.eye.y), double(c.eye.z), double(c.target.x),
                double(c.target.y), double(c.target.z), double(c.up.x), double(c.up.y),
                double(c.up.z), double(c.fov_deg));
  return buffer;
}

}  // namespace prt
