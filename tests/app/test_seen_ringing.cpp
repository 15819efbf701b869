// FindSeenRinging and ShownLights (app/seen_ringing.h): the rule behind render's and demo's
// default window, on lights whose convolutions are known in closed form. A light a + b z (bands
// 0 and 1) convolved with a kernel k is k_0 a + k_1 b z, lowest k_0 a - k_1 |b|. The Phong lobe
// of exponent N has h_0 = (N+2)/(N+1), h_1 = 1 (material/lobe.h), the clamped cosine A_0 = pi,
// A_1 = 2 pi/3 (sh/zonal.h).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/seen_ringing.h"
#include "core/constants.h"
#include "material/material.h"

using namespace prt;

namespace {

/// The compass search ends with steps of 1e-9 rad; the value it misses at a smooth extremum is
/// second order in the step, and the sums round near 1e-15: 1e-12 is far above both.
constexpr double kSearchTolerance = 1e-12;

/// The grey light a + b z as SH coefficients of bands 0 and 1.
ShRgb Linear(double a, double b) {
  ShRgb c(4, glm::dvec3(0.0));
  c[0] = glm::dvec3(a * std::sqrt(4.0 * kPi));
  c[2] = glm::dvec3(b * std::sqrt(4.0 * kPi / 3.0));
  return c;
}

std::vector<std::string> Names(const std::vector<ShownLight>& shown) {
  std::vector<std::string> names;
  for (const auto& s : shown) names.push_back(s.name);
  return names;
}

const std::string kIrradiance = "the irradiance", kLobe = "the light seen through the glossy lobe", kLight = "the light";

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("ShownLights: each view shows the convolutions its frames draw, and only those") {
    const Material diffuse, glossy = ParseMaterial("phong:50,0.3"), no_coat = ParseMaterial("phong:50,0");
    using V = std::vector<std::string>;
    CHECK(Names(ShownLights(diffuse, View::kRadiance, 4)) == V{kIrradiance});
    CHECK(Names(ShownLights(glossy, View::kRadiance, 4)) == V{kIrradiance, kLobe});
    // The irradiance view leaves the lobe out (albedo 1, diffuse): catches a lobe added there.
    CHECK(Names(ShownLights(glossy, View::kIrradiance, 4)) == V{kIrradiance});
    CHECK(Names(ShownLights(glossy, View::kGlossy, 4)) == V{kLobe});
    CHECK(Names(ShownLights(diffuse, View::kGlossy, 4)).empty());
    CHECK(Names(ShownLights(no_coat, View::kRadiance, 4)) == V{kIrradiance});  // KS 0 shows no lobe
    CHECK(Names(ShownLights(glossy, View::kLight, 4)) == V{kLight});
    CHECK(ShownLights(glossy, View::kAlbedo, 4).empty());
    CHECK(ShownLights(glossy, View::kTransport, 4).empty());
    // The kernels: the lobe's zonal coefficients h_0 = 52/51, h_1 = 1 for N = 50.
    const std::vector<ShownLight> shown = ShownLights(glossy, View::kGlossy, 1);
    REQUIRE(shown.size() == 1);
    const std::vector<double>& lobe = shown[0].kernel;
    REQUIRE(lobe.size() == 2);
    CHECK(lobe[0] == doctest::Approx(52.0 / 51.0));
    CHECK(lobe[1] == doctest::Approx(1.0));
  }

  TEST_CASE("FindSeenRinging: 1 + 1.2 z rings as itself and through a sharp lobe, not as irradiance") {
    const ShRgb light = Linear(1.0, 1.2);  // lowest -0.2 at the south pole
    // Seen as itself (--view light): it rings.
    const SeenRinging itself = FindSeenRinging(light, Material{}, View::kLight);
    CHECK(itself.rings);
    CHECK(itself.what == kLight);
    CHECK(itself.lowest == doctest::Approx(-0.2).epsilon(kSearchTolerance));
    CHECK(itself.peak == doctest::Approx(2.2).epsilon(kSearchTolerance));
    // A diffuse surface shows pi - 0.8 pi > 0: no window. Catches a rule that checks the light
    // itself whatever the view.
    const SeenRinging diffuse = FindSeenRinging(light, Material{}, View::kRadiance);
    CHECK_FALSE(diffuse.rings);
    CHECK(diffuse.what == kIrradiance);
    CHECK(diffuse.lowest == doctest::Approx(0.2 * kPi).epsilon(kSearchTolerance));
    // phong:50 shows 52/51 - 1.2 < 0 through its lobe, though the irradiance stays positive: the
    // lobe is the worst of the two. Catches a rule that looks at the irradiance alone.
    const SeenRinging coat = FindSeenRinging(light, ParseMaterial("phong:50,0.3"), View::kRadiance);
    CHECK(coat.rings);
    CHECK(coat.what == kLobe);
    CHECK(coat.lowest == doctest::Approx(52.0 / 51.0 - 1.2).epsilon(kSearchTolerance));
    CHECK(coat.peak == doctest::Approx(52.0 / 51.0 + 1.2).epsilon(kSearchTolerance));
    // phong:1 is broad (h_0 = 3/2): 1.5 - 1.2 > 0. Catches "glossy, so always a window".
    CHECK_FALSE(FindSeenRinging(light, ParseMaterial("phong:1,0.3"), View::kRadiance).rings);
    // Views without light decide nothing.
    const SeenRinging albedo = FindSeenRinging(light, Material{}, View::kAlbedo);
    CHECK_FALSE(albedo.rings);
    CHECK(albedo.what.empty());
  }

  TEST_CASE("FindSeenRinging: the tolerance is kSeenRingingTolerance of the peak, at any brightness") {
    // 1 + (1 + d) z has lowest / peak = -d / (2 + d) = -q for d = 2q / (1 - q).
    const auto light_with_share = [](double q, double scale) {
      ShRgb c = Linear(1.0, 1.0 + 2.0 * q / (1.0 - q));
      for (auto& v : c) v *= scale;
      return c;
    };
    for (double scale : {1e-6, 1.0, 1e6}) {
      CAPTURE(scale);
      // A tenth of the tolerance below zero: rounding-level, no ringing. Catches a tolerance of 0.
      CHECK_FALSE(FindSeenRinging(light_with_share(0.1 * kSeenRingingTolerance, scale), Material{}, View::kLight).rings);
      // Ten times it: ringing. Catches a tolerance in absolute units (wrong at 1e-6 or 1e6) or one
      // far looser than documented.
      CHECK(FindSeenRinging(light_with_share(10.0 * kSeenRingingTolerance, scale), Material{}, View::kLight).rings);
    }
  }
}
