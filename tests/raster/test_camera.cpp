#include <doctest/doctest.h>

#include <glm/mat4x4.hpp>

#include "core/error.h"
#include "raster/camera.h"

TEST_SUITE("raster") {
  TEST_CASE("FrameBounds shows the whole box from the front, above and to the right") {
    for (float aspect : {0.5f, 1.f, 16.f / 9.f}) {
      const glm::vec3 lo(-1.f, 0.f, -0.5f), hi(1.f, 3.4f, 0.5f);
      const prt::Camera c = prt::FrameBounds(lo, hi, aspect);
      CHECK(c.eye.z > hi.z);
      CHECK(c.eye.x > 0.f);
      CHECK(c.eye.y > 0.5f * (lo.y + hi.y));
      const glm::mat4 m = prt::ProjectionMatrix(c, aspect) * prt::ViewMatrix(c);
      for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
        const glm::vec4 clip = m * glm::vec4(p, 1.f);
        CHECK(clip.w > c.near_plane);
        CHECK(clip.w < c.far_plane);
        CHECK(std::abs(clip.x / clip.w) < 1.f);
        CHECK(std::abs(clip.y / clip.w) < 1.f);
      }
    }
  }

  TEST_CASE("CameraArgs prints the command-line syntax") {
    prt::Camera c;
    c.eye = glm::vec3(0.f, 8.f, 22.f);
    c.target = glm::vec3(0.f, 1.f, 1.f);
    c.fov_deg = 40.f;
    CHECK(prt::CameraArgs(c) == "--eye 0,8,22 --target 0,1,1 --up 0,1,0 --fov 40");
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
}
