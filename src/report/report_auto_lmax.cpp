#include "report/report_auto_lmax.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>

#include "precompute/light.h"
#include "sh/zonal.h"

namespace prt {

AutoLmax ChooseLmax(const Environment& env, double tolerance, int max_lmax) {
  const int ref = std::max(kAutoReferenceLmax, max_lmax);
  const ShRgb light = ProjectLight(env, ref);
  // Energy of the irradiance per band.
  std::vector<double> band(ref + 1, 0.0);
  double total = 0.0;
  for (int l = 0; l <= ref; ++l) {
    const double a = ClampedCosineBand(l);
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) band[l] += a * a * glm::dot(light[k], light[k]);
    total += band[l];
  }
  // e[l]: relative irradiance error after truncating at band l.
  std::vector<double> e(max_lmax + 1);
  double tail = total;
  for (int l = 0; l <= max_lmax; ++l) {
    tail -= band[l];
    e[l] = total > 0 ? std::sqrt(std::max(tail, 0.0) / total) : 0.0;
  }
  AutoLmax result;
  result.lmax = max_lmax;
  for (int l = 0; l <= max_lmax; ++l)
    if (e[l] <= tolerance) {
      result.lmax = l;
      break;
    }
  result.error = e[result.lmax];
  char b[256];
  std::snprintf(b, sizeof b, "lmax auto -> %d: irradiance error %.3g against %d bands is %s the tolerance %.3g",
                result.lmax, result.error, ref, result.error <= tolerance ? "within" : "still above (highest band allowed)",
                tolerance);
  result.why = b;
  if (result.lmax > 0) {
    std::snprintf(b, sizeof b, "; lmax %d would give %.3g", result.lmax - 1, e[result.lmax - 1]);
    result.why += b;
  }
  return result;
}

}  // namespace prt
