#include "sh/convolved_range.h"

#include "sh/dering.h"
#include "sh/window.h"

namespace prt {

ShRange ConvolvedRange(const ShRgb& light, const std::vector<double>& kernel) {
  ShRgb convolved = light;
  ApplyWeights(kernel, convolved);  // band l times k_l (Funk–Hecke)
  ShRgb negated = convolved;
  for (auto& c : negated) c = -c;
  return {LowestRadiance(convolved), -LowestRadiance(negated)};
}

}  // namespace prt
