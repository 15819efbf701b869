#include "app/seen_ringing.h"

#include "sh/convolved_range.h"
#include "sh/zonal.h"

namespace prt {

std::vector<ShownLight> ShownLights(const Material& material, View view, int lmax) {
  std::vector<double> irradiance(lmax + 1);
  for (int l = 0; l <= lmax; ++l) irradiance[l] = ClampedCosineBand(l);
  const bool lobe = material.glossy && material.ks > 0;
  std::vector<ShownLight> shown;
  if (view == View::kRadiance || view == View::kIrradiance) shown.push_back({"the irradiance", irradiance});
  if (lobe && (view == View::kRadiance || view == View::kGlossy))
    shown.push_back({"the light seen through the glossy lobe", material.lobe.ZonalCoefficients(lmax)});
  if (view == View::kLight) shown.push_back({"the light", std::vector<double>(lmax + 1, 1.0)});
  return shown;
}

SeenRinging FindSeenRinging(const ShRgb& light, const Material& material, View view) {
  SeenRinging worst;
  double worst_share = 0;  // lowest / peak of the worst so far
  for (const ShownLight& shown : ShownLights(material, view, LmaxOfCount(light.size()))) {
    const ShRange range = ConvolvedRange(light, shown.kernel);
    const double share = range.highest > 0 ? range.lowest / range.highest : 0.0;
    if (!worst.what.empty() && share >= worst_share) continue;
    worst = {share < -kSeenRingingTolerance, shown.name, range.lowest, range.highest};
    worst_share = share;
  }
  return worst;
}

}  // namespace prt
