#pragma once
/// \file
/// Indexing of real spherical-harmonic coefficients, defined once for the whole program.
///
/// Bands l = 0..lmax, orders m = -l..l, flat index k = l(l+1) + m, so band l occupies
/// k = l^2 .. (l+1)^2 - 1 and a set of bands 0..lmax has (lmax+1)^2 coefficients.
/// ("Order" is ambiguous in the field: the course's `SHOrder = 2` means lmax = 2, 9 coefficients.)

#include <vector>

#include <glm/vec3.hpp>

namespace prt {

/// Highest band the command line accepts. The basis itself is finite and accurate up to
/// kMaxBasisLmax; 64 bands already mean 4225 coefficients per vertex.
constexpr int kMaxLmax = 64;
/// Highest band the basis evaluator supports (tested finite at every direction).
constexpr int kMaxBasisLmax = 200;

/// Number of coefficients of bands 0..lmax: (lmax+1)^2.
constexpr int CoeffCount(int lmax) { return (lmax + 1) * (lmax + 1); }
/// Flat index of Y_lm: l(l+1) + m.
constexpr int ShIndex(int l, int m) { return l * (l + 1) + m; }

/// RGB coefficients of a light: one linear-RGB triple per basis function.
using ShRgb = std::vector<glm::dvec3>;

/// lmax of a coefficient vector of size `count`, or -1 if `count` is not a perfect square.
int LmaxOfCount(std::size_t count);

/// The coefficients of bands 0..lmax of `light` (all of them when it has fewer).
ShRgb FirstBands(const ShRgb& light, int lmax);

}  // namespace prt
