#include "precompute/reference.h"

#include <atomic>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/rng.h"
#include "geometry/bvh.h"
#include "geometry/ray.h"
#include "precompute/reference_env_sampler.h"

namespace prt {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInvGolden = 0.61803398874989484820;  // 1 / golden ratio

/// Fractional part in [0, 1).
double Frac(double x) { return x - std::floor(x); }

/// A unit vector pair (t, b) completing n to a right-handed frame (Duff et al. 2017).
void Basis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

/// Cosine-weighted direction about n for (u1, u2) (Malley's method).
glm::dvec3 CosineDirection(const glm::dvec3& n, double u1, double u2) {
  glm::dvec3 t, b;
  Basis(n, t, b);
  const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
  return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1.0 - u1)) * n);
}

class Estimator {
 public:
  Estimator(const Mesh& mesh, const Environment& env, const ReferenceOptions& o)
      : mesh_(mesh), o_(o), sampler_(env, o.table_rows, o.table_cols),
        bvh_(o.mode == TransportMode::kUnshadowed ? Bvh() : Bvh::Build(mesh)),
        scale_(o.mode == TransportMode::kUnshadowed ? 0.f : bvh_.SceneScale()) {}

  /// Mean over n lattice points of one vertex, shifted by (s1, s2) and (s3, s4).
  glm::dvec3 Vertex(std::size_t v, int n, Pcg32& rng, std::uint64_t& rays) const {
    const glm::dvec3 p(mesh_.positions[v]), nrm(mesh_.normals[v]);
    const double s1 = rng.NextDouble(), s2 = rng.NextDouble(), s3 = rng.NextDouble(), s4 = rng.NextDouble();
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i) {
      const double u1 = (i + 0.5) / n, u2 = Frac(i * kInvGolden);
      glm::dvec3 value = Direct(p, nrm, Frac(u1 + s1), Frac(u2 + s2), rays);
      if (o_.mode == TransportMode::kInterreflection)
        value += Indirect(p, nrm, Frac(u1 + s3), Frac(u2 + s4), o_.bounces, rng, rays);
      sum += value;
    }
    return glm::dvec3(mesh_.albedo[v]) * (sum / double(n));
  }

 private:
  /// (1/pi) L V max(0, n.w) / p for one environment sample.
  glm::dvec3 Direct(const glm::dvec3& p, const glm::dvec3& n, double u1, double u2, std::uint64_t& rays) const {
    const EnvSample s = sampler_.Sample(u1, u2);
    const double cosine = glm::dot(n, s.dir);
    if (cosine <= 0.0 || !(s.pdf > 0.0)) return glm::dvec3(0.0);
    if (o_.mode != TransportMode::kUnshadowed) {
      Ray ray;
      ray.origin = OffsetRayOrigin(glm::vec3(p), glm::vec3(n), scale_);
      ray.dir = glm::vec3(s.dir);
      ++rays;
      if (bvh_.Occluded(ray)) return glm::dvec3(0.0);
    }
    return s.radiance * (cosine / (kPi * s.pdf));
  }

  /// (1/pi) integral over blocked w of Lo(h) cos dw, estimated by one cosine-weighted path of
  /// up to `depth` bounces.
  glm::dvec3 Indirect(const glm::dvec3& p, const glm::dvec3& n, double u1, double u2, int depth, Pcg32& rng,
                      std::uint64_t& rays) const {
    if (depth <= 0) return glm::dvec3(0.0);
    const glm::dvec3 w = CosineDirection(n, u1, u2);
    Ray ray;
    ray.origin = OffsetRayOrigin(glm::vec3(p), glm::vec3(n), scale_);
    ray.dir = glm::vec3(w);
    ++rays;
    const auto hit = bvh_.Intersect(ray);
    if (!hit) return glm::dvec3(0.0);
    const auto& tri = mesh_.triangles[hit->triangle];
    const glm::vec3& p0 = mesh_.positions[tri[0]];
    glm::vec3 g = glm::cross(mesh_.positions[tri[1]] - p0, mesh_.positions[tri[2]] - p0);
    if (glm::dot(g, mesh_.normals[tri[0]] + mesh_.normals[tri[1]] + mesh_.normals[tri[2]]) < 0.0f) g = -g;
    if (glm::dot(g, ray.dir) >= 0.0f) return glm::dvec3(0.0);  // the unlit back reflects nothing
    const double b[3] = {1.0 - hit->u - hit->v, hit->u, hit->v};
    glm::dvec3 hp(0.0), hn(0.0), albedo(0.0);
    for (int j = 0; j < 3; ++j) {
      hp += b[j] * glm::dvec3(mesh_.positions[tri[j]]);
      hn += b[j] * glm::dvec3(mesh_.normals[tri[j]]);
      albedo += b[j] * glm::dvec3(mesh_.albedo[tri[j]]);
    }
    if (glm::dot(hn, hn) == 0.0) return glm::dvec3(0.0);
    hn = glm::normalize(hn);
    // Lo(h) = albedo(h) * [direct + indirect] at the hit; the cosine weight is 1 (pdf cos/pi).
    glm::dvec3 lo = Direct(hp, hn, rng.NextDouble(), rng.NextDouble(), rays);
    if (depth > 1) lo += Indirect(hp, hn, rng.NextDouble(), rng.NextDouble(), depth - 1, rng, rays);
    return albedo * lo;
  }

  const Mesh& mesh_;
  ReferenceOptions o_;
  EnvSampler sampler_;
  Bvh bvh_;
  float scale_;
};

}  // namespace

Reference ComputeReference(const Mesh& mesh, const Environment& env, const ReferenceOptions& o) {
  if (o.samples < 2) throw Error("--samples: " + std::to_string(o.samples) + " is too few for a reference (expected >= 2)");
  const Estimator estimator(mesh, env, o);
  const std::size_t nv = mesh.vertex_count();
  const int half = o.samples / 2;
  Reference ref;
  ref.radiance.resize(nv);
  ref.error.resize(nv);
  std::vector<std::uint64_t> chunk_rays(ChunkCount(nv, 16), 0);
  Progress progress("reference", nv);
  ParallelFor(nv, 16, [&](std::size_t begin, std::size_t end) {
    std::uint64_t rays = 0;
    for (std::size_t v = begin; v < end; ++v) {
      Pcg32 rng_a(MixSeed(o.seed, 0), v), rng_b(MixSeed(o.seed, 1), v);
      const glm::dvec3 a = estimator.Vertex(v, half, rng_a, rays);
      const glm::dvec3 b = estimator.Vertex(v, half, rng_b, rays);
      ref.radiance[v] = 0.5 * (a + b);
      ref.error[v] = 0.5 * glm::abs(a - b);
    }
    chunk_rays[begin / 16] = rays;
    progress.Advance(end - begin);
  });
  double e2 = 0, r2 = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    e2 += glm::dot(ref.error[v], ref.error[v]);
    r2 += glm::dot(ref.radiance[v], ref.radiance[v]);
  }
  const double denom = nv ? 3.0 * double(nv) : 1.0;
  ref.rms_error = std::sqrt(e2 / denom);
  ref.rms_radiance = std::sqrt(r2 / denom);
  for (std::uint64_t r : chunk_rays) ref.rays += r;
  return ref;
}

}  // namespace prt
