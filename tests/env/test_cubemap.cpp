#include <doctest/doctest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/rng.h"
#include "env/cube_faces.h"
#include "env/cubemap.h"
#include "tests/env/env_test_util.h"

using namespace prt;

namespace {
constexpr double kFourPi = 4.0 * kPi;
// Exact texel solid angles sum to 4 pi up to rounding.
constexpr double kSolidAngleSumTolerance = 1e-12;

/// A standard cube of size^2 faces whose texels hold their own (face, row, column).
CubemapEnvironment IndexCube(int size) {
  std::array<ImageF, 6> faces;
  for (int k = 0; k < 6; ++k) {
    faces[k] = ImageF(size, size);
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) faces[k].at(col, row) = glm::vec3(float(k), float(row), float(col));
  }
  return CubemapEnvironment(std::move(faces), CubeLayout::kStandard, "index cube");
}
}  // namespace

TEST_SUITE("env") {
  TEST_CASE("cube texel solid angles sum to 4 pi for any face size") {
    for (int size : {1, 2, 3, 17, 64, 256, 1000}) {
      double sum = 0.0;
      for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col) sum += TexelSolidAngle(col, row, size);
      CHECK(std::abs(6.0 * sum - kFourPi) < kSolidAngleSumTolerance);
    }
    // Corner texels are about 5.2x smaller than centre ones (CONVENTIONS.md), at 512^2.
    const double ratio = TexelSolidAngle(256, 256, 512) / TexelSolidAngle(0, 0, 512);
    CHECK(ratio == doctest::Approx(5.2).epsilon(0.01));
  }

  TEST_CASE("face frames are orthonormal and right-handed (N = U x V reversed per OpenGL)") {
    for (CubeLayout layout : {CubeLayout::kStandard, CubeLayout::kGames202}) {
      glm::dvec3 normal_sum(0.0);
      for (const FaceFrame& f : FaceFrames(layout)) {
        CHECK(glm::dot(f.n, f.u) == 0.0);
        CHECK(glm::dot(f.n, f.v) == 0.0);
        CHECK(glm::dot(f.u, f.v) == 0.0);
        normal_sum += f.n;
      }
      CHECK(glm::length(normal_sum) == 0.0);  // the six faces cover the six axis directions
    }
    // The standard table is the OpenGL layout: the faces' (U, V) frames are all left-handed
    // with N, i.e. cross(U, V) = -N; the course's mirrored posx breaks that.
    for (const FaceFrame& f : FaceFrames(CubeLayout::kStandard)) CHECK(glm::cross(f.u, f.v) == -f.n);
    CHECK(glm::cross(FaceFrames(CubeLayout::kGames202)[0].u, FaceFrames(CubeLayout::kGames202)[0].v) ==
          FaceFrames(CubeLayout::kGames202)[0].n);
  }

  TEST_CASE("the standard face table is OpenGL's: every texel centre of every face looks where the spec says") {
    // Faces of 6 texels whose values name (face, row, column): the lookup at the spec's direction
    // of a texel centre must return that texel. A swapped, mirrored or turned face fails.
    const int size = 6;
    const CubemapEnvironment env = IndexCube(size);
    for (int k = 0; k < 6; ++k)
      for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col) {
          const double s = (col + 0.5) / size, t = (row + 0.5) / size;
          const glm::dvec3 d = test::OpenGlCubeDirection(k, s, t);
          const test::CubeTexel back = test::OpenGlCubeTexel(d);  // the test's table is self-consistent
          REQUIRE(back.face == k);
          REQUIRE(std::abs(back.s - s) < 1e-12);
          REQUIRE(std::abs(back.t - t) < 1e-12);
          CAPTURE(k);
          CAPTURE(row);
          CAPTURE(col);
          CHECK(glm::length(env.Radiance(glm::normalize(d)) - glm::dvec3(k, row, col)) < 1e-9);
        }
    // The quadrature nodes the projection sums over sit at the same texels, with their values.
    std::vector<Texel> texels;
    for (std::size_t r = 0; r < env.RowCount(); ++r) {
      env.Row(r, texels);
      REQUIRE(texels.size() == std::size_t(size));
      for (int col = 0; col < size; ++col) {
        const test::CubeTexel at = test::OpenGlCubeTexel(texels[col].dir);
        CAPTURE(r);
        CAPTURE(col);
        CHECK(at.face == int(r / size));
        CHECK(int(at.t * size) == int(r % size));
        CHECK(int(at.s * size) == col);
        CHECK(glm::length(glm::dvec3(texels[col].radiance) - glm::dvec3(at.face, r % size, col)) == 0.0);
      }
    }
    // And the faces' named axes: +Y is up (posy), -Z is forward (negz).
    CHECK(env.Radiance({0, 1, 0}).x == 2.0);
    CHECK(env.Radiance({0, 0, -1}).x == 5.0);
  }

  TEST_CASE("the course's face table is the standard one with posy/negy and posz/negz swapped and posx mirrored") {
    // CONVENTIONS.md's account of the course's precompute code, which its published light.txt
    // files follow (checked against them by the tests that need the course data).
    const auto& standard = FaceFrames(CubeLayout::kStandard);
    const auto& course = FaceFrames(CubeLayout::kGames202);
    const auto same = [](const FaceFrame& a, const FaceFrame& b) { return a.n == b.n && a.u == b.u && a.v == b.v; };
    CHECK(course[0].n == standard[0].n);
    CHECK(course[0].u == -standard[0].u);  // posx mirrored
    CHECK(course[0].v == standard[0].v);
    CHECK(same(course[1], standard[1]));  // negx as is
    CHECK(same(course[2], standard[3]));  // posy given negy's frame
    CHECK(same(course[3], standard[2]));
    CHECK(same(course[4], standard[5]));  // posz given negz's frame
    CHECK(same(course[5], standard[4]));
  }

  TEST_CASE("Radiance() looks up the texel a direction falls in") {
    // Each texel holds its own index, so a lookup at its centre must return that index.
    const int size = 8;
    const CubemapEnvironment env = IndexCube(size);
    std::vector<Texel> texels;
    for (std::size_t r = 0; r < env.RowCount(); ++r) {
      env.Row(r, texels);
      for (int col = 0; col < size; ++col) {
        // Bilinear weights at a texel centre are 1 and 0 up to rounding of the coordinates.
        const glm::dvec3 v = env.Radiance(texels[col].dir);
        CHECK(glm::length(v - glm::dvec3(double(r / size), double(r % size), double(col))) < 1e-9);
      }
    }
  }
}
