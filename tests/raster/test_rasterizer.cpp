// The whole rasterizer on scenes with an analytic answer: vertex colours, perspective-correct
// interpolation, depth order, near-plane clipping, supersampling, background, determinism.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "core/parallel.h"
#include "geometry/procedural.h"
#include "raster/rasterizer.h"
#include "tests/test_support.h"

namespace {

using prt::Camera;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// Float planes evaluated a few hundred pixels from their anchor: a few ulps of 1/w and
// colour/w, relative, before the division.
constexpr float kColourTolerance = 2e-5f;
// The perspective quad spans a 10:1 depth ratio, which amplifies the relative float error of
// the 1/w and colour/w planes about tenfold near the far edge.
constexpr float kPerspectiveTolerance = 2e-4f;

// Eye at the origin looking down -Z, 90 degree vertical fov, square image: a point
// (X, Y, -d) lands on screen at x = (X / d + 1) * size / 2, y = (1 - Y / d) * size / 2.
Camera AxisCamera(float near_plane = 0.1f) {
  Camera c;
  c.eye = glm::vec3(0.f);
  c.target = glm::vec3(0.f, 0.f, -1.f);
  c.up = glm::vec3(0.f, 1.f, 0.f);
  c.fov_deg = 90.f;
  c.near_plane = near_plane;
  return c;
}

// The world point at depth d seen at screen position (x, y) by AxisCamera on a size x size image.
float F(int v) { return static_cast<float>(v); }

glm::vec3 AtScreen(float x, float y, float d, int size) {
  return glm::vec3((2.f * x / F(size) - 1.f) * d, (1.f - 2.f * y / F(size)) * d, -d);
}

}  // namespace

TEST_SUITE("raster") {
  TEST_CASE("Colours at pixel centres on vertices equal the vertex colours") {
    // A 3 x 3 grid of vertices on pixel centres, each at its own depth and colour, as 8
    // triangles. Every vertex pixel that is covered must show exactly its vertex colour.
    const int size = 64;
    std::vector<glm::vec3> positions, colors;
    std::vector<std::array<int, 2>> pixel;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const int px = 10 + 20 * i, py = 12 + 19 * j;
        const float depth = 1.f + 0.7f * F((i * 5 + j * 3) % 7);
        positions.push_back(AtScreen(F(px) + 0.5f, F(py) + 0.5f, depth, size));
        colors.push_back(glm::vec3(0.1f * F(i + 1), 0.3f * F(j) + 0.05f, 0.9f - 0.1f * F(i + j)));
        pixel.push_back({px, py});
      }
    Triangles tris;
    for (std::uint32_t j = 0; j < 2; ++j)
      for (std::uint32_t i = 0; i < 2; ++i) {
        const std::uint32_t a = j * 3 + i, b = a + 1, c = a + 4, d = a + 3;
        tris.push_back({a, c, b});
        tris.push_back({a, d, c});
      }
    const auto frame = prt::Rasterize(AxisCamera(), size, size, positions, tris, colors);
    int checked = 0;
    for (std::size_t v = 0; v < positions.size(); ++v) {
      const auto [x, y] = pixel[v];
      if (frame.coverage[y * size + x] == 0.f) continue;
      const glm::vec3 got = frame.image.at(x, y);
      for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(colors[v][c]).epsilon(kColourTolerance));
      ++checked;
    }
    CHECK(checked >= 3);  // the centre, and the top-left corners of the grid at least
  }

  TEST_CASE("Interpolation across a foreshortened quad is perspective-correct") {
    // Floor y = -1 from depth 1 to 10; red grows linearly with depth along the floor.
    const int size = 96;
    const std::vector<glm::vec3> positions = {{-1, -1, -1}, {1, -1, -1}, {1, -1, -10}, {-1, -1, -10}};
    const std::vector<glm::vec3> colors = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 0}};
    const auto frame = prt::Rasterize(AxisCamera(), size, size, positions, {{0, 1, 2}, {0, 2, 3}}, colors);
    int checked = 0;
    float max_affine_gap = 0.f;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        // The ray through the pixel centre meets the floor at depth d = 1 / -ndc_y.
        const float ndc_x = 2.f * (F(x) + 0.5f) / F(size) - 1.f, ndc_y = 1.f - 2.f * (F(y) + 0.5f) / F(size);
        if (ndc_y >= 0.f) continue;
        const float d = -1.f / ndc_y, wx = ndc_x * d;
        if (d < 1.05f || d > 9.9f || std::fabs(wx) > 0.95f) continue;  // well inside the quad
        REQUIRE(frame.coverage[y * size + x] == 1.f);
        const float expected = (d - 1.f) / 9.f;
        CHECK(frame.image.at(x, y).x == doctest::Approx(expected).epsilon(kPerspectiveTolerance));
        // Screen-linear interpolation between the near and far edges would give this instead:
        const float y_near = (1.f + 1.f) * F(size) / 2.f, y_far = (1.f + 0.1f) * F(size) / 2.f;
        const float affine = (y_near - (F(y) + 0.5f)) / (y_near - y_far);
        max_affine_gap = std::max(max_affine_gap, std::fabs(affine - expected));
        ++checked;
      }
    CHECK(checked > 500);
    CHECK(max_affine_gap > 0.2f);  // so the test tells perspective from affine interpolation
  }

  TEST_CASE("Nearer triangles win regardless of drawing order") {
    const int size = 32;
    // Two interpenetrating triangles: A at constant depth 3, B tilted from depth 2 to 4.
    const std::vector<glm::vec3> positions = {
        AtScreen(2, 2, 3, size), AtScreen(30, 4, 3, size), AtScreen(6, 30, 3, size),
        AtScreen(30, 30, 2, size), AtScreen(2, 28, 2, size), AtScreen(16, 1, 4, size)};
    const std::vector<glm::vec3> colors = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    const auto ab = prt::Rasterize(AxisCamera(), size, size, positions, {{0, 1, 2}, {3, 4, 5}}, colors);
    const auto ba = prt::Rasterize(AxisCamera(), size, size, positions, {{3, 4, 5}, {0, 1, 2}}, colors);
    CHECK(ab.image.pixels == ba.image.pixels);
    // Where both cover, the one nearer along the pixel's ray shows: B is nearer low on screen.
    int red = 0, blue = 0;
    for (const auto& p : ab.image.pixels) red += p.x > 0.5f, blue += p.z > 0.5f;
    CHECK(red > 50);
    CHECK(blue > 50);
    // A separate pair, one entirely in front: the front one's colour wherever it covers.
    const std::vector<glm::vec3> pair = {AtScreen(0, 0, 5, size), AtScreen(32, 0, 5, size), AtScreen(0, 32, 5, size),
                                         AtScreen(0, 0, 2, size), AtScreen(32, 0, 2, size), AtScreen(0, 32, 2, size)};
    const auto back_first = prt::Rasterize(AxisCamera(), size, size, pair, {{0, 2, 1}, {3, 5, 4}}, colors);
    const auto front_first = prt::Rasterize(AxisCamera(), size, size, pair, {{3, 5, 4}, {0, 2, 1}}, colors);
    for (std::size_t i = 0; i < back_first.image.pixels.size(); ++i)
      if (back_first.coverage[i] > 0.f) {
        CHECK(back_first.image.pixels[i] == glm::vec3(0, 0, 1));
        CHECK(front_first.image.pixels[i] == glm::vec3(0, 0, 1));
      }
  }

  TEST_CASE("On an exact depth tie the triangle drawn first stays, however far apart in the list") {
    // Two coplanar screen-filling quads, red then blue, with 10,000 off-screen triangles between
    // them (the setup and binning work in chunks of thousands): red must stay everywhere, at
    // one sample per pixel and supersampled, for one thread and for three.
    const int size = 24;
    std::vector<glm::vec3> positions = {AtScreen(0, 0, 3, size), AtScreen(24, 0, 3, size),
                                        AtScreen(24, 24, 3, size), AtScreen(0, 24, 3, size)};
    std::vector<glm::vec3> colors(4, glm::vec3(1, 0, 0));
    for (int i = 0; i < 4; ++i) positions.push_back(positions[i]), colors.emplace_back(0, 0, 1);
    const std::uint32_t off = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), {{50, 50, -3}, {51, 50, -3}, {50, 51, -3}});  // far off to the right
    colors.insert(colors.end(), 3, glm::vec3(0, 1, 0));
    Triangles triangles = {{0, 2, 1}, {0, 3, 2}};
    for (int i = 0; i < 10000; ++i) triangles.push_back({off, off + 1, off + 2});
    triangles.push_back({4, 6, 5});
    triangles.push_back({4, 7, 6});
    for (int ssaa : {1, 2})
      for (int threads : {1, 3}) {
        prt::RasterOptions options;
        options.ssaa = ssaa;
        const auto frame = prt::test::WithThreads(threads, [&] {
          return prt::Rasterize(AxisCamera(), size, size, positions, triangles, colors, options);
        });
        for (const auto& p : frame.image.pixels) REQUIRE(p == glm::vec3(1, 0, 0));
      }
  }

  TEST_CASE("Triangles crossing the near plane are clipped, not dropped or wrapped") {
    // A floor quad y = -1 from 5 units behind the eye to 20 in front, near plane at 2: the
    // visible part is the floor between depths 2 and 20 within |x| <= 3.
    const int size = 80;
    const float near_plane = 2.f;
    const std::vector<glm::vec3> positions = {{-3, -1, 5}, {3, -1, 5}, {3, -1, -20}, {-3, -1, -20}};
    const std::vector<glm::vec3> colors(4, glm::vec3(1.f));
    const auto frame = prt::Rasterize(AxisCamera(near_plane), size, size, positions,
                                      {{0, 1, 2}, {0, 2, 3}}, colors);
    const auto inside = [&](float sx, float sy) {
      const float ndc_x = 2.f * sx / F(size) - 1.f, ndc_y = 1.f - 2.f * sy / F(size);
      if (ndc_y >= 0.f) return false;  // above the horizon: the floor is never seen there
      const float d = -1.f / ndc_y;
      return d >= near_plane && d <= 20.f && std::fabs(ndc_x * d) <= 3.f;
    };
    int covered = 0, empty = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        // Compare only where the answer is the same 0.6 pixels around the centre.
        const float cx = F(x) + 0.5f, cy = F(y) + 0.5f;
        const bool in = inside(cx, cy);
        if (inside(cx - 0.6f, cy) != in || inside(cx + 0.6f, cy) != in ||
            inside(cx, cy - 0.6f) != in || inside(cx, cy + 0.6f) != in)
          continue;
        CHECK_MESSAGE(frame.coverage[y * size + x] == (in ? 1.f : 0.f), "pixel " << x << "," << y);
        (in ? covered : empty) += 1;
      }
    CHECK(covered > 500);
    CHECK(empty > 1000);
  }

  TEST_CASE("Colour is interpolated at the near-plane cut: a world-linear colour stays exact up to the near plane") {
    // The floor of the clipping test, its colour linear in world position: r = (z + 20) / 25,
    // g = (x + 3) / 6. Perspective-correct interpolation reproduces a world-linear attribute
    // exactly, at every pixel, including those next to the near plane, whose triangles were cut
    // there: the cut points must carry the colour of where they lie on the edge.
    const int size = 80;
    const float near_plane = 2.f;
    const std::vector<glm::vec3> positions = {{-3, -1, 5}, {3, -1, 5}, {3, -1, -20}, {-3, -1, -20}};
    std::vector<glm::vec3> colors;
    for (const glm::vec3& p : positions) colors.emplace_back((p.z + 20.f) / 25.f, (p.x + 3.f) / 6.f, 0.25f);
    const auto frame = prt::Rasterize(AxisCamera(near_plane), size, size, positions, {{0, 1, 2}, {0, 2, 3}}, colors);
    int checked = 0, near_cut = 0;
    float worst = 0.f;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        if (frame.coverage[y * size + x] != 1.f) continue;
        const float ndc_x = 2.f * (F(x) + 0.5f) / F(size) - 1.f, ndc_y = 1.f - 2.f * (F(y) + 0.5f) / F(size);
        const float d = -1.f / ndc_y, world_x = ndc_x * d;
        const glm::vec3 expected((20.f - d) / 25.f, (world_x + 3.f) / 6.f, 0.25f);
        const glm::vec3 got = frame.image.at(x, y);
        worst = std::max({worst, std::fabs(got.x - expected.x), std::fabs(got.y - expected.y), std::fabs(got.z - expected.z)});
        ++checked;
        near_cut += d < 3.f;
      }
    CHECK(checked > 500);
    CHECK(near_cut > 50);  // rows just beyond the near plane are among them
    CHECK(worst < kPerspectiveTolerance);
  }

  TEST_CASE("Supersampling resolves partial coverage over the background") {
    // Left of screen x = 10.5 white, background blue: with 2 x 2 samples, column 10 is half
    // covered; without supersampling its centre lies on the edge (left edge: covered).
    const int size = 20;
    const std::vector<glm::vec3> positions = {AtScreen(-5, -5, 2, size), AtScreen(10.5f, -5, 2, size),
                                              AtScreen(10.5f, 40, 2, size), AtScreen(-5, 40, 2, size)};
    const std::vector<glm::vec3> colors(4, glm::vec3(1.f));
    prt::RasterOptions options;
    options.ssaa = 2;
    options.background.color = glm::vec3(0.f, 0.f, 1.f);
    const auto frame = prt::Rasterize(AxisCamera(), size, size, positions, {{0, 2, 1}, {0, 3, 2}}, colors, options);
    CHECK(frame.coverage[5 * size + 10] == 0.5f);
    CHECK(frame.image.at(10, 5) == glm::vec3(0.5f, 0.5f, 1.f));
    CHECK(frame.image.at(9, 5) == glm::vec3(1.f));
    CHECK(frame.image.at(11, 5) == glm::vec3(0.f, 0.f, 1.f));
  }

  TEST_CASE("The background callback sees world-space view directions") {
    prt::RasterOptions options;
    options.background.radiance = [](const glm::vec3& d) { return d; };
    const auto frame = prt::Rasterize(AxisCamera(), 9, 9, {}, {}, {}, options);
    const glm::vec3 centre = frame.image.at(4, 4), corner = frame.image.at(8, 0);
    CHECK(centre.z == doctest::Approx(-1.f));
    CHECK(corner.x > 0.4f);  // right
    CHECK(corner.y > 0.4f);  // top
    CHECK(frame.coverage[0] == 0.f);
  }

  TEST_CASE("Bad input is reported, not drawn") {
    const std::vector<glm::vec3> p = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
    CHECK_THROWS_AS(prt::Rasterize(AxisCamera(), 8, 8, p, {{0, 1, 3}}, p), prt::Error);
    CHECK_THROWS_AS(prt::Rasterize(AxisCamera(), 8, 8, p, {{0, 1, 2}}, {}), prt::Error);
    CHECK_THROWS_AS(prt::Rasterize(AxisCamera(), 0, 8, p, {{0, 1, 2}}, p), prt::Error);
    prt::RasterOptions bad;
    bad.ssaa = 9;
    CHECK_THROWS_AS(prt::Rasterize(AxisCamera(), 8, 8, p, {{0, 1, 2}}, p, bad), prt::Error);
  }
}
