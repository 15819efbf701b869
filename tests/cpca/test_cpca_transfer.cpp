// Glossy shading from CPCA-compressed transfer matrices (cpca/cpca_transfer.h): equal to
// GlossyFromMatrices on the matrices the model reconstructs, for one and three channels and a
// light with fewer bands; lossless compression shades as the full matrices do; frame after frame
// the cluster products follow the light and the eye.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "cpca/cpca_transfer.h"
#include "precompute/shade.h"
#include "precompute/transfer_matrix.h"
#include "precompute/transport.h"
#include "tests/precompute/glossy_test_util.h"
#include "tests/test_support.h"

using namespace prt;

TEST_SUITE_BEGIN("cpca");

namespace {

/// Shadowed (or coloured interreflection: three channels) transfer matrices of the test scene.
Transport Matrices(bool coloured) { return test::MakeGlossyMatrixScene(coloured, "phong:8,0.4").transport; }

/// Largest |a - b| over every vertex and channel, relative to the largest |b|.
double RelativeMax(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v)
    for (int c = 0; c < 3; ++c) diff = std::max(diff, double(std::abs(a[v][c] - b[v][c]))), scale = std::max(scale, double(std::abs(b[v][c])));
  return scale > 0 ? diff / scale : diff;
}

}  // namespace

TEST_CASE("cpca shading equals GlossyFromMatrices on the reconstructed matrices, 1 and 3 channels") {
  // Tolerance: the two sum the same terms in another order (the light through the cluster's
  // matrices first, floats for the products): float rounding of ~9 x 9 terms.
  constexpr double kReorder = 2e-5;
  const Mesh mesh = test::SphereOverPlane();
  for (bool coloured : {false, true}) {
    Transport t = Matrices(coloured);
    REQUIRE(t.channels == (coloured ? 3 : 1));
    CpcaOptions o;
    o.clusters = 5;
    o.terms = 2;
    const CpcaTransfer cpca = CompressTransferMatrices(t, o);
    Transport rebuilt = t;
    rebuilt.matrices = ReconstructMatrices(cpca);
    // The light coloured so that a channel read for another shows; a second frame (other light,
    // other eye) so that products left from the first would show.
    for (int frame = 0; frame < 2; ++frame) {
      ShRgb light = test::BandLimitedLight(2);
      for (auto& l : light) l *= glm::dvec3(1.0, 0.5 + frame, 0.25);
      const glm::dvec3 eye = frame == 0 ? glm::dvec3(3.0, 4.0, 2.0) : glm::dvec3(-2.0, 1.5, 3.0);
      CHECK(RelativeMax(GlossyFromCpca(mesh, cpca, t.material, light, eye),
                        GlossyFromMatrices(mesh, rebuilt, t.material, light, eye)) < kReorder);
      CHECK(RelativeMax(ShadeVerticesCpca(mesh, t, cpca, light, true, eye), ShadeVertices(mesh, rebuilt, light, true, &eye)) <
            kReorder);
    }
    // A light of fewer bands uses the first columns only, as the full path does.
    const ShRgb low = test::BandLimitedLight(1);
    const glm::dvec3 eye(1.0, 3.0, 2.0);
    CHECK(RelativeMax(GlossyFromCpca(mesh, cpca, t.material, low, eye), GlossyFromMatrices(mesh, rebuilt, t.material, low, eye)) <
          kReorder);
  }
}

TEST_CASE("cpca shading: lossless compression shades as the full matrices") {
  // Tolerance: as above, plus the float rounding of the lossless model (one matrix per cluster).
  constexpr double kReorder = 2e-5;
  const Mesh mesh = test::SphereOverPlane();
  for (bool coloured : {false, true}) {
    const Transport t = Matrices(coloured);
    CpcaOptions o;
    o.clusters = int(t.vertices * t.channels);
    o.terms = 1;
    const CpcaTransfer cpca = CompressTransferMatrices(t, o);
    CHECK(CpcaRelativeError(cpca.model, t.matrices.data()) < 1e-6);
    const ShRgb light = test::BandLimitedLight(2);
    const glm::dvec3 eye(3.0, 4.0, 2.0);
    const auto full = GlossyFromMatrices(mesh, t, t.material, light, eye);
    CHECK(RelativeMax(GlossyFromCpca(mesh, cpca, t.material, light, eye), full) < kReorder);
    double peak = 0.0;
    for (const auto& c : full) peak = std::max(peak, double(c.x + c.y + c.z));
    CHECK(peak > 0.0);  // not vacuous
  }
}
