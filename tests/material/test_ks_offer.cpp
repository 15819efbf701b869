// The KS prt offers for a material library's gloss (`--material phong:N,KS` in the materials
// line, io/obj_materials.h through material/material.h's FittingKs) must be one that prt then
// accepts beside the same albedo (CheckMaterialEnergy), and the largest such value it can print:
// checked over a grid of albedos, 0.644 among them (whose Ks 0.3555 was offered as 0.36, then
// refused), and albedos whose complement 1 - a lies just above, on or below a multiple of 0.01.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/text.h"
#include "io/obj_materials.h"
#include "material/material.h"
#include "tests/test_support.h"

namespace prt {
namespace {

/// The albedos of the grid, as the mesh holds them (floats): 0 to 1 by 0.001, and beside each
/// multiple of 0.01 the albedos whose complement is that multiple plus or minus a little (1e-7
/// to 5e-6: under, at and over the check's slack of 1e-6), and 0.644.
std::vector<float> Albedos() {
  std::vector<float> out;
  for (int i = 0; i <= 1000; ++i) out.push_back(float(i) / 1000.0f);
  for (int k = 0; k <= 100; ++k)
    for (const double d : {-5e-6, -2e-6, -1e-6, -1e-7, 1e-7, 1e-6, 2e-6, 5e-6}) {
      const double a = 1.0 - (k / 100.0 + d);
      if (a >= 0.0 && a <= 1.0) out.push_back(float(a));
    }
  out.push_back(0.644f);
  return out;
}

/// The coat weights tried beside albedo `a`: the usual ones, and around the complement 1 - a
/// (where rounding to the nearest goes over it).
std::vector<double> Weights(float a) {
  std::vector<double> out = {1.0, 0.9, 0.5, 0.3555, 0.2, 0.05, 0.004};
  for (const double d : {-0.006, -0.0049, -0.0045, -0.001, 0.0, 0.001, 0.0045, 0.006})
    if (1.0 - a + d >= 0.0 && 1.0 - a + d <= 1.0) out.push_back(1.0 - a + d);
  return out;
}

/// Whether `--material phong:20,KS` (KS as printed) passes prt's own check beside albedo `a`.
bool Accepted(const std::string& ks, float a) {
  const Material m = ParseMaterial("phong:20," + ks);
  return test::ErrorMessage([&] { CheckMaterialEnergy(m, a, "the test's albedo"); }).empty();
}

/// `ks` to the nearest two decimals, printed.
std::string Nearest(double ks) { return ShortestFloat(float(std::round(ks * 100.0) / 100.0)); }

/// No offer is right only when the nearest two decimals are 0 or nothing above 0 fits.
void CheckNoOffer(double ks, float a) { CHECK((std::lround(ks * 100.0) == 0 || !Accepted("0.01", a))); }

/// The printed KS two decimals above `ks` (a multiple of 0.01).
std::string OneStepUp(double ks) { return ShortestFloat(float((std::round(ks * 100.0) + 1.0) / 100.0)); }

/// Checks the offer `printed` for a coat of weight `ks` beside albedo `a`: accepted; and either
/// the nearest two decimals of `ks` (when those fit) or the largest printed value accepted.
void CheckOffer(const std::string& printed, double ks, float a) {
  CAPTURE(printed);
  const auto value = ParseNumber(printed);
  REQUIRE(value);
  CHECK(std::abs(*value * 100.0 - std::round(*value * 100.0)) < 1e-9);  // two decimals
  CHECK(Accepted(printed, a));
  const std::string nearest = Nearest(ks);
  if (printed != nearest) {
    CHECK(!Accepted(nearest, a));               // lowered only when the nearest does not fit
    CHECK(!Accepted(OneStepUp(*value), a));     // and then to the largest that does
    CHECK(*value < *ParseNumber(nearest));
  }
}

}  // namespace

TEST_SUITE("material") {
  TEST_CASE("material: the KS offered beside an albedo is accepted by prt, and the largest it can print") {
    std::size_t offers = 0, lowered = 0;
    for (const float a : Albedos())
      for (const double ks : Weights(a)) {
        CAPTURE(a);
        CAPTURE(ks);
        const KsOffer offer = FittingKs(ks, a);
        if (!(offer.ks > 0.0)) {
          CheckNoOffer(ks, a);
          continue;
        }
        CheckOffer(ShortestFloat(float(offer.ks)), ks, a);
        CHECK(offer.lowered == (ShortestFloat(float(offer.ks)) != Nearest(ks)));
        ++offers, lowered += offer.lowered;
      }
    CHECK(offers > 10000);
    CHECK(lowered > 1000);
    // The case: Kd 0.644 with Ks 0.3555 was offered 0.36 (0.644 + 0.36 = 1.004, refused).
    CHECK(ShortestFloat(float(FittingKs(0.3555, 0.644f).ks)) == "0.35");
    CHECK(ShortestFloat(float(FittingKs(0.5, 0.644f).ks)) == "0.35");
    CHECK(ShortestFloat(float(FittingKs(0.5, 0.8f).ks)) == "0.2");  // 0.8f is 0.800000012: within the slack
  }

  TEST_CASE("material: the materials line's --material offer is accepted by prt, and the largest it can print") {
    // The offer as the run summary prints it (DescribeMaterialFields), parsed back from the text.
    std::size_t offers = 0;
    for (const float a : Albedos())
      for (const double ks : Weights(a)) {
        CAPTURE(a);
        CAPTURE(ks);
        MaterialFields fields;
        fields.keywords = {"newmtl", "Kd", "Ks", "Ns"};
        fields.gloss_material = "coat";
        fields.ks = glm::vec3(float(ks));
        fields.ns = 20.0f;
        MaterialUse use;
        use.brightest_kd = a;
        const std::string line = DescribeMaterialFields(fields, use);
        CAPTURE(line);
        // The mean of the file's Ks as the line takes it (a float sum).
        const double mean = (fields.ks.x + fields.ks.y + fields.ks.z) / 3.0;
        const std::string marker = "--material phong:20,";
        const std::size_t at = line.find(marker);
        if (at == std::string::npos) {
          CheckNoOffer(mean, a);
          continue;
        }
        const std::size_t begin = at + marker.size(), end = line.find_first_of(",)", begin);
        REQUIRE(end != std::string::npos);
        CheckOffer(line.substr(begin, end - begin), mean, a);
        ++offers;
      }
    CHECK(offers > 10000);
  }
}

}  // namespace prt
