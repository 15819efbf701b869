#include "precompute/transfer_matrix.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/frame.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "material/lobe_transfer.h"
#include "precompute/hit_light.h"
#include "precompute/transport_direct.h"
#include "sh/basis.h"
#include "sh/quadrature.h"

namespace prt {
namespace {


/// out += f * a b^T (n x n).
void AddOuter(double f, const double* a, const double* b, int n, double* out) {
  for (int i = 0; i < n; ++i) {
    const double fa = f * a[i];
    double* row = out + std::size_t(i) * n;
    for (int j = 0; j < n; ++j) row[j] += fa * b[j];
  }
}

}  // namespace

std::uint64_t TransferMatrixBytes(std::size_t vertices, int lmax, int channels) {
  const std::uint64_t n = std::uint64_t(CoeffCount(lmax));
  return std::uint64_t(vertices) * std::uint64_t(channels) * n * n * sizeof(float);
}

void UnshadowedTransferMatrix(const glm::dvec3& normal, int lmax, double* out) {
  const int n = CoeffCount(lmax);
  std::fill(out, out + std::size_t(n) * n, 0.0);
  std::vector<double> z, wz, y(n);
  GaussLegendre(lmax + 1, z, wz);  // on [-1, 1]; mapped to z in [0, 1]
  const int azimuths = 2 * lmax + 2;
  glm::dvec3 e1, e2;
  TangentFrame(normal, e1, e2);
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double c = 0.5 * (z[i] + 1.0), rho = std::sqrt(std::max(0.0, 1.0 - c * c));
    for (int j = 0; j < azimuths; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / azimuths;
      const glm::dvec3 s = c * normal + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
      EvalBasis(lmax, s, y.data());
      AddOuter(0.5 * wz[i] * (2.0 * kPi / azimuths) * c, y.data(), y.data(), n, out);
    }
  }
}

void ComputeTransferMatrices(const Mesh& mesh, const DirectionPlan* plan, const DirectResult* direct, int lmax,
                             const std::vector<double>* hit_transfer, Transport& transport, const VertexBlock& block) {
  const int n = CoeffCount(lmax);
  const std::size_t nn = std::size_t(n) * n, nv = mesh.vertex_count();
  const int channels = transport.channels;
  transport.matrices.assign(nv * channels * nn, 0.0f);
  const std::size_t first = std::min(block.begin, nv), last = std::min(block.end, nv);
  Progress progress("transfer matrices", last - first);
  ParallelFor(last - first, 32, [&](std::size_t begin, std::size_t end) {
    std::vector<double> m(channels * nn), y(n), lit(n);
    for (std::size_t v = first + begin; v < first + end; ++v) {
      const glm::dvec3 normal(mesh.normals[v]);
      // As the direct transfer: a vertex none of whose directions is open gets exactly 0, not
      // the closed form minus its noisy estimate.
      const bool open = !direct || direct->sees_sky[v];
      if (open) UnshadowedTransferMatrix(normal, lmax, m.data());
      else std::fill(m.begin(), m.begin() + nn, 0.0);
      for (int c = 1; c < channels; ++c) std::copy(m.begin(), m.begin() + nn, m.begin() + c * nn);
      if (direct) {
        // The blocked directions the direct pass found, with what they hit (transport_direct.h).
        const std::size_t directions = plan->PoolOf(v).size();  // the camera's vertices take more
        const double vertex_weight = 4.0 * kPi / double(directions);
        for (const VertexHit& h : direct->hits[v]) {
          const glm::dvec3& dir = plan->Direction(v, h.dir);
          const double cosine = glm::dot(normal, dir);
          EvalBasis(lmax, dir, y.data());
          if (open)
            for (int c = 0; c < channels; ++c) AddOuter(-vertex_weight * cosine, y.data(), y.data(), n, m.data() + c * nn);
          if (!hit_transfer || !h.front) continue;
          // The hit point's diffuse light: albedo(h) T(h), barycentric (or the texture).
          const glm::vec3 albedo =
              mesh.textured() ? HitAlbedo(mesh, v, h.triangle, h.u, h.v, directions) : glm::vec3(0.f);
          for (int c = 0; c < channels; ++c) {
            std::fill(lit.begin(), lit.end(), 0.0);
            AddHitLight(mesh, h.triangle, h.u, h.v, *hit_transfer, channels, n, c, 1.0, lit.data(),
                        mesh.textured() ? &albedo : nullptr);
            AddOuter(vertex_weight * cosine, y.data(), lit.data(), n, m.data() + c * nn);
          }
        }
      }
      std::copy(m.begin(), m.end(), transport.matrices.begin() + v * channels * nn);
    }
    progress.Advance(end - begin);
  });
}

void LobeRow(const glm::dvec3& normal, const glm::dvec3& position, const glm::dvec3& eye, int lmax,
             const std::vector<double>& h, double* hy) {
  EvalBasis(lmax, LobeAxis(normal, position, eye), hy);
  for (int l = 0, k = 0; l <= lmax; ++l)
    for (int m = -l; m <= l; ++m, ++k) hy[k] *= h[l];
}

void LobeRows(const Mesh& mesh, std::size_t begin, std::size_t end, const glm::dvec3& eye, int lmax,
              const std::vector<double>& h, std::vector<double>& rows) {
  const std::size_t count = end - begin, n = CoeffCount(lmax);
  std::vector<double> axes(3 * count);  // x, then y, then z of every vertex's lobe axis
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec3 r = LobeAxis(glm::dvec3(mesh.normals[begin + i]), glm::dvec3(mesh.positions[begin + i]), eye);
    axes[i] = r.x, axes[count + i] = r.y, axes[2 * count + i] = r.z;
  }
  rows.resize(count * n);
  EvalBasisBatch(lmax, count, axes.data(), axes.data() + count, axes.data() + 2 * count, rows.data());
  for (std::size_t i = 0; i < count; ++i)
    for (int l = 0, k = 0; l <= lmax; ++l)
      for (int m = -l; m <= l; ++m, ++k) rows[i * n + std::size_t(k)] *= h[std::size_t(l)];
}

std::vector<glm::vec3> GlossyFromMatrices(const Mesh& mesh, const Transport& transport, const Material& material,
                                          const ShRgb& light, const glm::dvec3& eye) {
  const int lmax = transport.lmax, n = CoeffCount(lmax);
  const std::size_t nn = std::size_t(n) * n;
  const int used = std::min<int>(n, int(light.size()));
  const std::vector<double> h = material.lobe.ZonalCoefficients(lmax);
  std::vector<glm::vec3> out(mesh.vertex_count(), glm::vec3(0.0f));
  if (!material.glossy) return out;
  ParallelFor(out.size(), 256, [&](std::size_t begin, std::size_t end) {
    std::vector<double> hy(n), w(n);
    for (std::size_t v = begin; v < end; ++v) {
      LobeRow(glm::dvec3(mesh.normals[v]), glm::dvec3(mesh.positions[v]), eye, lmax, h, hy.data());
      // KS (hy^T M) L: the lobe row times the matrix, then the light. The row product is the
      // n^2 part of the cost: one for all three colours when they share a matrix.
      for (int c = 0; c < transport.channels; ++c) {
        const float* m = transport.matrices.data() + (v * transport.channels + c) * nn;
        std::fill(w.begin(), w.begin() + used, 0.0);
        for (int i = 0; i < n; ++i) {
          if (hy[i] == 0.0) continue;
          const float* row = m + std::size_t(i) * n;
          for (int j = 0; j < used; ++j) w[j] += hy[i] * double(row[j]);
        }
        for (int cc = 0; cc < 3; ++cc) {
          if (transport.channels != 1 && cc != c) continue;
          double sum = 0.0;
          for (int j = 0; j < used; ++j) sum += w[j] * light[j][cc];
          out[v][cc] = static_cast<float>(material.ks * sum);
        }
      }
    }
  });
  return out;
}

}  // namespace prt
