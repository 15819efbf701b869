// --material values (material/material.h): what is accepted, what is refused and how.
#include <doctest/doctest.h>

#include <string>

#include "core/error.h"
#include "material/material.h"
#include "tests/test_support.h"

using namespace prt;

TEST_SUITE_BEGIN("material");

namespace {
std::string Problem(const std::string& text) {
  return test::ErrorMessage([&] { ParseMaterial(text); });
}
}  // namespace

TEST_CASE("--material parses diffuse and phong:N[,KS] and names them back") {
  CHECK_FALSE(ParseMaterial("diffuse").glossy);
  const Material m = ParseMaterial("phong:50");
  CHECK(m.glossy);
  CHECK(m.lobe.exponent == 50);
  CHECK(m.ks == 0.5);
  CHECK(m.Name() == "phong:50,0.5");
  const Material k = ParseMaterial("phong:1000,0.25");
  CHECK(k.lobe.exponent == 1000);
  CHECK(k.ks == 0.25);
  CHECK(ParseMaterial(k.Name()).Name() == k.Name());
}

TEST_CASE("--material refuses malformed values with what it expected") {
  for (const char* bad : {"phong", "phong:", "phong:0", "phong:1001", "phong:2.5", "phong:x", "phong:10,", "phong:10,1.5",
                          "phong:10,-0.1", "glossy", "Phong:10", "phong:10,0.5,1"}) {
    CAPTURE(bad);
    const std::string p = Problem(bad);
    CHECK(p.find("expected diffuse or phong:N[,KS]") != std::string::npos);
  }
}

TEST_CASE("albedo + KS above 1 is refused, at 1 accepted") {
  const Material m = ParseMaterial("phong:10,0.5");
  CHECK_NOTHROW(CheckMaterialEnergy(m, 0.5, "--albedo"));
  CHECK_THROWS_AS(CheckMaterialEnergy(m, 0.51, "--albedo"), Error);
  CHECK_NOTHROW(CheckMaterialEnergy(ParseMaterial("diffuse"), 1.0, "--albedo"));
  // An albedo stored as float: 0.8f + 0.2 is 1 to float precision, not above it.
  CHECK_NOTHROW(CheckMaterialEnergy(ParseMaterial("phong:10,0.2"), double(0.8f), "the demo scene"));
}

TEST_SUITE_END();
