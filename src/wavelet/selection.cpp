#include "wavelet/selection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/error.h"
#include "core/name_table.h"
#include "wavelet/haar.h"

namespace prt {
namespace {

constexpr auto kSelections = MakeNameTable<Selection>({
    {Selection::kMagnitude, "magnitude"},
    {Selection::kArea, "area"},
});
static_assert(kSelections.Distinct());

}  // namespace

Selection SelectionFromName(const std::string& name) {
  if (const std::optional<Selection> s = kSelections.Find(name)) return *s;
  throw Error("wavelet selection '" + name + "': expected " + kSelections.Joined(", ", " or "));
}

const char* SelectionName(Selection selection) { return kSelections.Name(selection); }

std::vector<std::string> SelectionNames() { return kSelections.Names(); }

std::vector<double> SelectionWeights(int face_size, Selection selection) {
  const std::size_t per_face = static_cast<std::size_t>(face_size) * face_size;
  std::vector<double> w(6 * per_face, 1.0);
  // Each face's scaling coefficient first, whatever its size: the mean over the face.
  for (int f = 0; f < 6; ++f) w[f * per_face] = std::numeric_limits<double>::infinity();
  if (selection == Selection::kMagnitude) return w;
  for (std::size_t i = 1; i < per_face; ++i) {
    const int side = HaarSupport(static_cast<int>(i / face_size), static_cast<int>(i % face_size), face_size);
    for (int f = 0; f < 6; ++f) w[f * per_face + i] = double(side) * side;
  }
  return w;
}

void KeepLargest(const double* coeffs, const std::vector<double>& weights, std::size_t budget,
                 std::vector<std::uint32_t>& kept) {
  kept.clear();
  const std::size_t n = weights.size();
  for (std::size_t i = 0; i < n; ++i)
    if (coeffs[i] != 0.0) kept.push_back(static_cast<std::uint32_t>(i));
  if (kept.size() > budget) {
    const auto more_important = [&](std::uint32_t a, std::uint32_t b) {
      const double ia = std::abs(coeffs[a]) * weights[a], ib = std::abs(coeffs[b]) * weights[b];
      return ia != ib ? ia > ib : a < b;
    };
    std::nth_element(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(budget), kept.end(), more_important);
    kept.resize(budget);
  }
  std::sort(kept.begin(), kept.end());
}

}  // namespace prt
