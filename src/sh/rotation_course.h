#pragma once
/// \file
/// The course's rotation method for bands 1 and 2, kept for teaching and cross-checked against
/// the exact band matrices of sh/rotation.h (tests/sh/test_rotation.cpp).
///
/// Band l is a (2l+1)-dimensional space closed under rotation, so D_l is fixed by its action on
/// 2l+1 directions n_i whose basis vectors are linearly independent. Stack A = [Y_l(n_i)] and
/// B = [Y_l(R n_i)] as columns: Y_l(R d) = D_l Y_l(d) at every n_i gives B = D_l A, so
/// D_l = B A^-1. Exact whenever A is invertible; its accuracy follows A's condition number
/// (1 for the course's band-1 directions, 2.74 for its band-2 ones). For high bands, good
/// point sets get hard to find, which is why the program uses Wigner's d (sh/rotation.h).

#include <vector>

#include <glm/mat3x3.hpp>

namespace prt {

/// D_l(R) for l = 1 or 2 by the projection method, row-major (2l+1)^2 entries.
std::vector<double> CourseBandMatrix(const glm::dmat3& R, int l);

/// The course's sample directions for band l (1 or 2).
std::vector<glm::dvec3> CourseDirections(int l);

/// Solves X A = B for X (all n x n, row-major) by Gauss–Jordan with partial pivoting.
std::vector<double> SolveRight(const std::vector<double>& A, const std::vector<double>& B, int n);

}  // namespace prt
