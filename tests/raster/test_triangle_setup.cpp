// Coverage rules of triangle_setup.h, checked by counting how often each pixel is filled.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/rng.h"
#include "raster/triangle_setup.h"

namespace {

using prt::ScreenVertex;

// Times each pixel of a width x height target is filled by the given triangles.
struct CoverageCount {
  int width, height;
  std::vector<int> count;
  CoverageCount(int w, int h) : width(w), height(h), count(static_cast<std::size_t>(w) * h, 0) {}
  void Draw(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
    prt::RasterTriangle t;
    if (!prt::SetupTriangle(a, b, c, width, height, false, t)) return;
    prt::RowWalker rows(t, t.y_min);
    for (int y = t.y_min; y <= t.y_max; ++y) {
      const prt::Span s = rows.Next();
      for (int x = s.begin; x < s.end; ++x) ++count[static_cast<std::size_t>(y) * width + x];
    }
  }
  int Min() const { return *std::min_element(count.begin(), count.end()); }
  int Max() const { return *std::max_element(count.begin(), count.end()); }
};

float F(int v) { return static_cast<float>(v); }

float Uniform(prt::Pcg32& rng) { return static_cast<float>(rng.NextDouble()); }

ScreenVertex V(float x, float y) {
  ScreenVertex v;
  v.x = x;
  v.y = y;
  return v;
}

}  // namespace

TEST_SUITE("raster") {
  TEST_CASE("A full-screen quad of two triangles covers every pixel exactly once") {
    for (bool flip : {false, true}) {  // both diagonals, both windings
      CoverageCount cov(37, 23);
      const ScreenVertex a = V(0, 0), b = V(37, 0), c = V(37, 23), d = V(0, 23);
      if (flip) {
        cov.Draw(a, b, d);
        cov.Draw(d, b, c);
      } else {
        cov.Draw(a, c, b);
        cov.Draw(a, d, c);
      }
      CHECK(cov.Min() == 1);
      CHECK(cov.Max() == 1);
    }
  }

  TEST_CASE("The top-left rule: centres on top and left edges are in, on bottom and right out") {
    // Square with corners on pixel centres (0.5, 0.5) and (2.5, 2.5): 9 centres lie on it or in
    // it; the rule keeps the top row and left column, so exactly pixels x, y in {0, 1}.
    CoverageCount cov(4, 4);
    cov.Draw(V(0.5f, 0.5f), V(2.5f, 0.5f), V(2.5f, 2.5f));
    cov.Draw(V(0.5f, 0.5f), V(2.5f, 2.5f), V(0.5f, 2.5f));
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        CHECK_MESSAGE(cov.count[y * 4 + x] == (x < 2 && y < 2 ? 1 : 0), "pixel " << x << "," << y);
  }

  TEST_CASE("A fan around a shared vertex covers every pixel exactly once") {
    prt::Pcg32 rng(7, 1);
    for (int trial = 0; trial < 50; ++trial) {
      const int w = 29, h = 31;
      CoverageCount cov(w, h);
      // Centre at a random sub-pixel position; rim on a rectangle around the whole target.
      const ScreenVertex centre = V(1.f + Uniform(rng) * F(w - 2), 1.f + Uniform(rng) * F(h - 2));
      std::vector<ScreenVertex> rim;
      const int per_side = 3 + trial % 5;
      for (int i = 0; i < per_side; ++i) rim.push_back(V(-1.f + (F(w) + 2.f) * F(i) / F(per_side), -1.f));
      for (int i = 0; i < per_side; ++i) rim.push_back(V(F(w) + 1.f, -1.f + (F(h) + 2.f) * F(i) / F(per_side)));
      for (int i = 0; i < per_side; ++i) rim.push_back(V(F(w) + 1.f - (F(w) + 2.f) * F(i) / F(per_side), F(h) + 1.f));
      for (int i = 0; i < per_side; ++i) rim.push_back(V(-1.f, F(h) + 1.f - (F(h) + 2.f) * F(i) / F(per_side)));
      for (std::size_t i = 0; i < rim.size(); ++i) cov.Draw(centre, rim[i], rim[(i + 1) % rim.size()]);
      CHECK(cov.Min() == 1);
      CHECK(cov.Max() == 1);
    }
  }

  TEST_CASE("Shared edges at random sub-pixel offsets: no pixel drawn twice or skipped") {
    // A grid of quads over the whole target; inner vertices jittered by up to 0.15 cells (quads stay convex), so
    // shared edges pass at every sub-pixel offset, through pixel centres included (some
    // vertices are snapped to centres on purpose).
    prt::Pcg32 rng(11, 3);
    for (int trial = 0; trial < 40; ++trial) {
      const int w = 48, h = 40, cells = 6;
      std::vector<ScreenVertex> grid;
      for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
          float x = -1.f + (F(w) + 2.f) * F(i) / F(cells), y = -1.f + (F(h) + 2.f) * F(j) / F(cells);
          if (i > 0 && i < cells && j > 0 && j < cells) {
            x += (Uniform(rng) - 0.5f) * 0.3f * (F(w) / F(cells));
            y += (Uniform(rng) - 0.5f) * 0.3f * (F(h) / F(cells));
            if (Uniform(rng) < 0.3f) x = std::floor(x) + 0.5f, y = std::floor(y) + 0.5f;
          }
          grid.push_back(V(x, y));
        }
      CoverageCount cov(w, h);
      for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
          const auto& a = grid[j * (cells + 1) + i];
          const auto& b = grid[j * (cells + 1) + i + 1];
          const auto& c = grid[(j + 1) * (cells + 1) + i + 1];
          const auto& d = grid[(j + 1) * (cells + 1) + i];
          if ((i + j + trial) % 2) {
            cov.Draw(a, b, c);
            cov.Draw(a, c, d);
          } else {
            cov.Draw(a, b, d);
            cov.Draw(b, c, d);
          }
        }
      CHECK(cov.Min() == 1);
      CHECK(cov.Max() == 1);
    }
  }

  TEST_CASE("RowWalker finds RowSpan's spans, by stepping narrow triangles and dividing wide ones") {
    // Random triangles from under a pixel to three times kScanWidth across, partly off the target,
    // at random sub-pixel positions: every row's span must be RowSpan's (the reference, which
    // solves the three edge inequalities by division).
    prt::Pcg32 rng(5, 9);
    const int w = 120, h = 90;
    int narrow = 0, wide = 0;
    for (int trial = 0; trial < 3000; ++trial) {
      const float size = 0.5f + 3.f * prt::kScanWidth * Uniform(rng) * Uniform(rng);
      const float cx = -10.f + (F(w) + 20.f) * Uniform(rng), cy = -10.f + (F(h) + 20.f) * Uniform(rng);
      ScreenVertex v[3];
      for (auto& p : v) p = V(cx + size * (Uniform(rng) - 0.5f), cy + size * (Uniform(rng) - 0.5f));
      prt::RasterTriangle t;
      if (!prt::SetupTriangle(v[0], v[1], v[2], w, h, false, t)) continue;
      (t.x_max - t.x_min < prt::kScanWidth ? narrow : wide)++;
      prt::RowWalker rows(t, t.y_min);
      for (int y = t.y_min; y <= t.y_max; ++y) {
        const prt::Span walked = rows.Next(), solved = prt::RowSpan(t, y);
        const bool same = walked.begin >= walked.end ? solved.begin >= solved.end
                                                     : walked.begin == solved.begin && walked.end == solved.end;
        REQUIRE(same);
      }
    }
    CHECK(narrow > 500);
    CHECK(wide > 100);
  }

  TEST_CASE("Back faces are dropped only when culling, degenerate triangles always") {
    const ScreenVertex a = V(1, 1), b = V(9, 1), c = V(1, 9);  // clockwise on screen (y down)
    prt::RasterTriangle t;
    CHECK(prt::SetupTriangle(a, b, c, 10, 10, false, t));
    CHECK_FALSE(prt::SetupTriangle(a, b, c, 10, 10, true, t));
    CHECK(prt::SetupTriangle(a, c, b, 10, 10, true, t));
    CHECK_FALSE(prt::SetupTriangle(a, b, V(5, 1), 10, 10, false, t));
  }
}
