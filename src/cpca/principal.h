#pragma once
/// \file
/// The principal directions of a set of vectors: what one cluster of CPCA keeps (cpca.h).
///
/// For rows x_i (i in `members`) with mean m, the K principal directions are the top K
/// eigenvectors of the covariance C = sum_i (x_i - m)(x_i - m)^T: the orthonormal p_1..p_K that
/// minimise sum_i || (x_i - m) - sum_k (p_k . (x_i - m)) p_k ||^2 (Eckart–Young [1]).
///
/// Found without forming C (dim x dim, 390 625 entries at lmax 4) by subspace iteration [2]:
/// V <- orth(X^T X V), X the centred rows, each step 4 m dim K multiply-adds, then one
/// Rayleigh–Ritz step (the K x K matrix Z^T Z, Z = X V^T, diagonalised by cyclic Jacobi) so the
/// directions come out ordered by the variance they hold. Orthonormalisation is modified
/// Gram–Schmidt; a direction with nothing left (fewer distinct members than K, or a rank-deficient
/// cluster) is replaced by the next unit axis orthogonal to the others, so the basis is always
/// orthonormal and K = dim is lossless. Everything is serial and in a fixed order: the result does
/// not depend on the thread that runs it.
///
/// References
/// [1] Eckart, Young, "The approximation of one matrix by another of lower rank", Psychometrika 1936.
/// [2] Golub, Van Loan, "Matrix Computations", 4th ed., sec. 8.3.7 (orthogonal iteration), 8.5 (Jacobi).

#include <cstdint>
#include <vector>

namespace prt {

/// Refines `basis` (terms x dim doubles, row k the k-th direction) toward the top `terms`
/// principal directions of the rows data[r * dim ...] for r in `members`, about `mean` (dim
/// doubles), by `steps` steps of subspace iteration from what `basis` holds (a warm start; a
/// basis of zeros is started from `seed`'s random combination of the members). On return the
/// rows are orthonormal and ordered by decreasing variance. Requires terms <= dim.
void RefinePrincipalDirections(const float* data, int dim, const std::vector<std::uint32_t>& members,
                               const double* mean, int terms, int steps, std::uint64_t seed, std::vector<double>& basis);

/// Orthonormalises the rows of `rows` (count x dim) in place by modified Gram–Schmidt, in row
/// order; a row with (nearly) nothing left is replaced by the first unit axis that is not.
void OrthonormalizeRows(int count, int dim, double* rows);

/// Eigen-decomposition of the symmetric `k` x `k` matrix `a` (row-major, destroyed) by cyclic
/// Jacobi: eigenvalues in decreasing order into `values`, eigenvector j as row j of `vectors`.
void SymmetricEigen(int k, std::vector<double>& a, std::vector<double>& values, std::vector<double>& vectors);

}  // namespace prt
