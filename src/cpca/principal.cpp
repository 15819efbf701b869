#include "cpca/principal.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/rng.h"

namespace prt {
namespace {

/// Below this share of its length before orthogonalisation a row holds only rounding: replaced.
constexpr double kDependent = 1e-9;
/// Jacobi stops once the off-diagonal mass is below this share of the whole (or after kSweeps).
constexpr double kJacobiTolerance = 1e-30;
constexpr int kSweeps = 60;

double Dot(const double* a, const double* b, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}

/// Z = X V^T: z[i * terms + k] = (x_i - m) . v_k, for the members' centred rows. The directions
/// are read transposed (dim x terms), so each row's terms accumulate side by side.
void Project(const float* data, int dim, const std::vector<std::uint32_t>& members, const double* mean, int terms,
             const std::vector<double>& basis, std::vector<double>& z, std::vector<double>& centred) {
  // kLanes terms at a time, the last block padded with zero directions: fixed-length inner loops
  // that the compiler keeps in vector registers.
  constexpr int kLanes = 4;
  const int padded = (terms + kLanes - 1) / kLanes * kLanes;
  z.assign(members.size() * terms, 0.0);
  std::vector<double> across(std::size_t(dim) * padded, 0.0);
  for (int k = 0; k < terms; ++k)
    for (int d = 0; d < dim; ++d) across[std::size_t(d) * padded + k] = basis[std::size_t(k) * dim + d];
  for (std::size_t i = 0; i < members.size(); ++i) {
    const float* x = data + std::size_t(members[i]) * dim;
    for (int d = 0; d < dim; ++d) centred[d] = double(x[d]) - mean[d];
    for (int k0 = 0; k0 < padded; k0 += kLanes) {
      double acc[kLanes] = {};
      for (int d = 0; d < dim; ++d) {
        const double* a = across.data() + std::size_t(d) * padded + k0;
        for (int l = 0; l < kLanes; ++l) acc[l] += a[l] * centred[d];
      }
      for (int l = 0; l < kLanes && k0 + l < terms; ++l) z[i * terms + k0 + l] = acc[l];
    }
  }
}

/// W = Z^T X: row k of `w` = sum_i z[i][k] (x_i - m).
void BackProject(const float* data, int dim, const std::vector<std::uint32_t>& members, const double* mean, int terms,
                 const std::vector<double>& z, std::vector<double>& w, std::vector<double>& centred) {
  w.assign(std::size_t(terms) * dim, 0.0);
  for (std::size_t i = 0; i < members.size(); ++i) {
    const float* x = data + std::size_t(members[i]) * dim;
    for (int d = 0; d < dim; ++d) centred[d] = double(x[d]) - mean[d];
    for (int k = 0; k < terms; ++k) {
      const double f = z[i * terms + k];
      double* row = w.data() + std::size_t(k) * dim;
      for (int d = 0; d < dim; ++d) row[d] += f * centred[d];
    }
  }
}

}  // namespace

void OrthonormalizeRows(int count, int dim, double* rows) {
  int next_axis = 0;
  for (int k = 0; k < count; ++k) {
    double* r = rows + std::size_t(k) * dim;
    for (int attempt = 0;; ++attempt) {
      const double before = std::sqrt(Dot(r, r, dim));
      for (int j = 0; j < k; ++j) {
        const double* q = rows + std::size_t(j) * dim;
        const double f = Dot(r, q, dim);
        for (int d = 0; d < dim; ++d) r[d] -= f * q[d];
      }
      const double after = std::sqrt(Dot(r, r, dim));
      if (after > 0.0 && after > kDependent * before) {
        for (int d = 0; d < dim; ++d) r[d] /= after;
        break;
      }
      // Nothing left of this row: the next unit axis (one of dim is always independent of k < dim rows).
      if (next_axis >= dim || attempt > dim) {
        std::fill(r, r + dim, 0.0);  // cannot happen for count <= dim; keeps the row harmless
        break;
      }
      std::fill(r, r + dim, 0.0);
      r[next_axis++] = 1.0;
    }
  }
}

void SymmetricEigen(int k, std::vector<double>& a, std::vector<double>& values, std::vector<double>& vectors) {
  // Cyclic Jacobi: rotate away each off-diagonal (p, q) in a fixed order. v accumulates the
  // rotations, its columns the eigenvectors.
  std::vector<double> v(std::size_t(k) * k, 0.0);
  for (int i = 0; i < k; ++i) v[i * k + i] = 1.0;
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    double off = 0.0, total = 0.0;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) (i == j ? total : off) += a[i * k + j] * a[i * k + j];
    if (off <= kJacobiTolerance * (total + off)) break;
    for (int p = 0; p < k; ++p)
      for (int q = p + 1; q < k; ++q) {
        const double apq = a[p * k + q];
        if (apq == 0.0) continue;
        const double theta = (a[q * k + q] - a[p * k + p]) / (2.0 * apq);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int r = 0; r < k; ++r) {  // A <- A J (columns p, q)
          const double arp = a[r * k + p], arq = a[r * k + q];
          a[r * k + p] = c * arp - s * arq;
          a[r * k + q] = s * arp + c * arq;
        }
        for (int r = 0; r < k; ++r) {  // A <- J^T A (rows p, q)
          const double apr = a[p * k + r], aqr = a[q * k + r];
          a[p * k + r] = c * apr - s * aqr;
          a[q * k + r] = s * apr + c * aqr;
        }
        for (int r = 0; r < k; ++r) {
          const double vrp = v[r * k + p], vrq = v[r * k + q];
          v[r * k + p] = c * vrp - s * vrq;
          v[r * k + q] = s * vrp + c * vrq;
        }
      }
  }
  // Decreasing eigenvalue; ties keep index order (stable).
  std::vector<int> order(k);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&a, k](int x, int y) { return a[x * k + x] > a[y * k + y]; });
  values.resize(k);
  vectors.assign(std::size_t(k) * k, 0.0);
  for (int j = 0; j < k; ++j) {
    values[j] = a[order[j] * k + order[j]];
    for (int r = 0; r < k; ++r) vectors[j * k + r] = v[r * k + order[j]];
  }
}

void RefinePrincipalDirections(const float* data, int dim, const std::vector<std::uint32_t>& members,
                               const double* mean, int terms, int steps, std::uint64_t seed, std::vector<double>& basis) {
  if (terms <= 0) return;
  basis.resize(std::size_t(terms) * dim, 0.0);
  std::vector<double> z, w, centred(dim);
  const bool cold = std::all_of(basis.begin(), basis.end(), [](double x) { return x == 0.0; });
  if (cold) {
    // A random combination of the members (signs from the cluster's own stream): one power step
    // from a random start, so no direction of the data starts orthogonal to the basis.
    Pcg32 rng(seed, 0);
    z.resize(members.size() * terms);
    for (double& x : z) x = (rng.NextU32() & 1u) ? 1.0 : -1.0;
    BackProject(data, dim, members, mean, terms, z, basis, centred);
  }
  OrthonormalizeRows(terms, dim, basis.data());
  for (int s = 0; s < steps; ++s) {
    Project(data, dim, members, mean, terms, basis, z, centred);
    BackProject(data, dim, members, mean, terms, z, w, centred);
    basis.swap(w);
    OrthonormalizeRows(terms, dim, basis.data());
  }
  // Rayleigh–Ritz: the best directions within the span, ordered by the variance they hold.
  Project(data, dim, members, mean, terms, basis, z, centred);
  std::vector<double> h(std::size_t(terms) * terms, 0.0), values, vectors;
  for (std::size_t i = 0; i < members.size(); ++i)
    for (int a = 0; a < terms; ++a)
      for (int b = 0; b < terms; ++b) h[a * terms + b] += z[i * terms + a] * z[i * terms + b];
  SymmetricEigen(terms, h, values, vectors);
  w.assign(std::size_t(terms) * dim, 0.0);
  for (int j = 0; j < terms; ++j)
    for (int k = 0; k < terms; ++k) {
      const double f = vectors[j * terms + k];
      for (int d = 0; d < dim; ++d) w[std::size_t(j) * dim + d] += f * basis[std::size_t(k) * dim + d];
    }
  basis.swap(w);
  OrthonormalizeRows(terms, dim, basis.data());  // rounding of the rotation; keeps the order
}

}  // namespace prt
