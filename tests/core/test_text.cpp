// Numbers as text: the shortest decimal that reads back exactly (what the run summary prints so
// a camera can be passed back as options), and printf-style formatting.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/rng.h"
#include "core/text.h"

TEST_SUITE("core") {
  TEST_CASE("ShortestFloat reads back exactly, with no more digits than needed") {
    CHECK(prt::ShortestFloat(3.2f) == "3.2");
    CHECK(prt::ShortestFloat(-1e-7f) == "-1e-07");
    CHECK(prt::ShortestFloat(16777216.f) == "16777216");
    CHECK(prt::ShortestFloat(40.f) == "40");  // not 4e+01
    CHECK(prt::ShortestFloat(1e7f) == "10000000");
    CHECK(prt::ShortestFloat(0.f) == "0");
    prt::Pcg32 rng(7, 1);
    for (int i = 0; i < 20000; ++i) {
      // Random bit patterns cover every exponent; NaN and infinity are skipped.
      const std::uint32_t bits = rng.NextU32();
      float v;
      std::memcpy(&v, &bits, sizeof v);
      if (!std::isfinite(v)) continue;
      const std::string text = prt::ShortestFloat(v);
      CAPTURE(text);
      REQUIRE(std::strtof(text.c_str(), nullptr) == v);
    }
  }

  TEST_CASE("Formatted writes what printf would") {
    CHECK(prt::Formatted("[%.3f s] %s %d", 1.23456, "x", 7) == "[1.235 s] x 7");
    CHECK(prt::Formatted("%g", 1e6) == "1e+06");
  }
}
