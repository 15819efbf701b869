#include "sh/window.h"

#include <cmath>
#include <optional>

#include "core/constants.h"
#include "core/error.h"
#include "core/name_table.h"

namespace prt {
namespace {

constexpr auto kWindows = MakeNameTable<Window>({
    {Window::kNone, "none"},
    {Window::kHann, "hann"},
    {Window::kLanczos, "lanczos"},
});
static_assert(kWindows.Distinct());

}  // namespace

const char* WindowName(Window w) { return kWindows.Name(w); }

std::vector<std::string> WindowNames() { return kWindows.Names(); }

double WindowWeight(Window w, int l, int lmax) {
  const double x = kPi * l / (lmax + 1.0);
  switch (w) {
    case Window::kHann: return 0.5 * (1.0 + std::cos(x));
    case Window::kLanczos: return l == 0 ? 1.0 : std::sin(x) / x;
    default: return 1.0;
  }
}

Window WindowFromName(const std::string& name) {
  if (const std::optional<Window> w = kWindows.Find(name)) return *w;
  throw Error("window '" + name + "' is not one of " + kWindows.Joined(", ", ", "));
}

void ApplyWeights(const std::vector<double>& weights, ShRgb& coeffs) {
  const int lmax = LmaxOfCount(coeffs.size());
  for (int l = 0; l <= lmax; ++l)
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) coeffs[k] *= weights[l];
}

void ApplyWindow(Window w, ShRgb& coeffs) {
  const int lmax = LmaxOfCount(coeffs.size());
  std::vector<double> weights(lmax + 1);
  for (int l = 0; l <= lmax; ++l) weights[l] = WindowWeight(w, l, lmax);
  ApplyWeights(weights, coeffs);
}

}  // namespace prt
