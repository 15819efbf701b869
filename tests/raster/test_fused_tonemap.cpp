// Tone mapping into a kept buffer and fused into the rasterizer's bands (raster/tonemap.h,
// RasterOptions::tone_map, keep_linear): the same bytes and repair counts as ToneMap of the
// finished frame, for one and several samples per pixel, a solid and a looked-up background,
// any thread count, and a buffer reused across sizes.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/parallel.h"
#include "raster/rasterizer.h"
#include "raster/tonemap.h"

namespace {

// A strip of triangles across the frame whose vertex colours run from negative (ringing) over
// [0, 1] to above 1, with one NaN vertex: every branch of the tone map, on drawn pixels.
struct Strip {
  std::vector<glm::vec3> positions, colors;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

Strip MakeStrip() {
  Strip s;
  const int columns = 24;
  for (int i = 0; i <= columns; ++i) {
    const float x = -1.f + 2.f * float(i) / columns;
    s.positions.push_back({x, -0.6f, 0.f});
    s.positions.push_back({x, 0.7f, -0.2f * x});
    const float v = -0.3f + 1.6f * float(i) / columns;
    s.colors.push_back({v, 0.5f * v, 1.f - v});
    s.colors.push_back({1.f - v, v * v, v});
  }
  s.colors[17].y = std::numeric_limits<float>::quiet_NaN();
  for (std::uint32_t i = 0; i < columns; ++i) {
    s.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 1});
    s.triangles.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
  }
  return s;
}

prt::Camera Front() {
  prt::Camera c;
  c.eye = {0.f, 0.f, 3.f};
  c.target = {0.f, 0.f, 0.f};
  c.fov_deg = 50.f;
  c.near_plane = 0.1f;
  c.far_plane = 10.f;
  return c;
}

}  // namespace

TEST_SUITE("raster") {
  TEST_CASE("ToneMapInto a reused buffer and ToneMapRows give ToneMap's bytes and counts") {
    prt::Image8 kept;
    for (const auto& [w, h] : {std::pair{37, 53}, std::pair{5, 3}, std::pair{300, 41}}) {
      prt::ImageF image(w, h);
      for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const float t = float(i % 97) / 60.f - 0.2f;
        image.pixels[i] = {t, 1.3f - t, i % 31 == 0 ? std::numeric_limits<float>::quiet_NaN() : 0.5f * t};
      }
      prt::ToneMapOptions options;
      options.curve = prt::ToneCurve::kAces;
      options.exposure_ev = 0.7f;
      const prt::ToneMapped fresh = prt::ToneMap(image, options);
      REQUIRE(fresh.negative_pixels > 0);
      REQUIRE(fresh.nan_pixels > 0);
      const prt::ToneMapCounts counts = prt::ToneMapInto(image, options, kept);
      CHECK(kept.width == w);
      CHECK(kept.height == h);
      CHECK(kept.rgb == fresh.image.rgb);
      CHECK(counts.negative_pixels == fresh.negative_pixels);
      CHECK(counts.nan_pixels == fresh.nan_pixels);
      // Rows in two pieces add up to the whole.
      prt::Image8 rows(w, h);
      prt::ToneMapCounts sum = prt::ToneMapRows(image, 0, h / 2, options, rows);
      sum += prt::ToneMapRows(image, h / 2, h, options, rows);
      CHECK(rows.rgb == fresh.image.rgb);
      CHECK(sum.negative_pixels == fresh.negative_pixels);
      CHECK(sum.nan_pixels == fresh.nan_pixels);
    }
  }

  TEST_CASE("Tone mapping fused into the bands writes ToneMap's bytes of the drawn frame, with or without the linear frame, at any ssaa and thread count") {
    const Strip strip = MakeStrip();
    prt::ToneMapOptions tone;
    tone.curve = prt::ToneCurve::kReinhard;
    tone.exposure_ev = 0.5f;
    for (int ssaa : {1, 2}) {
      for (int threads : {1, 2}) {
        prt::SetThreadCount(threads);
        prt::Rasterizer rasterizer;
        prt::Image8 toned;
        prt::RasterOptions options;
        options.ssaa = ssaa;
        options.background.color = {0.2f, -0.1f, 0.4f};  // a negative background channel is counted too
        options.tone_map = &tone;
        options.tone_mapped = &toned;
        // 61 rows: the last band is partial.
        const prt::RasterImage& frame =
            rasterizer.Draw(Front(), 83, 61, strip.positions, strip.triangles, strip.colors, options);
        const prt::ToneMapped expected = prt::ToneMap(frame.image, tone);
        CHECK(toned.width == 83);
        CHECK(toned.height == 61);
        CHECK(toned.rgb == expected.image.rgb);
        CHECK(frame.tone_counts.negative_pixels == expected.negative_pixels);
        CHECK(frame.tone_counts.nan_pixels == expected.nan_pixels);
        CHECK(expected.nan_pixels > 0);
        CHECK(expected.negative_pixels > 83 * 61 / 2);  // the background's pixels at least
        // The linear frame left out: the same bytes and counts, from the band buffers alone.
        const prt::ToneMapCounts kept_counts = frame.tone_counts;
        prt::Image8 alone;
        options.tone_mapped = &alone;
        options.keep_linear = false;
        const prt::RasterImage& none =
            rasterizer.Draw(Front(), 83, 61, strip.positions, strip.triangles, strip.colors, options);
        CHECK(none.image.pixels.empty());
        CHECK(none.coverage.empty());
        CHECK(alone.rgb == expected.image.rgb);
        CHECK(none.tone_counts.negative_pixels == kept_counts.negative_pixels);
        CHECK(none.tone_counts.nan_pixels == kept_counts.nan_pixels);
        // And over a background looked up per pixel.
        options.background.radiance = [](const glm::vec3& d) { return 0.5f * d + glm::vec3(0.5f); };
        rasterizer.Draw(Front(), 83, 61, strip.positions, strip.triangles, strip.colors, options);
        options.keep_linear = true;
        options.tone_mapped = &toned;
        const prt::ToneMapped looked_up =
            prt::ToneMap(rasterizer.Draw(Front(), 83, 61, strip.positions, strip.triangles, strip.colors, options).image, tone);
        CHECK(alone.rgb == looked_up.image.rgb);
        CHECK(toned.rgb == looked_up.image.rgb);
        options.background.radiance = nullptr;
        // Without tone mapping asked for, the counts are zero and the buffer untouched.
        prt::Image8 untouched(2, 2);
        options.tone_map = nullptr;
        options.tone_mapped = &untouched;
        CHECK(rasterizer.Draw(Front(), 83, 61, strip.positions, strip.triangles, strip.colors, options)
                  .tone_counts.negative_pixels == 0);
        CHECK(untouched.width == 2);
      }
    }
    prt::SetThreadCount(0);
  }
}
