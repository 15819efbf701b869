// The threads tier of src/cpca (tests/README.md, "Tiers"): clustered PCA's fit and its shading,
// on one thread and on more threads than cores, give the same bits; ThreadSanitizer watches the
// many-thread runs.
#include <doctest/doctest.h>

#include "cpca/cpca.h"
#include "cpca/cpca_transfer.h"
#include "core/rng.h"
#include "tests/precompute/glossy_test_util.h"
#include "tests/threads_util.h"

namespace prt {

TEST_SUITE("cpca") {
  TEST_CASE("threads: the clusters, weights, means and principal rows, and the shading, the same bits on 1 and many threads") {
    // Rows of random numbers, 1200 of them: several chunks of rows (256 a chunk).
    constexpr int kDim = 25;
    std::vector<float> rows(1200 * kDim);
    Pcg32 rng(21, 7);
    for (float& x : rows) x = float(2.0 * rng.NextDouble() - 1.0);
    CpcaOptions o;
    o.clusters = 9;
    o.terms = 2;
    o.candidates = 3;
    const auto [one, many] = test::OneAndMany([&] { return CompressCpca(rows.data(), 1200, kDim, o); });
    CHECK(one.cluster == many.cluster);
    CHECK(one.weights == many.weights);
    CHECK(one.means == many.means);
    CHECK(one.principal == many.principal);

    // Shading through the compressed transfer matrices of a glossy scene.
    const test::GlossyMatrixScene scene = test::MakeGlossyMatrixScene(true, "phong:8,0.4");
    const ShRgb light = test::BandLimitedLight(2);
    CpcaOptions shading;
    shading.clusters = 6;
    shading.terms = 3;
    const auto [shaded_one, shaded_many] = test::OneAndMany([&] {
      const CpcaTransfer cpca = CompressTransferMatrices(scene.transport, shading);
      return GlossyFromCpca(scene.mesh, cpca, scene.transport.material, light, glm::dvec3(3.0, 4.0, 2.0));
    });
    CHECK(shaded_one == shaded_many);
  }
}

}  // namespace prt
