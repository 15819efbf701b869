#pragma once
/// \file
/// Gauss–Legendre product quadrature on the sphere.
///
/// With n Gauss–Legendre nodes z_i (weights w_i) in z = cos(theta) and 2n equally spaced
/// azimuths, sum_i sum_j f(z_i, phi_j) w_i (2 pi / 2n) integrates every spherical polynomial of
/// degree <= 2n - 1 exactly [1]. Any product Y_lm Y_l'm' with l, l' < n is such a polynomial,
/// so this quadrature checks orthonormality exactly and projects smooth functions (the
/// procedural sky) with spectral accuracy.
///
/// References
/// [1] Atkinson, Han, "Spherical Harmonics and Approximations on the Unit Sphere", Springer
///     2012, section 5.2 (product Gauss rules).
/// [2] Golub, Welsch, "Calculation of Gauss quadrature rules", 1969 (nodes found here instead
///     by Newton's method on P_n, started at the Chebyshev-like guesses cos(pi (i - 1/4)/(n + 1/2))).

#include <vector>

#include <glm/vec3.hpp>

namespace prt {

struct SphereQuadrature {
  std::vector<glm::dvec3> directions;  ///< unit
  std::vector<double> weights;         ///< solid angle each; sum 4 pi
};

/// n Gauss–Legendre nodes and weights on [-1, 1], nodes ascending.
void GaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights);

/// The product rule of n nodes in z and 2n in phi: exact for degree <= 2n - 1.
SphereQuadrature GaussSphere(int n);

}  // namespace prt
