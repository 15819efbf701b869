#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "raster/annotate.h"

namespace {

// At 1080 lines the legend's text scale is 2: stb_easy_font digits are 7 font pixels tall, 14
// here. 12 leaves room for the shortest digit glyphs and still fails at scale 1.
constexpr int kMinTextHeight1080 = 12;

bool Inside(const prt::PixelRect& inner, const prt::PixelRect& outer) {
  return inner.x0 >= outer.x0 && inner.y0 >= outer.y0 && inner.x1 <= outer.x1 && inner.y1 <= outer.y1;
}

const std::uint8_t* Pixel(const prt::Image8& image, int x, int y) {
  return &image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x)];
}

}  // namespace

TEST_SUITE("raster") {
  TEST_CASE("TextSize bounds every pixel DrawText writes") {
    for (int scale : {1, 3}) {
      prt::Image8 image(200, 60);
      prt::DrawText(image, 5, 7, "+1.23e-05 T6", glm::vec3(1.f), scale);
      const glm::ivec2 size = prt::TextSize("+1.23e-05 T6", scale);
      int lit = 0;
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
          if (Pixel(image, x, y)[0] != 0) {
            ++lit;
            CHECK((x >= 5 && x < 5 + size.x && y >= 7 && y < 7 + size.y));
          }
      CHECK(lit > 0);
    }
  }

  TEST_CASE("the diverging legend scales with the image and stays inside it") {
    const std::pair<int, int> sizes[] = {{96, 96}, {640, 480}, {1920, 1080}, {300, 1000}, {3840, 2160}};
    for (const auto& [w, h] : sizes)
      for (double max_abs : {0.5, 1.23456e-7, -0.0}) {
        CAPTURE(w);
        CAPTURE(h);
        CAPTURE(max_abs);
        const auto layout = prt::LayoutDivergingLegend(w, h, max_abs, "T12");
        REQUIRE(layout.has_value());
        const prt::PixelRect image_rect{0, 0, w, h};
        CHECK(Inside(layout->panel, image_rect));
        CHECK(Inside(layout->bar, layout->panel));
        CHECK(Inside(layout->title, layout->panel));
        for (const prt::PixelRect& label : layout->labels) CHECK(Inside(label, layout->panel));
        CHECK(layout->text_scale == std::max(1, (h + 270) / 540));
        // At most half the width, unless the text is already at its smallest.
        if (layout->text_scale > 1) CHECK(w - layout->panel.x0 <= w / 2);

        // Drawn on black: every pixel inside the panel, white text only in the text boxes.
        prt::Image8 image(w, h);
        prt::DrawDivergingLegend(image, max_abs, "T12");
        int text_top = h, text_bottom = -1, outside_panel = 0, stray_white = 0;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            const std::uint8_t* p = Pixel(image, x, y);
            if (p[0] == 0 && p[1] == 0 && p[2] == 0) continue;
            const prt::PixelRect at{x, y, x + 1, y + 1};
            outside_panel += !Inside(at, layout->panel);
            if (p[0] == 255 && p[1] == 255 && p[2] == 255) {
              stray_white += !(Inside(at, layout->title) || Inside(at, layout->labels[0]) ||
                               Inside(at, layout->labels[1]) || Inside(at, layout->labels[2]));
              if (Inside(at, layout->labels[1])) text_top = std::min(text_top, y), text_bottom = std::max(text_bottom, y);
            }
          }
        CHECK(outside_panel == 0);
        CHECK(stray_white == 0);
        // The "0" label's height in pixels.
        if (h >= 1080) CHECK(text_bottom - text_top + 1 >= kMinTextHeight1080);
        // Red at the top of the bar, blue at the bottom.
        const int x = (layout->bar.x0 + layout->bar.x1) / 2;
        const std::uint8_t* top = Pixel(image, x, layout->bar.y0);
        const std::uint8_t* bottom = Pixel(image, x, layout->bar.y1 - 1);
        CHECK(top[0] > 2 * top[2]);
        CHECK(bottom[2] > 2 * bottom[0]);
      }
  }

  TEST_CASE("the diverging legend shrinks its text, then gives up, on small images") {
    // 1000 lines ask for scale 2; 120 columns cannot hold it in half their width.
    const auto narrow = prt::LayoutDivergingLegend(120, 1000, 0.5, "T3");
    REQUIRE(narrow.has_value());
    CHECK(narrow->text_scale == 1);
    CHECK(narrow->panel.x0 >= 0);
    // Too small for anything: nothing drawn.
    CHECK_FALSE(prt::LayoutDivergingLegend(24, 24, 0.5, "T3").has_value());
    prt::Image8 image(24, 24);
    prt::DrawDivergingLegend(image, 0.5, "T3");
    CHECK(std::all_of(image.rgb.begin(), image.rgb.end(), [](std::uint8_t v) { return v == 0; }));
  }
}
