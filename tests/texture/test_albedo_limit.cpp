// LimitAlbedo (texture/albedo_limit.h): texels above the energy limit of a glossy coat keep their
// hue at the limit, the others are untouched, and the mip pyramid follows.
#include <doctest/doctest.h>

#include <optional>

#include "texture/albedo_limit.h"

namespace prt {

TEST_SUITE("texture") {
TEST_CASE("albedo limit: texels above the limit keep their hue at the limit, the others are untouched") {
  ImageF image(2, 1);
  image.pixels = {glm::vec3(1.0f, 0.5f, 0.25f), glm::vec3(0.6f, 0.1f, 0.0f)};
  std::size_t scaled = 0;
  const std::optional<Texture> limited = LimitAlbedo(Texture(image, "t"), 0.7f, scaled);
  REQUIRE(limited.has_value());
  const Texture& fitted = *limited;
  CHECK(scaled == 1);
  CHECK(fitted.level(0).pixels[0].x == doctest::Approx(0.7f));
  CHECK(fitted.level(0).pixels[0].y == doctest::Approx(0.35f));   // the ratios 1 : 0.5 : 0.25 stay
  CHECK(fitted.level(0).pixels[0].z == doctest::Approx(0.175f));
  CHECK(fitted.level(0).pixels[1] == glm::vec3(0.6f, 0.1f, 0.0f));
  CHECK(fitted.mean().x <= 0.7f);  // the pyramid is rebuilt from the fitted texels
  CHECK(fitted.name() == "t");
  // Nothing above the limit: nothing to rebuild.
  CHECK_FALSE(LimitAlbedo(fitted, 0.7f, scaled).has_value());
  CHECK(scaled == 0);
}
}

}  // namespace prt
