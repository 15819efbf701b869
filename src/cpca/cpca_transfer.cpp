#include "cpca/cpca_transfer.h"

#include <algorithm>

#include "core/error.h"
#include "core/parallel.h"
#include "core/simd.h"
#include "precompute/shade.h"
#include "precompute/transfer_matrix.h"

namespace prt {
namespace {

/// Partial sums per lane: fixed-length inner loops the compiler keeps in vector registers (the
/// order of the sums is fixed, so every thread rounds alike).
constexpr int kLanes = 4;

/// sum_i a[i] b[i] over `n` floats, in kLanes partial sums.
PRT_SIMD_INLINE float DotLanes(const float* __restrict a, const float* __restrict b, int n) {
  float lane[kLanes] = {};
  int i = 0;
  for (; i + kLanes <= n; i += kLanes)
    for (int l = 0; l < kLanes; ++l) lane[l] += a[i + l] * b[i + l];
  float s = (lane[0] + lane[1]) + (lane[2] + lane[3]);
  for (; i < n; ++i) s += a[i] * b[i];
  return s;
}

/// One frame's products: [((c * (K + 1) + t) * 3 + colour) * n + i], t = 0 the mean, t = k + 1
/// the k-th principal matrix, each times the light's colour (its first `used` coefficients).
std::vector<float> ClusterLightProducts(const CpcaTransfer& cpca, const ShRgb& light) {
  const CpcaModel& m = cpca.model;
  const int n = CoeffCount(cpca.lmax), used = std::min<int>(n, int(light.size())), terms = m.terms;
  std::vector<float> colour_light(3 * std::size_t(n), 0.0f);  // [colour][j], 0 beyond `used`
  for (int colour = 0; colour < 3; ++colour)
    for (int j = 0; j < used; ++j) colour_light[colour * n + j] = float(light[j][colour]);
  std::vector<float> out(std::size_t(m.clusters) * (terms + 1) * 3 * n);
  ParallelFor(std::size_t(m.clusters), 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
      for (int t = 0; t <= terms; ++t) {
        const float* a = t == 0 ? m.means.data() + c * m.dim : m.principal.data() + (c * terms + (t - 1)) * m.dim;
        float* o = out.data() + (c * (terms + 1) + t) * 3 * n;
        for (int colour = 0; colour < 3; ++colour)
          for (int i = 0; i < n; ++i) o[colour * n + i] = DotLanes(a + std::size_t(i) * n, colour_light.data() + colour * n, n);
      }
  });
  return out;
}

/// What every vertex of one frame reads.
struct VertexJob {
  const Mesh& mesh;
  const CpcaTransfer& cpca;
  const float* products;          ///< ClusterLightProducts
  std::vector<double> h;          ///< the lobe's zonal coefficients
  double ks;
  glm::dvec3 eye;
  glm::vec3* out;
};

/// The glossy radiance of vertices [begin, end): their lobe rows toward the eye (`rows`, from
/// LobeRows), y = (M_c L) + sum_k w_k (P_ck L) from the cluster's products, then KS hy . y.
/// Inlined into one function per instruction set (the same operations in the same order: the
/// same bits from each).
PRT_SIMD_INLINE void ShadeVertexRange(const VertexJob& j, std::size_t begin, std::size_t end, const double* rows) {
  const CpcaModel& m = j.cpca.model;
  const int lmax = j.cpca.lmax, n = CoeffCount(lmax), channels = j.cpca.channels, terms = m.terms;
  std::vector<float> y(3 * std::size_t(n)), lobe(n);
  for (std::size_t v = begin; v < end; ++v) {
    const double* hy = rows + (v - begin) * std::size_t(n);
    for (int i = 0; i < n; ++i) lobe[i] = float(hy[i]);
    for (int c = 0; c < channels; ++c) {
      // All three colours with one matrix, else this channel's.
      const std::size_t row = v * channels + c;
      const int first = channels == 1 ? 0 : c, width = (channels == 1 ? 3 : 1) * n;
      const float* __restrict p = j.products + (std::size_t(m.cluster[row]) * (terms + 1) * 3 + first) * n;
      const float* w = m.weights.data() + row * terms;
      float* __restrict yv = y.data();
      for (int i = 0; i < width; ++i) yv[i] = p[i];
      for (int k = 0; k < terms; ++k) {
        const float wk = w[k];
        const float* __restrict pk = p + std::size_t(k + 1) * 3 * n;
        for (int i = 0; i < width; ++i) yv[i] += wk * pk[i];
      }
      for (int colour = first; colour < first + width / n; ++colour)
        j.out[v][colour] = static_cast<float>(j.ks * DotLanes(lobe.data(), yv + (colour - first) * n, n));
    }
  }
}

void ShadeVerticesBase(const VertexJob& j, std::size_t begin, std::size_t end, const double* rows) {
  ShadeVertexRange(j, begin, end, rows);
}
PRT_TARGET_AVX2 void ShadeVerticesAvx2(const VertexJob& j, std::size_t begin, std::size_t end, const double* rows) {
  ShadeVertexRange(j, begin, end, rows);
}

}  // namespace

CpcaTransfer CompressTransferMatrices(const Transport& t, const CpcaOptions& options) {
  if (t.matrices.empty()) throw Error("CPCA needs transfer matrices to compress (internal)");
  CpcaTransfer c;
  c.lmax = t.lmax;
  c.channels = t.channels;
  c.vertices = t.vertices;
  const int n = CoeffCount(t.lmax);
  c.model = CompressCpca(t.matrices.data(), t.matrices.size() / (std::size_t(n) * n), n * n, options);
  return c;
}

std::vector<float> ReconstructMatrices(const CpcaTransfer& cpca) {
  const CpcaModel& m = cpca.model;
  std::vector<float> out(m.rows * m.dim);
  for (std::size_t r = 0; r < m.rows; ++r) m.Reconstruct(r, out.data() + r * m.dim);
  return out;
}

std::vector<glm::vec3> GlossyFromCpca(const Mesh& mesh, const CpcaTransfer& cpca, const Material& material,
                                      const ShRgb& light, const glm::dvec3& eye) {
  std::vector<glm::vec3> out(mesh.vertex_count(), glm::vec3(0.0f));
  if (!material.glossy) return out;
  const std::vector<float> products = ClusterLightProducts(cpca, light);
  const VertexJob job{mesh, cpca, products.data(), material.lobe.ZonalCoefficients(cpca.lmax), material.ks, eye, out.data()};
  const bool avx2 = CpuVectorLevel() >= VectorLevel::kAvx2;
  ParallelFor(out.size(), 256, [&](std::size_t begin, std::size_t end) {
    // The lobe rows of the whole range first, the basis several vertices at a time (LobeRows).
    std::vector<double> rows;
    LobeRows(mesh, begin, end, job.eye, cpca.lmax, job.h, rows);
    if (avx2) ShadeVerticesAvx2(job, begin, end, rows.data());
    else ShadeVerticesBase(job, begin, end, rows.data());
  });
  return out;
}

std::vector<glm::vec3> ShadeVerticesCpca(const Mesh& mesh, const Transport& transport, const CpcaTransfer& cpca,
                                         const ShRgb& light, bool albedo, const glm::dvec3& eye) {
  std::vector<glm::vec3> colors = ShadeDiffuse(mesh, transport, light, albedo);
  if (albedo && transport.material.glossy) {
    const std::vector<glm::vec3> glossy = GlossyFromCpca(mesh, cpca, transport.material, light, eye);
    for (std::size_t v = 0; v < colors.size(); ++v) colors[v] += glossy[v];
  }
  return colors;
}

}  // namespace prt
