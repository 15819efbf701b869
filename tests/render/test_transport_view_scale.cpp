// The transport view's colour scale (TransportViewScale): its ends are the largest |T_k| over the
// vertices, so a coefficient that is negative everywhere (T_6 on an up-facing floor: prt help
// basis) is drawn at full strength, not divided by zero or by its smallest magnitude.
#include <doctest/doctest.h>

#include <vector>

#include "render/render_frames.h"

namespace prt {
namespace {

/// A basis whose transfer coefficients are given outright (only the transport view's calls work).
class GivenCoefficients : public FrameLight {
 public:
  explicit GivenCoefficients(std::vector<std::vector<double>> rows) : rows_(std::move(rows)) {}
  void Turn(double) override {}
  void SetAxis(const glm::dvec3&) override {}
  std::vector<glm::vec3> Shade(const Mesh&, bool, const glm::dvec3*) const override { return {}; }
  bool HasGlossy() const override { return false; }
  std::vector<glm::vec3> Glossy(const Mesh&, const glm::dvec3*) const override { return {}; }
  glm::vec3 Kept(const glm::dvec3&) const override { return glm::vec3(0.0f); }
  int ViewCoefficients() const override { return int(rows_.front().size()); }
  double Coefficient(std::size_t v, int k) const override { return rows_[v][k]; }

 private:
  std::vector<std::vector<double>> rows_;
};

}  // namespace

TEST_SUITE("render") {
  TEST_CASE("transport view scale: the largest magnitude over the vertices, whatever its sign") {
    const GivenCoefficients light({{0.5, -3.0, -0.25}, {-2.0, 1.0, -0.5}, {1.5, -0.5, -1.0}});
    CHECK(TransportViewScale(light, 3, 0) == 2.0);   // mixed signs: the negative end is larger
    CHECK(TransportViewScale(light, 3, 1) == 3.0);
    CHECK(TransportViewScale(light, 3, 2) == 1.0);   // negative everywhere
    CHECK(TransportViewScale(light, 2, 2) == 0.5);   // only the first `vertices` count
  }
}

}  // namespace prt
