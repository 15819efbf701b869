#include "sh/window.h"

#include <cmath>

namespace prt {

const char* WindowName(Window w) {
  switch (w) {
    case Window::kHann: return "hann";
    case Window::kLanczos: return "lanczos";
    default: return "none";
  }
}

double WindowWeight(Window w, int l, int lmax) {
  constexpr double kPi = 3.14159265358979323846;
  const double x = kPi * l / (lmax + 1.0);
  switch (w) {
    case Window::kHann: return 0.5 * (1.0 + std::cos(x));
    case Window::kLanczos: return l == 0 ? 1.0 : std::sin(x) / x;
    default: return 1.0;
  }
}

void ApplyWindow(Window w, ShRgb& coeffs) {
  const int lmax = LmaxOfCount(coeffs.size());
  for (int l = 0; l <= lmax; ++l) {
    const double weight = WindowWeight(w, l, lmax);
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) coeffs[k] *= weight;
  }
}

}  // namespace prt

#include <algorithm>
#include <vector>

#include "sh/basis.h"
#include "sh/quadrature.h"

namespace prt {

double MinReconstruction(const ShRgb& coeffs) {
  const int lmax = LmaxOfCount(coeffs.size());
  const SphereQuadrature grid = GaussSphere(lmax + 8);
  std::vector<double> y(coeffs.size());
  double lowest = 1e300;
  for (const auto& d : grid.directions) {
    EvalBasis(lmax, d, y.data());
    glm::dvec3 v(0.0);
    for (std::size_t k = 0; k < coeffs.size(); ++k) v += y[k] * coeffs[k];
    lowest = std::min({lowest, v.x, v.y, v.z});
  }
  return lowest;
}

AutoWindow ChooseWindow(const ShRgb& coeffs) {
  // Mean radiance is c_00 Y_00; 1e-9 of it is the "rounding" floor.
  const double mean = std::max({coeffs[0].x, coeffs[0].y, coeffs[0].z}) * 0.28209479177387814;
  const double floor = -1e-9 * std::max(mean, 1e-300);
  AutoWindow result{Window::kNone, MinReconstruction(coeffs), 0.0};
  for (Window w : {Window::kNone, Window::kLanczos, Window::kHann}) {
    ShRgb windowed = coeffs;
    ApplyWindow(w, windowed);
    result.window = w;
    result.min_after = (w == Window::kNone) ? result.min_before : MinReconstruction(windowed);
    if (result.min_after >= floor) break;
  }
  return result;
}

}  // namespace prt
