#include "sh/rotation_course.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "sh/basis.h"

namespace prt {

std::vector<glm::dvec3> CourseDirections(int l) {
  const double k = 1.0 / std::sqrt(2.0);
  if (l == 1) return {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}};
  return {{1, 0, 0}, {0, 0, 1}, {k, k, 0}, {k, 0, k}, {0, k, k}};
}

std::vector<double> SolveRight(const std::vector<double>& A, const std::vector<double>& B, int n) {
  // X A = B  <=>  A^T X^T = B^T: eliminate on the transposed system.
  std::vector<double> a(n * n), b(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      a[i * n + j] = A[j * n + i];
      b[i * n + j] = B[j * n + i];
    }
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int r = col + 1; r < n; ++r)
      if (std::abs(a[r * n + col]) > std::abs(a[pivot * n + col])) pivot = r;
    if (std::abs(a[pivot * n + col]) < 1e-14) throw std::runtime_error("singular direction set");
    for (int j = 0; j < n; ++j) {
      std::swap(a[col * n + j], a[pivot * n + j]);
      std::swap(b[col * n + j], b[pivot * n + j]);
    }
    for (int r = 0; r < n; ++r) {
      if (r == col) continue;
      const double f = a[r * n + col] / a[col * n + col];
      for (int j = 0; j < n; ++j) {
        a[r * n + j] -= f * a[col * n + j];
        b[r * n + j] -= f * b[col * n + j];
      }
    }
  }
  std::vector<double> x(n * n);  // X = (A^T \ B^T)^T
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) x[j * n + i] = b[i * n + j] / a[i * n + i];
  return x;
}

std::vector<double> CourseBandMatrix(const glm::dmat3& R, int l) {
  const int n = 2 * l + 1;
  const auto dirs = CourseDirections(l);
  std::vector<double> A(n * n), B(n * n);  // column i = Y_l(n_i), Y_l(R n_i)
  for (int i = 0; i < n; ++i) {
    const auto y = EvalBasis(l, dirs[i]);
    const auto yr = EvalBasis(l, R * dirs[i]);
    for (int m = 0; m < n; ++m) {
      A[m * n + i] = y[l * l + m];
      B[m * n + i] = yr[l * l + m];
    }
  }
  return SolveRight(A, B, n);
}

}  // namespace prt
