#include <doctest/doctest.h>

#include <string>

#include "raster/annotate.h"
#include "raster/basis_chart.h"

TEST_SUITE("raster") {
  TEST_CASE("the basis chart names the SH pole, and the caption fits even for one band") {
    const std::string caption = prt::kBasisPoleCaption;
    CHECK(caption.find("+Z") != std::string::npos);
    CHECK(caption.find("Y-up") != std::string::npos);
    for (int lmax : {0, 2}) {
      const prt::Image8 chart = prt::DrawBasisChart(lmax, 32);
      const glm::ivec2 size = prt::TextSize(caption);
      // The caption is drawn at (4, 16), in 0.9 grey (230).
      REQUIRE(4 + size.x <= chart.width);
      int lit = 0;
      for (int y = 16; y < 16 + size.y; ++y)
        for (int x = 4; x < 4 + size.x; ++x) lit += chart.rgb[3 * (static_cast<std::size_t>(y) * chart.width + x)] == 230;
      CHECK(lit > 100);
    }
  }
}
