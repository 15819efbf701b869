#include "wavelet/haar.h"

#include <algorithm>

namespace prt {
namespace {

constexpr double kRootHalf = 0.70710678118654752440;  // 1 / sqrt(2)

/// One step on the first `m` entries of x (stride `stride`): averages to the first half,
/// differences to the second.
void Step(double* x, int m, int stride, double* tmp) {
  const int h = m / 2;
  for (int i = 0; i < h; ++i) {
    const double a = x[(2 * i) * stride], b = x[(2 * i + 1) * stride];
    tmp[i] = (a + b) * kRootHalf;
    tmp[h + i] = (a - b) * kRootHalf;
  }
  for (int i = 0; i < m; ++i) x[i * stride] = tmp[i];
}

/// The inverse of Step.
void Unstep(double* x, int m, int stride, double* tmp) {
  const int h = m / 2;
  for (int i = 0; i < h; ++i) {
    const double s = x[i * stride], d = x[(h + i) * stride];
    tmp[2 * i] = (s + d) * kRootHalf;
    tmp[2 * i + 1] = (s - d) * kRootHalf;
  }
  for (int i = 0; i < m; ++i) x[i * stride] = tmp[i];
}

}  // namespace

void HaarForward(double* data, int n, std::vector<double>& scratch) {
  scratch.resize(static_cast<std::size_t>(n));
  for (int m = n; m >= 2; m /= 2) {
    for (int r = 0; r < m; ++r) Step(data + static_cast<std::size_t>(r) * n, m, 1, scratch.data());
    for (int c = 0; c < m; ++c) Step(data + c, m, n, scratch.data());
  }
}

void HaarInverse(double* data, int n, std::vector<double>& scratch) {
  scratch.resize(static_cast<std::size_t>(n));
  for (int m = 2; m <= n; m *= 2) {
    for (int c = 0; c < m; ++c) Unstep(data + c, m, n, scratch.data());
    for (int r = 0; r < m; ++r) Unstep(data + static_cast<std::size_t>(r) * n, m, 1, scratch.data());
  }
}

int HaarSupport(int row, int col, int n) {
  const int top = std::max(row, col);
  if (top == 0) return n;
  int level = 0;
  while ((2 << level) <= top) ++level;  // 2^level <= top < 2^(level + 1)
  return n >> level;
}

}  // namespace prt
