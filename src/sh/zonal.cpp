#include "sh/zonal.h"

#include <cmath>
#include <vector>

#include "core/constants.h"
#include "sh/basis.h"

namespace prt {

double ClampedCosineBand(int l) {
  if (l == 0) return kPi;
  if (l == 1) return 2.0 * kPi / 3.0;
  if (l % 2 == 1) return 0.0;
  // C(l, l/2) / 2^l by the running product C(2j, j)/4^j = prod_{i=1..j} (2i-1)/(2i).
  double central = 1.0;
  for (int i = 1; i <= l / 2; ++i) central *= (2.0 * i - 1.0) / (2.0 * i);
  const double sign = ((l / 2 - 1) % 2 == 0) ? 1.0 : -1.0;
  return 2.0 * kPi * sign / ((l + 2.0) * (l - 1.0)) * central;
}

double ClampedCosineZonalCoeff(int l) {
  return ClampedCosineBand(l) * std::sqrt((2.0 * l + 1.0) / (4.0 * kPi));
}

void UnshadowedTransfer(int lmax, const glm::dvec3& n, double* out) {
  EvalBasis(lmax, n, out);
  for (int l = 0; l <= lmax; ++l) {
    const double scale = ClampedCosineBand(l) / kPi;
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) out[k] *= scale;
  }
}

}  // namespace prt
