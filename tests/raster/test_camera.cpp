#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "core/constants.h"
#include "core/error.h"
#include "core/rng.h"
#include "io/obj_loader.h"
#include "raster/camera.h"
#include "tests/test_support.h"

namespace {

// FramePoints computes in double but hands back a float camera, and the projection below runs in
// float: the eye, target and each product round at about 1e-7 relative, a few ulps of NDC.
// 1e-4 NDC (0.05 pixel on a 1000-pixel side) is far above that and far below a misfit.
constexpr float kNdcTolerance = 1e-4f;

// Extremes of the points' projection (NDC) and the nearest depth, for one camera and aspect.
struct Projected {
  glm::vec2 lo{1e30f}, hi{-1e30f};
  float nearest_w = 1e30f;
  bool finite = true;
};

Projected Project(const prt::Camera& c, float aspect, const std::vector<glm::vec3>& points) {
  const glm::mat4 m = prt::ProjectionMatrix(c, aspect) * prt::ViewMatrix(c);
  Projected r;
  for (const glm::vec3& p : points) {
    const glm::vec4 clip = m * glm::vec4(p, 1.f);
    const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
    r.finite = r.finite && std::isfinite(ndc.x) && std::isfinite(ndc.y);
    r.lo = glm::min(r.lo, ndc), r.hi = glm::max(r.hi, ndc);
    r.nearest_w = std::min(r.nearest_w, clip.w);
  }
  return r;
}

std::vector<glm::vec3> BoxCorners(const glm::vec3& lo, const glm::vec3& hi) {
  std::vector<glm::vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
  return corners;
}

// Deterministic points in [0, 1)^3.
std::vector<glm::vec3> Scatter(int n, std::uint64_t seed) {
  prt::Pcg32 rng(seed, 0);
  std::vector<glm::vec3> points;
  for (int i = 0; i < n; ++i) {
    const float x = float(rng.NextDouble()), y = float(rng.NextDouble()), z = float(rng.NextDouble());
    points.emplace_back(x, y, z);
  }
  return points;
}

}  // namespace

TEST_SUITE("raster") {
  TEST_CASE("FrameBounds shows the whole box from the front, above and to the right") {
    for (float aspect : {0.5f, 1.f, 16.f / 9.f}) {
      const glm::vec3 lo(-1.f, 0.f, -0.5f), hi(1.f, 3.4f, 0.5f);
      const prt::Camera c = prt::FrameBounds(lo, hi, aspect);
      CHECK(c.eye.z > hi.z);
      CHECK(c.eye.x > 0.f);
      CHECK(c.eye.y > 0.5f * (lo.y + hi.y));
      const glm::mat4 m = prt::ProjectionMatrix(c, aspect) * prt::ViewMatrix(c);
      for (const glm::vec3& p : BoxCorners(lo, hi)) {
        const glm::vec4 clip = m * glm::vec4(p, 1.f);
        CHECK(clip.w > c.near_plane);
        CHECK(clip.w < c.far_plane);
        CHECK(std::abs(clip.x / clip.w) < 1.f);
        CHECK(std::abs(clip.y / clip.w) < 1.f);
      }
    }
  }

  TEST_CASE("FramePoints fits the projected points exactly, centred, for any aspect") {
    const float edge = 1.f / (1.f + prt::kFrameMargin);
    std::vector<glm::vec3> floor;  // a wide flat set: a 10 x 6 floor with a small box on it
    for (int i = 0; i <= 10; ++i)
      for (int k = 0; k <= 6; ++k) floor.emplace_back(float(i) - 5.f, 0.f, float(k) - 3.f);
    for (const glm::vec3& p : BoxCorners({1.f, 0.f, 0.f}, {2.f, 1.f, 1.f})) floor.push_back(p);
    std::vector<glm::vec3> lopsided = Scatter(200, 7u);  // a cluster and two far outliers
    lopsided.emplace_back(6.f, 0.5f, -2.f);
    lopsided.emplace_back(-1.f, 4.f, 3.f);
    const std::vector<std::vector<glm::vec3>> sets = {
        BoxCorners({-0.3f, 0.f, -0.2f}, {0.3f, 3.4f, 0.2f}),  // tall and thin
        floor, lopsided};
    for (const auto& points : sets)
      for (float aspect : {0.36f, 1.f, 2.5f}) {
        CAPTURE(aspect);
        CAPTURE(points.size());
        const prt::Camera c = prt::FramePoints(points, aspect);
        CHECK_NOTHROW(prt::CheckCamera(c));
        CHECK(c.up == glm::vec3(0.f, 1.f, 0.f));
        const Projected r = Project(c, aspect, points);
        REQUIRE(r.finite);
        CHECK(r.nearest_w > c.near_plane);
        // Inside, and centred on both axes.
        CHECK(std::max(r.hi.x, -r.lo.x) <= edge + kNdcTolerance);
        CHECK(std::max(r.hi.y, -r.lo.y) <= edge + kNdcTolerance);
        CHECK(std::abs(r.hi.x + r.lo.x) <= kNdcTolerance);
        CHECK(std::abs(r.hi.y + r.lo.y) <= kNdcTolerance);
        // Tight: on the tighter axis the image reaches the margin on both sides.
        const bool x_tight = std::abs(r.hi.x - edge) <= kNdcTolerance && std::abs(r.lo.x + edge) <= kNdcTolerance;
        const bool y_tight = std::abs(r.hi.y - edge) <= kNdcTolerance && std::abs(r.lo.y + edge) <= kNdcTolerance;
        CHECK((x_tight || y_tight));
        // Same view direction as FrameBounds: from the front-right, above.
        const glm::vec3 back = glm::normalize(c.eye - c.target);
        CHECK(back.x > 0.f);
        CHECK(back.y > 0.f);
        CHECK(back.z > 0.f);
        // Deterministic.
        const prt::Camera again = prt::FramePoints(points, aspect);
        CHECK(again.eye == c.eye);
        CHECK(again.target == c.target);
        CHECK(again.near_plane == c.near_plane);
        CHECK(again.far_plane == c.far_plane);
      }
  }

  TEST_CASE("FramePoints fills a tall frame with a standing figure where FrameBounds does not") {
    // Mary's bounds (games202 mary.obj, rounded): 3.41 tall, 1.89 wide, 1.87 deep; 360 x 1000.
    const glm::vec3 lo(-0.94f, 0.f, -1.16f), hi(0.94f, 3.41f, 0.71f);
    const std::vector<glm::vec3> corners = BoxCorners(lo, hi);
    const float aspect = 0.36f;
    const Projected framed = Project(prt::FramePoints(corners, aspect), aspect, corners);
    const Projected sphere = Project(prt::FrameBounds(lo, hi, aspect), aspect, corners);
    // Filled: 1 / (1 + margin) of the frame on the tighter axis.
    const float framed_fill = std::max(framed.hi.x - framed.lo.x, framed.hi.y - framed.lo.y) / 2.f;
    const float sphere_fill = std::max(sphere.hi.x - sphere.lo.x, sphere.hi.y - sphere.lo.y) / 2.f;
    MESSAGE("box of mary's size in 360 x 1000: FramePoints fills " << (framed.hi.y - framed.lo.y) / 2.f
            << " of the height and " << (framed.hi.x - framed.lo.x) / 2.f << " of the width; FrameBounds "
            << (sphere.hi.y - sphere.lo.y) / 2.f << " and " << (sphere.hi.x - sphere.lo.x) / 2.f);
    CHECK(framed_fill >= 1.f / (1.f + prt::kFrameMargin) - kNdcTolerance);
    CHECK(framed_fill > 1.5f * sphere_fill);
  }

  TEST_CASE("FramePoints frames the course's mary tightly" * prt::test::NeedsSharedData()) {
    const std::string data = *prt::test::SharedData();
    const std::vector<glm::vec3> mary = prt::LoadObj(data + "/games202/mary/mary.obj").mesh.positions;
    REQUIRE(mary.size() > 1000);
    const float aspect = 360.f / 1000.f;
    const Projected r = Project(prt::FramePoints(mary, aspect), aspect, mary);
    const Projected old = [&] {
      glm::vec3 lo(1e30f), hi(-1e30f);
      for (const glm::vec3& p : mary) lo = glm::min(lo, p), hi = glm::max(hi, p);
      return Project(prt::FrameBounds(lo, hi, aspect), aspect, mary);
    }();
    MESSAGE("mary in 360 x 1000: FramePoints fills " << (r.hi.y - r.lo.y) / 2.f << " of the height and "
                                                      << (r.hi.x - r.lo.x) / 2.f << " of the width; FrameBounds "
                                                      << (old.hi.y - old.lo.y) / 2.f << " and " << (old.hi.x - old.lo.x) / 2.f);
    const float edge = 1.f / (1.f + prt::kFrameMargin);
    CHECK(std::max(r.hi.x - r.lo.x, r.hi.y - r.lo.y) / 2.f >= edge - kNdcTolerance);
    CHECK(std::max({r.hi.x, -r.lo.x, r.hi.y, -r.lo.y}) <= edge + kNdcTolerance);
  }

  TEST_CASE("FramePoints survives degenerate sets without NaN") {
    const glm::vec3 f = -glm::normalize(prt::FrameBounds(glm::vec3(-1.f), glm::vec3(1.f), 1.f).eye);
    const glm::vec3 s = glm::normalize(glm::cross(f, glm::vec3(0.f, 1.f, 0.f)));
    std::vector<glm::vec3> edge_on, along_view;  // a plane containing the view direction; a segment along it
    for (int i = 0; i <= 4; ++i)
      for (int k = 0; k <= 4; ++k) edge_on.push_back(float(i) * f + float(k) * s);
    for (int i = 0; i <= 4; ++i) along_view.push_back(glm::vec3(1.f, 2.f, 3.f) + float(i) * f);
    const std::vector<std::vector<glm::vec3>> sets = {
        {}, {glm::vec3(1.f, 2.f, 3.f)}, {glm::vec3(-4.f), glm::vec3(-4.f), glm::vec3(-4.f)}, edge_on, along_view};
    for (const auto& points : sets)
      for (float aspect : {0.36f, 1.f, 2.5f}) {
        CAPTURE(points.size());
        const prt::Camera c = prt::FramePoints(points, aspect);
        REQUIRE_NOTHROW(prt::CheckCamera(c));
        const Projected r = Project(c, aspect, points.empty() ? std::vector<glm::vec3>{glm::vec3(0.f)} : points);
        CHECK(r.finite);
        CHECK(r.nearest_w > c.near_plane);
        CHECK(std::max({r.hi.x, -r.lo.x, r.hi.y, -r.lo.y}) <= 1.f);
      }
  }

  TEST_CASE("FitClipPlanes keeps the box in front of the near plane, even from inside it") {
    const glm::vec3 lo(-5.f, -1.f, -5.f), hi(5.f, 2.f, 5.f);
    prt::Camera c;
    c.eye = glm::vec3(0.f, 3.f, 7.f), c.target = glm::vec3(0.f, 0.8f, 0.f);
    c = prt::FitClipPlanes(c, lo, hi);
    const glm::vec3 f = glm::normalize(c.target - c.eye);
    float nearest = 1e30f;
    for (const glm::vec3& p : BoxCorners(lo, hi)) nearest = std::min(nearest, glm::dot(p - c.eye, f));
    // Half the nearest corner's depth (the bounding sphere reaches much nearer).
    CHECK(c.near_plane == doctest::Approx(0.5f * nearest).epsilon(1e-5));
    CHECK(c.far_plane > c.near_plane);
    // A camera inside the box still gets a positive near plane.
    c.eye = glm::vec3(0.f), c.target = glm::vec3(0.f, 0.f, -1.f);
    c = prt::FitClipPlanes(c, lo, hi);
    CHECK(c.near_plane > 0.f);
    CHECK_NOTHROW(prt::CheckCamera(c));
  }

  TEST_CASE("CameraArgs prints the command-line syntax") {
    prt::Camera c;
    c.eye = glm::vec3(0.f, 8.f, 22.f);
    c.target = glm::vec3(0.f, 1.f, 1.f);
    c.fov_deg = 40.f;
    CHECK(prt::CameraArgs(c) == "--eye 0,8,22 --target 0,1,1 --up 0,1,0 --fov 40");
    c.eye = glm::vec3(6.f, 3.2f, -0.1f);
    CHECK(prt::CameraArgs(c).rfind("--eye 6,3.2,-0.1 ", 0) == 0);  // not 3.20000005
  }

  TEST_CASE("CheckCamera names the option at fault") {
    prt::Camera c;
    c.up = glm::vec3(0.f, 0.f, 1.f);  // along the view direction (0, 0, -5)
    CHECK_THROWS_WITH_AS(prt::CheckCamera(c), doctest::Contains("--up"), prt::Error);
    c = prt::Camera();
    c.fov_deg = 180.f;
    CHECK_THROWS_WITH_AS(prt::CheckCamera(c), doctest::Contains("--fov"), prt::Error);
    c = prt::Camera();
    c.target = c.eye;
    CHECK_THROWS_WITH_AS(prt::CheckCamera(c), doctest::Contains("--eye"), prt::Error);
  }

  TEST_CASE("Orbit turns the eye right-handedly about the up line through the target, keeping its distance") {
    prt::Camera c;
    c.target = glm::vec3(1.0f, 2.0f, 3.0f);
    c.eye = c.target + glm::vec3(0.0f, 1.0f, 5.0f);
    c.up = glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 lo(-1.0f), hi(1.0f);
    // About +Y, +Z turns toward +X by a quarter turn: (0, 1, 5) -> (5, 1, 0).
    const prt::Camera q = prt::Orbit(c, 90.0, lo, hi);
    CHECK(glm::length(q.eye - c.target - glm::vec3(5.0f, 1.0f, 0.0f)) < 1e-5f);
    CHECK(q.target == c.target);
    for (double degrees : {-30.0, 45.0, 200.0, 720.0}) {
      const prt::Camera o = prt::Orbit(c, degrees, lo, hi);
      CHECK(glm::length(o.eye - o.target) == doctest::Approx(glm::length(c.eye - c.target)).epsilon(1e-6));
      CHECK(o.eye.y == doctest::Approx(c.eye.y).epsilon(1e-6));  // the height along up is kept
      const double a = std::atan2(double(o.eye.x - c.target.x), double(o.eye.z - c.target.z)) * 180.0 / prt::kPi;
      CHECK(std::remainder(a - degrees, 360.0) == doctest::Approx(0.0).epsilon(1e-4).scale(1.0));
    }
    CHECK(prt::Orbit(c, 0.0, lo, hi).eye == c.eye);
  }
}
