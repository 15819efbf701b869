// Clustered PCA (cpca/cpca.h, cpca/principal.h) on vectors whose answer is known: rows planted
// as exactly mean + rank K per cluster come back to float precision with their clusters; one row
// per cluster, or K = dim, is lossless; more terms never lose; the model does not depend on the
// thread count.
#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <vector>

#include "core/rng.h"
#include "cpca/cpca.h"
#include "cpca/principal.h"
#include "tests/test_support.h"

using namespace prt;

TEST_SUITE_BEGIN("cpca");

namespace {

// Reconstructions that should be exact, up to floats: the rows are floats of size ~3, the model's
// means, directions and weights floats too (up to 16 terms), so a few float roundings relative
// to the rows' norm.
constexpr double kFloatPrecision = 2e-6;

/// Rows of `dim` floats: `clusters` planted clusters, row r in cluster r % clusters (interleaved,
/// so no cluster is a block of rows), each mean_c + sum_k t_rk u_ck with `rank` random directions.
/// `mean_scale` sets how far apart the means lie (0: all the same mean).
struct Planted {
  int dim = 16;
  std::vector<float> rows;
  std::vector<int> truth;
};

Planted Plant(int clusters, int rank, int per_cluster, int dim, double mean_scale, std::uint64_t seed) {
  Pcg32 rng(seed, 7);
  const auto uniform = [&rng] { return 2.0 * rng.NextDouble() - 1.0; };
  std::vector<std::vector<double>> mean(clusters, std::vector<double>(dim)), dir(clusters * rank, std::vector<double>(dim));
  for (auto& m : mean)
    for (double& x : m) x = mean_scale * uniform();
  for (auto& u : dir)
    for (double& x : u) x = uniform();
  Planted p;
  p.dim = dim;
  for (int r = 0; r < clusters * per_cluster; ++r) {
    const int c = r % clusters;
    std::vector<double> x = mean[c];
    for (int k = 0; k < rank; ++k) {
      const double t = uniform();
      for (int d = 0; d < dim; ++d) x[d] += t * dir[c * rank + k][d];
    }
    for (double v : x) p.rows.push_back(float(v));
    p.truth.push_back(c);
  }
  return p;
}

/// True when the model's clusters are the planted ones (up to their numbering).
bool SamePartition(const CpcaModel& m, const std::vector<int>& truth) {
  std::set<std::pair<int, std::uint32_t>> pairs;
  std::set<int> planted;
  std::set<std::uint32_t> found;
  for (std::size_t r = 0; r < truth.size(); ++r) pairs.insert({truth[r], m.cluster[r]}), planted.insert(truth[r]), found.insert(m.cluster[r]);
  return pairs.size() == planted.size() && pairs.size() == found.size();
}

}  // namespace

TEST_CASE("cpca: planted mean + rank-K clusters come back to float precision, clusters recovered") {
  const Planted p = Plant(4, 2, 60, 16, 3.0, 11);
  CpcaOptions o;
  o.clusters = 4;
  o.terms = 2;
  const CpcaModel m = CompressCpca(p.rows.data(), p.truth.size(), p.dim, o);
  CHECK(CpcaRelativeError(m, p.rows.data()) < kFloatPrecision);
  CHECK(SamePartition(m, p.truth));
  // A term fewer cannot hold a rank-2 cluster: the error test is not vacuous.
  o.terms = 1;
  CHECK(CpcaRelativeError(CompressCpca(p.rows.data(), p.truth.size(), p.dim, o), p.rows.data()) > 0.05);
}

TEST_CASE("cpca: clusters told apart by their subspaces, not by their means") {
  // Two lines through the same point: a mean-distance assignment (plain k-means) cannot split
  // them, the reconstruction error does.
  const Planted p = Plant(2, 1, 100, 12, 0.0, 5);
  CpcaOptions o;
  o.clusters = 2;
  o.terms = 1;
  o.iterations = 10;
  const CpcaModel m = CompressCpca(p.rows.data(), p.truth.size(), p.dim, o);
  CHECK(CpcaRelativeError(m, p.rows.data()) < kFloatPrecision);
  CHECK(SamePartition(m, p.truth));
}

TEST_CASE("cpca: one row per cluster, or as many terms as numbers, is lossless") {
  const Planted p = Plant(3, 5, 10, 16, 1.0, 3);
  const std::size_t rows = p.truth.size();
  CpcaOptions o;
  o.clusters = int(rows);
  o.terms = 0;
  CHECK(CpcaRelativeError(CompressCpca(p.rows.data(), rows, p.dim, o), p.rows.data()) == 0.0);
  o.clusters = 2;
  o.terms = 16;
  CHECK(CpcaRelativeError(CompressCpca(p.rows.data(), rows, p.dim, o), p.rows.data()) < kFloatPrecision);
  // More clusters than rows: as many as rows, still lossless.
  o.clusters = int(rows) + 5;
  o.terms = 1;
  const CpcaModel many = CompressCpca(p.rows.data(), rows, p.dim, o);
  CHECK(many.clusters == int(rows));
  CHECK(CpcaRelativeError(many, p.rows.data()) < kFloatPrecision);
}

TEST_CASE("cpca: no cluster ends empty, with repeated rows, clusters near the row count, any iteration count") {
  // Repeated rows make k-means++ draw the same seed twice and tie rows between equal means
  // (a tie goes to the lower index), so clusters start empty; each must end with a row.
  struct Case {
    int rows, distinct, clusters, terms, iterations;
  };
  for (const Case c : {Case{40, 3, 10, 1, 4}, Case{30, 1, 5, 0, 4}, Case{30, 1, 5, 2, 0}, Case{12, 12, 11, 2, 1},
                       Case{12, 4, 12, 0, 0}, Case{64, 8, 32, 3, 2}}) {
    CAPTURE(c.rows);
    CAPTURE(c.distinct);
    CAPTURE(c.clusters);
    CAPTURE(c.terms);
    CAPTURE(c.iterations);
    const Planted p = Plant(c.distinct, 2, 1, 6, 1.0, 11);
    std::vector<float> rows;
    for (int r = 0; r < c.rows; ++r)  // row r repeats distinct row r % distinct
      rows.insert(rows.end(), p.rows.begin() + (r % c.distinct) * 6, p.rows.begin() + (r % c.distinct + 1) * 6);
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      CAPTURE(seed);
      CpcaOptions o;
      o.clusters = c.clusters, o.terms = c.terms, o.iterations = c.iterations, o.seed = seed;
      const CpcaModel m = CompressCpca(rows.data(), std::size_t(c.rows), 6, o);
      REQUIRE(m.clusters == c.clusters);
      std::vector<int> members(std::size_t(m.clusters), 0);
      for (std::uint32_t k : m.cluster) {
        REQUIRE(k < std::uint32_t(m.clusters));
        ++members[k];
      }
      for (int k = 0; k < m.clusters; ++k) CHECK_MESSAGE(members[std::size_t(k)] > 0, "cluster " << k << " is empty");
      // And no worse than one cluster of all the rows would be (a mean of nothing is 0, far off).
      CpcaOptions one = o;
      one.clusters = 1;
      CHECK(CpcaRelativeError(m, rows.data()) <=
            CpcaRelativeError(CompressCpca(rows.data(), std::size_t(c.rows), 6, one), rows.data()) + kFloatPrecision);
    }
  }
}

TEST_CASE("cpca: a cluster left empty never takes the only row of another") {
  // Rows B, C (one each) first, then eight of A: every row is reconstructed exactly (terms 0, each
  // cluster one value), so the rows' errors tie and the empty cluster's new row is found by row
  // order; B and C come first, but each is its cluster's only row and must stay where it is.
  const std::vector<float> a = {1, 0, 0}, b = {0, 1, 0}, c = {0, 0, 1};
  std::vector<float> rows;
  for (const auto* v : {&b, &c}) rows.insert(rows.end(), v->begin(), v->end());
  for (int i = 0; i < 8; ++i) rows.insert(rows.end(), a.begin(), a.end());
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    CAPTURE(seed);
    CpcaOptions o;
    o.clusters = 4, o.terms = 0, o.iterations = 1, o.seed = seed;
    const CpcaModel m = CompressCpca(rows.data(), 10, 3, o);
    std::vector<int> members(std::size_t(m.clusters), 0);
    for (std::uint32_t k : m.cluster) ++members[k];
    for (int k = 0; k < m.clusters; ++k) CHECK_MESSAGE(members[std::size_t(k)] > 0, "cluster " << k << " is empty");
    CHECK(CpcaRelativeError(m, rows.data()) == 0.0);  // B and C keep clusters of their own
  }
}

TEST_CASE("cpca: the error never grows with more terms, and the weights project on the stored mean") {
  // One cluster is PCA: rows with a decaying spectrum (direction k scaled by 0.6^k), so each term
  // added removes a known share. Tolerance for "not larger": float rounding of the errors.
  constexpr double kRounding = 1e-6;
  const Planted p = Plant(1, 8, 300, 16, 1.0, 9);
  std::vector<float> rows = p.rows;
  for (std::size_t r = 0; r < p.truth.size(); ++r)
    for (int d = 0; d < 16; ++d) rows[r * 16 + d] *= float(std::pow(0.6, d % 8));
  CpcaOptions o;
  o.clusters = 1;
  double last = 2.0;
  for (int k = 0; k <= 8; ++k) {
    o.terms = k;
    const CpcaModel m = CompressCpca(rows.data(), p.truth.size(), 16, o);
    const double e = CpcaRelativeError(m, rows.data());
    CHECK(e <= last + kRounding);
    last = e;
    // The weights are the projections of x - mean (mean stored in the model): the residual is
    // orthogonal to every direction.
    std::vector<float> y(16);
    for (std::size_t r = 0; r < 5; ++r) {
      m.Reconstruct(r, y.data());
      for (int t = 0; t < k; ++t) {
        double dot = 0.0;
        for (int d = 0; d < 16; ++d) dot += (rows[r * 16 + d] - y[d]) * m.principal[t * 16 + d];
        CHECK(std::abs(dot) < 1e-5);
      }
    }
  }
}

TEST_CASE("cpca: principal helpers: Jacobi eigenpairs and Gram-Schmidt with a dependent row") {
  // Tolerance: double rounding of a 3 x 3 Jacobi diagonalisation.
  constexpr double kTol = 1e-12;
  std::vector<double> a = {2, 1, 0, 1, 2, 0, 0, 0, 5}, values, vectors;
  SymmetricEigen(3, a, values, vectors);
  CHECK(values[0] == doctest::Approx(5).epsilon(kTol));
  CHECK(values[1] == doctest::Approx(3).epsilon(kTol));
  CHECK(values[2] == doctest::Approx(1).epsilon(kTol));
  CHECK(std::abs(std::abs(vectors[2]) - 1.0) < kTol);  // the first eigenvector is the z axis
  // Row 1 is twice row 0: replaced by a unit axis orthogonal to row 0.
  std::vector<double> rows = {1, 1, 0, 2, 2, 0, 0, 1, 1};
  OrthonormalizeRows(3, 3, rows.data());
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double dot = 0.0;
      for (int d = 0; d < 3; ++d) dot += rows[i * 3 + d] * rows[j * 3 + d];
      CHECK(std::abs(dot - (i == j ? 1.0 : 0.0)) < kTol);
    }
}
