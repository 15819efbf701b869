#include "cpca/cpca.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/parallel.h"
#include "core/rng.h"
#include "cpca/principal.h"

namespace prt {
namespace {

constexpr std::size_t kRowGrain = 256;  // rows per ParallelFor chunk (fixed: results do not depend on threads)

/// Projections run kLanes terms at a time (independent sums the compiler keeps in vector registers).
constexpr int kLanes = 4;

/// The clusters while they are fitted: means and directions in double.
struct Fit {
  int dim = 0, terms = 0;
  std::vector<std::vector<double>> mean, basis;  // per cluster: dim; terms x dim
  /// Per cluster the directions transposed, dim x padded (padded = terms rounded up to kLanes,
  /// the extra columns 0): for projecting a row on every direction in one pass.
  std::vector<std::vector<double>> across;
  int padded() const { return (terms + kLanes - 1) / kLanes * kLanes; }
  void Transpose(std::size_t c) {
    const int p = padded();
    across[c].assign(std::size_t(dim) * p, 0.0);
    for (int k = 0; k < terms; ++k)
      for (int d = 0; d < dim; ++d) across[c][std::size_t(d) * p + k] = basis[c][std::size_t(k) * dim + d];
  }
};

/// sum_d (x_d - m_d)^2 with kLanes partial sums (a fixed order: the same on every thread).
double SquaredDistance(const float* x, const double* m, int dim, double* centred = nullptr) {
  double lane[kLanes] = {};
  int d = 0;
  for (; d + kLanes <= dim; d += kLanes)
    for (int l = 0; l < kLanes; ++l) {
      const double e = double(x[d + l]) - m[d + l];
      if (centred) centred[d + l] = e;
      lane[l] += e * e;
    }
  double s = (lane[0] + lane[1]) + (lane[2] + lane[3]);
  for (; d < dim; ++d) {
    const double e = double(x[d]) - m[d];
    if (centred) centred[d] = e;
    s += e * e;
  }
  return s;
}

/// out[k] = p_k . centred for every direction (padded columns give 0).
void ProjectAll(const double* across, int dim, int padded, const double* centred, double* out) {
  std::fill(out, out + padded, 0.0);
  for (int k0 = 0; k0 < padded; k0 += kLanes) {
    double acc[kLanes] = {};
    for (int d = 0; d < dim; ++d) {
      const double* a = across + std::size_t(d) * padded + k0;
      for (int l = 0; l < kLanes; ++l) acc[l] += a[l] * centred[d];
    }
    for (int l = 0; l < kLanes; ++l) out[k0 + l] = acc[l];
  }
}

/// error(x, c) of cpca.h: what the cluster's mean and K directions leave of x, squared.
double ResidualError(const float* x, const Fit& fit, int c, std::vector<double>& centred, std::vector<double>& w) {
  double total = SquaredDistance(x, fit.mean[c].data(), fit.dim, centred.data());
  ProjectAll(fit.across[c].data(), fit.dim, fit.padded(), centred.data(), w.data());
  for (int k = 0; k < fit.terms; ++k) total -= w[k] * w[k];
  return std::max(0.0, total);
}

/// Step 1: k-means++ seeds; returns each row's nearest seed and sets the fit's means.
std::vector<std::uint32_t> SeedClusters(const float* data, std::size_t rows, int dim, int clusters, std::uint64_t seed,
                                        Fit& fit) {
  Pcg32 rng(seed, 0x5eed);
  std::vector<double> d2(rows, std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> nearest(rows, 0);
  std::vector<char> chosen(rows, 0);
  std::size_t pick = std::min(rows - 1, std::size_t(rng.NextDouble() * double(rows)));
  for (int c = 0; c < clusters; ++c) {
    chosen[pick] = 1;
    fit.mean[c].assign(data + pick * dim, data + (pick + 1) * dim);
    const double* m = fit.mean[c].data();
    ParallelFor(rows, kRowGrain, [&](std::size_t begin, std::size_t end) {
      for (std::size_t r = begin; r < end; ++r) {
        const double e = SquaredDistance(data + r * dim, m, dim);
        if (e < d2[r]) d2[r] = e, nearest[r] = std::uint32_t(c);
      }
    });
    nearest[pick] = std::uint32_t(c), d2[pick] = 0.0;  // a seed is its own cluster's, even where it repeats a row
    if (c + 1 == clusters) break;
    // The next seed: drawn with probability d2 / sum d2, scanned in row order.
    double total = 0.0;
    for (std::size_t r = 0; r < rows; ++r) total += chosen[r] ? 0.0 : d2[r];
    pick = rows;
    if (total > 0.0) {
      const double u = rng.NextDouble() * total;
      double run = 0.0;
      for (std::size_t r = 0; r < rows; ++r) {
        if (chosen[r] || d2[r] <= 0.0) continue;
        run += d2[r];
        pick = r;  // the last positive row, should rounding leave u beyond the sum
        if (run > u) break;
      }
    }
    if (pick == rows)  // every row equals a seed: the next row not chosen
      pick = std::size_t(std::find(chosen.begin(), chosen.end(), 0) - chosen.begin());
  }
  return nearest;
}

/// Each cluster's members, in row order.
std::vector<std::vector<std::uint32_t>> Members(const std::vector<std::uint32_t>& cluster, int clusters) {
  std::vector<std::vector<std::uint32_t>> members(clusters);
  for (std::size_t r = 0; r < cluster.size(); ++r) members[cluster[r]].push_back(std::uint32_t(r));
  return members;
}

/// Step 2: means and principal directions of every non-empty cluster.
void FitClusters(const float* data, const std::vector<std::uint32_t>& cluster, int steps, std::uint64_t seed, Fit& fit) {
  const int clusters = int(fit.mean.size()), dim = fit.dim;
  const auto members = Members(cluster, clusters);
  ParallelFor(std::size_t(clusters), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c) {
      const auto& in = members[c];
      if (in.empty()) continue;
      std::vector<double>& m = fit.mean[c];
      std::fill(m.begin(), m.end(), 0.0);
      for (std::uint32_t r : in)
        for (int d = 0; d < dim; ++d) m[d] += double(data[std::size_t(r) * dim + d]);
      for (double& x : m) x /= double(in.size());
      RefinePrincipalDirections(data, dim, in, m.data(), fit.terms, steps, MixSeed(seed, c), fit.basis[c]);
      fit.Transpose(c);
    }
  });
}

/// For each cluster, itself and the `count` other clusters whose means are nearest to its own.
std::vector<std::vector<std::uint32_t>> CandidateLists(const Fit& fit, int count) {
  const int clusters = int(fit.mean.size());
  std::vector<std::vector<std::uint32_t>> lists(clusters);
  ParallelFor(std::size_t(clusters), 4, [&](std::size_t begin, std::size_t end) {
    std::vector<std::pair<double, std::uint32_t>> by_distance(clusters);
    for (std::size_t c = begin; c < end; ++c) {
      for (int o = 0; o < clusters; ++o) {
        double s = 0.0;
        for (int d = 0; d < fit.dim; ++d) {
          const double e = fit.mean[c][d] - fit.mean[o][d];
          s += e * e;
        }
        by_distance[o] = {o == int(c) ? -1.0 : s, std::uint32_t(o)};  // itself first
      }
      const int keep = std::min(clusters, count + 1);
      std::partial_sort(by_distance.begin(), by_distance.begin() + keep, by_distance.end());
      for (int i = 0; i < keep; ++i) lists[c].push_back(by_distance[i].second);
    }
  });
  return lists;
}

/// Step 3: each row to its least-error candidate; returns each row's error there.
std::vector<double> AssignRows(const float* data, std::size_t rows, const Fit& fit, int candidates,
                               std::vector<std::uint32_t>& cluster) {
  const auto lists = CandidateLists(fit, candidates);
  std::vector<double> error(rows);
  ParallelFor(rows, kRowGrain, [&](std::size_t begin, std::size_t end) {
    std::vector<double> centred(fit.dim), w(fit.padded());
    for (std::size_t r = begin; r < end; ++r) {
      const float* x = data + r * fit.dim;
      std::uint32_t best = cluster[r];
      double best_error = std::numeric_limits<double>::infinity();
      for (std::uint32_t c : lists[cluster[r]]) {
        const double e = ResidualError(x, fit, int(c), centred, w);
        if (e < best_error || (e == best_error && c < best)) best_error = e, best = c;
      }
      cluster[r] = best;
      error[r] = best_error;
    }
  });
  return error;
}

/// A cluster left empty takes the worst-reconstructed row of a cluster that has more than one.
void ReseedEmpty(const float* data, const std::vector<double>& error, std::vector<std::uint32_t>& cluster, Fit& fit) {
  const int clusters = int(fit.mean.size());
  std::vector<std::size_t> count(clusters, 0);
  for (std::uint32_t c : cluster) ++count[c];
  if (std::find(count.begin(), count.end(), std::size_t(0)) == count.end()) return;
  std::vector<std::uint32_t> order(cluster.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&error](std::uint32_t a, std::uint32_t b) { return error[a] > error[b]; });
  std::size_t next = 0;
  for (int c = 0; c < clusters; ++c) {
    if (count[c] > 0) continue;
    while (next < order.size() && count[cluster[order[next]]] <= 1) ++next;
    if (next == order.size()) break;
    const std::uint32_t r = order[next++];
    --count[cluster[r]];
    cluster[r] = std::uint32_t(c);
    count[c] = 1;
    fit.mean[c].assign(data + std::size_t(r) * fit.dim, data + (std::size_t(r) + 1) * fit.dim);
    std::fill(fit.basis[c].begin(), fit.basis[c].end(), 0.0);  // a cold start
  }
}

}  // namespace

void CpcaModel::Reconstruct(std::size_t r, float* out) const {
  const std::uint32_t c = cluster[r];
  const float* m = means.data() + std::size_t(c) * dim;
  for (int d = 0; d < dim; ++d) out[d] = m[d];
  for (int k = 0; k < terms; ++k) {
    const float w = weights[r * terms + k];
    const float* p = principal.data() + (std::size_t(c) * terms + k) * dim;
    for (int d = 0; d < dim; ++d) out[d] += w * p[d];
  }
}

std::uint64_t CpcaModel::Bytes() const {
  return (means.size() + principal.size() + weights.size()) * sizeof(float) + cluster.size() * sizeof(std::uint32_t);
}

CpcaModel CompressCpca(const float* data, std::size_t rows, int dim, const CpcaOptions& o) {
  CpcaModel model;
  model.dim = dim;
  model.rows = rows;
  model.clusters = int(std::min<std::size_t>(std::max(1, o.clusters), rows));
  model.terms = std::clamp(o.terms, 0, dim);
  const int clusters = model.clusters, terms = model.terms;
  Fit fit;
  fit.dim = dim;
  fit.terms = terms;
  fit.mean.assign(clusters, std::vector<double>(dim, 0.0));
  fit.basis.assign(clusters, std::vector<double>(std::size_t(terms) * dim, 0.0));
  fit.across.resize(clusters);
  for (int c = 0; c < clusters; ++c) fit.Transpose(c);  // valid (zero) directions for any cluster never fitted

  std::vector<std::uint32_t> cluster = SeedClusters(data, rows, dim, clusters, o.seed, fit);
  // Seeds are rows: none is empty after the nearest-seed assignment (a seed is its own nearest).
  FitClusters(data, cluster, 4 * o.power_steps, o.seed, fit);
  for (int it = 0; it < o.iterations; ++it) {
    const std::vector<double> error = AssignRows(data, rows, fit, o.candidates, cluster);
    ReseedEmpty(data, error, cluster, fit);
    FitClusters(data, cluster, o.power_steps, o.seed, fit);
  }

  // The model in floats; the weights project on the float mean and directions it stores.
  model.means.resize(std::size_t(clusters) * dim);
  model.principal.resize(std::size_t(clusters) * terms * dim);
  for (int c = 0; c < clusters; ++c) {
    std::copy(fit.mean[c].begin(), fit.mean[c].end(), model.means.begin() + std::size_t(c) * dim);
    std::copy(fit.basis[c].begin(), fit.basis[c].end(), model.principal.begin() + std::size_t(c) * terms * dim);
  }
  model.cluster = cluster;
  model.weights.assign(rows * terms, 0.0f);
  ParallelFor(rows, kRowGrain, [&](std::size_t begin, std::size_t end) {
    std::vector<double> centred(dim);
    for (std::size_t r = begin; r < end; ++r) {
      const float* x = data + r * dim;
      const float* m = model.means.data() + std::size_t(cluster[r]) * dim;
      for (int d = 0; d < dim; ++d) centred[d] = double(x[d]) - double(m[d]);
      for (int k = 0; k < terms; ++k) {
        const float* p = model.principal.data() + (std::size_t(cluster[r]) * terms + k) * dim;
        double w = 0.0;
        for (int d = 0; d < dim; ++d) w += double(p[d]) * centred[d];
        model.weights[r * terms + k] = float(w);
      }
    }
  });
  return model;
}

double CpcaRelativeError(const CpcaModel& model, const float* data) {
  const std::size_t chunks = ChunkCount(model.rows, kRowGrain);
  std::vector<double> err(chunks, 0.0), norm(chunks, 0.0);
  ParallelFor(model.rows, kRowGrain, [&](std::size_t begin, std::size_t end) {
    std::vector<float> y(model.dim);
    double e = 0.0, n = 0.0;
    for (std::size_t r = begin; r < end; ++r) {
      model.Reconstruct(r, y.data());
      for (int d = 0; d < model.dim; ++d) {
        const double x = data[r * model.dim + d];
        e += (x - y[d]) * (x - y[d]);
        n += x * x;
      }
    }
    err[begin / kRowGrain] = e, norm[begin / kRowGrain] = n;
  });
  double e = 0.0, n = 0.0;
  for (std::size_t c = 0; c < chunks; ++c) e += err[c], n += norm[c];  // chunk order
  return n > 0.0 ? std::sqrt(e / n) : 0.0;
}

}  // namespace prt
