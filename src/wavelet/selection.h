#pragma once
/// \file
/// Which wavelet coefficients a sparse vector keeps: the `budget` of largest importance, the
/// rest dropped (a non-linear approximation [1, sec. 4]: which ones depends on the vector, so
/// a shadow edge keeps its fine coefficients exactly where it lies). Importance is
///
///   magnitude   |c|                  (the least L2 error for the budget: the basis is orthonormal)
///   area        |c| * support area   (coarse coefficients first; [1, sec. 5.2] found it the
///                                     better choice for lighting)
///
/// with the support area that of the coefficient's square on its face (wavelet/haar.h), in
/// texels. Each face's scaling coefficient (its mean) is kept before any other, under either
/// rule: then a constant light meets every vertex's whole transport (a white sky gives exactly
/// the albedo, however few coefficients are kept), and a kept light keeps its mean. The kept indices are returned in increasing order, which is also the order in which a
/// dot product reads a light's coefficients.
///
/// References
/// [1] Ng, Ramamoorthi, Hanrahan, "All-Frequency Shadows Using Non-linear Wavelet Lighting
///     Approximation", SIGGRAPH 2003.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace prt {

enum class Selection { kMagnitude, kArea };

/// "magnitude" or "area" as a Selection; throws Error for any other name.
Selection SelectionFromName(const std::string& name);
/// The name of `selection`.
const char* SelectionName(Selection selection);
/// Every selection's name, in the enum's order.
std::vector<std::string> SelectionNames();

/// The weight of each coefficient of a cube of faces `face_size` x `face_size` (6 face_size^2,
/// in the texel order of wavelet/cube_grid.h) under `selection`: 1, or its support's area;
/// infinity for the scaling coefficients.
std::vector<double> SelectionWeights(int face_size, Selection selection);

/// The indices of the `budget` entries of `coeffs` (size n) of largest |coeffs[i]| * weights[i],
/// zeros never kept, in increasing order, into `kept` (ties broken by the lower index, so the
/// choice is deterministic).
void KeepLargest(const double* coeffs, const std::vector<double>& weights, std::size_t budget,
                 std::vector<std::uint32_t>& kept);

}  // namespace prt
