#pragma once
/// \file
/// Clustered principal component analysis (CPCA) of a set of vectors (Sloan, Hall, Hart, Snyder
/// 2003 [1]): what compresses the glossy transfer matrices (cpca_transfer.h), one vector of
/// dim = n^2 floats per vertex and colour channel.
///
/// The rows x_r are split into clusters; cluster c keeps its mean m_c and K orthonormal principal
/// directions p_c1..p_cK (principal.h), each row its cluster and K weights:
///
///   x_r ~ m_c + sum_k w_rk p_ck,     w_rk = p_ck . (x_r - m_c)  (the projection: orthonormal p).
///
/// A row then takes K floats (and its cluster index) instead of dim, the clusters C (K + 1) dim.
/// Within a cluster this is the best rank-K affine fit (Eckart–Young); across clusters the
/// assignment is what matters, and CPCA makes it by the error that counts, not the distance to
/// the mean:
///
///   error(x, c) = || x - m_c ||^2 - sum_k (p_ck . (x - m_c))^2,
///
/// the squared residual left after the cluster's own K-term reconstruction [1, sec. 3]. The
/// iteration, like k-means with a subspace per cluster ("iterative CPCA" of [1]):
///
///   1. seed C means by k-means++ [2] (the first row at random, each next one drawn with
///      probability proportional to its squared distance to the nearest mean so far; draws from
///      a PCG stream of `seed`); every row joins its nearest mean;
///   2. fit: each cluster's mean and K principal directions of its members (warm-started
///      subspace iteration: `power_steps` steps, principal.h);
///   3. assign: each row to the cluster of least error(x, c) among its current cluster and the
///      `candidates` clusters whose means lie nearest to that cluster's mean (all C when C <=
///      candidates: an exact search); ties go to the lower index. A cluster left empty takes the
///      row reconstructed worst (largest error first, then lowest index);
///   4. repeat 2-3 `iterations` times, then fit once more and project the weights.
///
/// The candidate list is the one approximation: it keeps an iteration at O(rows candidates K dim)
/// instead of O(rows C K dim), and a row moves between clusters whose means are near, as it does
/// after the first iterations. Every step is per row or per cluster, serial inside, and every
/// reduction runs in a fixed order: the result is the same for any thread count.
///
/// References
/// [1] Sloan, Hall, Hart, Snyder, "Clustered Principal Components for Precomputed Radiance
///     Transfer", SIGGRAPH 2003.
/// [2] Arthur, Vassilvitskii, "k-means++: The Advantages of Careful Seeding", SODA 2007.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace prt {

struct CpcaOptions {
  int clusters = 256;     ///< C, at most the number of rows
  int terms = 4;          ///< K principal directions per cluster, at most dim
  int iterations = 4;     ///< fit + assign rounds after seeding
  int power_steps = 2;    ///< subspace-iteration steps per fit (the first fit takes 4 x as many)
  int candidates = 8;     ///< clusters tried per row besides its own (by nearest mean)
  std::uint64_t seed = 1;
};

/// The compressed rows: means[c * dim + d], principal[(c * terms + k) * dim + d],
/// cluster[r], weights[r * terms + k].
struct CpcaModel {
  int dim = 0, clusters = 0, terms = 0;
  std::size_t rows = 0;
  std::vector<float> means, principal;
  std::vector<std::uint32_t> cluster;
  std::vector<float> weights;

  /// Row r as the model reconstructs it, into `out` (dim floats).
  void Reconstruct(std::size_t r, float* out) const;
  /// Bytes the model takes (floats and 32-bit cluster indices).
  std::uint64_t Bytes() const;
};

/// Compresses `rows` vectors of `dim` floats (row r at data + r * dim). Requires rows >= 1.
CpcaModel CompressCpca(const float* data, std::size_t rows, int dim, const CpcaOptions& options);

/// sqrt(sum_r ||x_r - x^_r||^2 / sum_r ||x_r||^2): the relative Frobenius error of the model
/// over all rows (0 when every row is 0).
double CpcaRelativeError(const CpcaModel& model, const float* data);

}  // namespace prt
