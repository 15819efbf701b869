// The threads tier of src/material (tests/README.md, "Tiers"): a lobe's transfer table, filled a
// few nodes per chunk, is the same bits on one thread and on more threads than cores; its
// quadrature rules are kept per thread, so a thread that asks for a larger rule must not disturb
// another's. ThreadSanitizer watches both.
#include <doctest/doctest.h>

#include <cmath>
#include <thread>
#include <vector>

#include "material/lobe.h"
#include "material/lobe_transfer.h"
#include "sh/coeffs.h"
#include "tests/threads_util.h"

namespace prt {

TEST_SUITE("material") {
  TEST_CASE("threads: a lobe's transfer table is the same bits on 1 and many threads") {
    const Lobe lobe{LobeKind::kPhong, 40};
    const glm::dvec3 n(0, 0, 1), r = glm::normalize(glm::dvec3(0.3, 0.1, 0.9));
    const auto [one, many] = test::OneAndMany([&] {
      const LobeTransferTable table(lobe, 6);
      std::vector<double> t(CoeffCount(6));
      table.Transfer(n, r, t.data());
      return t;
    });
    CHECK(one == many);
  }

  TEST_CASE("threads: lobe transfers at high and low lmax on threads of their own agree in their low bands") {
    // Bands 0..1 do not depend on lmax apart from the arc rule's size. Tolerance: two converged
    // quadratures with different arc rules, 1e-9.
    const Lobe lobe{LobeKind::kPhong, 100};
    const glm::dvec3 n(0, 0, 1), r = glm::normalize(glm::dvec3(0.5, 0.0, 0.8));
    std::vector<double> high(CoeffCount(12)), low(CoeffCount(1));
    std::thread a([&] { LobeTransfer(lobe, n, r, 12, high.data()); });
    std::thread b([&] { LobeTransfer(lobe, n, r, 1, low.data()); });
    a.join();
    b.join();
    CHECK(std::abs(low[0]) > 0.05);
    for (std::size_t k = 0; k < low.size(); ++k) CHECK(std::abs(high[k] - low[k]) < 1e-9);
  }
}

}  // namespace prt
