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
