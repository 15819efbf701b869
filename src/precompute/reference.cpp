#include "precompute/reference.h"

#include <atomic>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/error.h"
#include "core/frame.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/rng.h"
#include "geometry/bvh.h"
#include "geometry/mesh_texture.h"
#include "geometry/ray.h"
#include "material/lobe_transfer.h"
#include "precompute/hit_light.h"  // FrontSide
#include "precompute/lobe_rays.h"  // kLobeStream: a half's lobe samples, apart from its other streams
#include "precompute/reference_env_sampler.h"

namespace prt {
namespace {

constexpr double kInvGolden = 0.61803398874989484820;  // 1 / golden ratio

/// Fractional part in [0, 1).
double Frac(double x) { return x - std::floor(x); }

/// Cosine-weighted direction about n for (u1, u2) (Malley's method).
glm::dvec3 CosineDirection(const glm::dvec3& n, double u1, double u2) {
  glm::dvec3 t, b;
  TangentFrame(n, t, b);
  const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
  return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1.0 - u1)) * n);
}

class Estimator {
 public:
  Estimator(const Mesh& mesh, const Environment& env, const ReferenceOptions& o)
      : mesh_(mesh), env_(env), o_(o), sampler_(env, o.table_rows, o.table_cols),
        bvh_(o.mode == TransportMode::kUnshadowed ? Bvh() : Bvh::Build(mesh)),
        scale_(o.mode == TransportMode::kUnshadowed ? 0.f : bvh_.SceneScale()) {
    o.material.lobe.SampleMu(0.5, lobe_weight_);  // h / density, the same for every mu
  }

  /// Mean over n lattice points of one vertex, shifted by (s1, s2) and (s3, s4); a glossy
  /// material adds its lobe term, its lobe samples shifted by (s5, s6) from `lobe_rng`.
  glm::dvec3 Vertex(std::size_t v, int n, Pcg32& rng, Pcg32& lobe_rng, std::uint64_t& rays) const {
    const glm::dvec3 p(mesh_.positions[v]), nrm(mesh_.normals[v]);
    const double s1 = rng.NextDouble(), s2 = rng.NextDouble(), s3 = rng.NextDouble(), s4 = rng.NextDouble();
    LobeTerm lobe;
    LobeTerm* glossy = o_.material.glossy ? &lobe : nullptr;
    double s5 = 0, s6 = 0;
    if (glossy) {
      // The lobe's axis: the mirror of the direction to the eye (as transport_glossy.cpp).
      lobe.axis = LobeAxis(nrm, p, *o_.eye);
      TangentFrame(lobe.axis, lobe.t, lobe.b);
      s5 = lobe_rng.NextDouble(), s6 = lobe_rng.NextDouble();
    }
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i) {
      const double u1 = (i + 0.5) / n, u2 = Frac(i * kInvGolden);
      glm::dvec3 value = Direct(p, nrm, Frac(u1 + s1), Frac(u2 + s2), rays, glossy);
      if (o_.mode == TransportMode::kInterreflection)
        value += Indirect(p, nrm, Frac(u1 + s3), Frac(u2 + s4), o_.bounces, rng, rays);
      sum += value;
      if (glossy) lobe.sum += LobeSample(p, nrm, lobe, Frac(u1 + s5), Frac(u2 + s6), lobe_rng, rays);
    }
    const glm::dvec3 diffuse = glm::dvec3(mesh_.albedo[v]) * (sum / double(n));
    return glossy ? diffuse + lobe.sum / double(n) : diffuse;
  }

 private:
  /// A glossy receiver's lobe axis r with a frame (t, b) across it, and its running sum.
  struct LobeTerm {
    glm::dvec3 axis, t, b;
    glm::dvec3 sum{0.0};
  };

  /// The environment technique's MIS weight w_env for a direction both techniques can draw
  /// (densities p_env, p_lobe); the lobe technique's is 1 - w_env.
  double EnvShare(double p_env, double p_lobe) const {
    switch (o_.glossy_sampling) {
      case GlossySampling::kEnvironment: return 1.0;
      case GlossySampling::kLobe: return 0.0;
      default: return p_env / (p_env + p_lobe);  // balance heuristic
    }
  }

  /// (1/pi) L V max(0, n.w) / p for one environment sample. For a glossy receiver it also adds
  /// to glossy->sum the sample's MIS share of the lobe term, KS h(r.w) L V max(0, n.w) w_env / p.
  glm::dvec3 Direct(const glm::dvec3& p, const glm::dvec3& n, double u1, double u2, std::uint64_t& rays,
                    LobeTerm* glossy = nullptr) const {
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
    if (glossy) {
      const double h = o_.material.lobe.Value(glm::dot(glossy->axis, s.dir));
      const double share = h > 0.0 ? EnvShare(s.pdf, h / lobe_weight_) : 0.0;
      if (share > 0.0) glossy->sum += s.radiance * (o_.material.ks * h * cosine * share / s.pdf);
    }
    return s.radiance * (cosine / (kPi * s.pdf));
  }

  /// One lobe-drawn direction s's estimate of KS integral h(r.s) max(0, n.s) X(s) ds, where X is
  /// L(s) where s sees the environment (weighted by the lobe technique's MIS share) and, with
  /// interreflection, the radiance the hit point sends back as a diffuse surface where s is
  /// blocked (the lobe alone samples that part: share 1). h / p_lobe is the lobe's weight.
  glm::dvec3 LobeSample(const glm::dvec3& p, const glm::dvec3& n, const LobeTerm& lobe, double u1, double u2,
                        Pcg32& rng, std::uint64_t& rays) const {
    double weight = 0.0;
    const double mu = o_.material.lobe.SampleMu(u1, weight), phi = 2.0 * kPi * u2;
    const double sine = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    const glm::dvec3 s = mu * lobe.axis + sine * (std::cos(phi) * lobe.t + std::sin(phi) * lobe.b);
    const double cosine = glm::dot(n, s);
    if (cosine <= 0.0) return glm::dvec3(0.0);
    const double f = o_.material.ks * weight * cosine;  // KS h cos / p_lobe
    if (o_.mode != TransportMode::kUnshadowed) {
      Ray ray;
      ray.origin = OffsetRayOrigin(glm::vec3(p), glm::vec3(n), scale_);
      ray.dir = glm::vec3(s);
      ++rays;
      if (o_.mode == TransportMode::kInterreflection) {
        if (const auto hit = bvh_.Intersect(ray)) return f * HitRadiance(ray, *hit, o_.bounces, rng, rays);
      } else if (bvh_.Occluded(ray)) {
        return glm::dvec3(0.0);
      }
    }
    const double lobe_share = 1.0 - EnvShare(sampler_.Pdf(s), o_.material.lobe.Value(mu) / lobe_weight_);
    return lobe_share > 0.0 ? env_.Radiance(s) * (f * lobe_share) : glm::dvec3(0.0);
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
    // The cosine weight is 1 (pdf cos/pi).
    return HitRadiance(ray, *hit, depth, rng, rays);
  }

  /// Lo(h) = albedo(h) * [direct + indirect through depth - 1] that the hit of `ray` sends
  /// back as a diffuse surface (barycentric normal and albedo, or the texture's); 0 from the
  /// unlit back.
  glm::dvec3 HitRadiance(const Ray& ray, const Hit& hit, int depth, Pcg32& rng, std::uint64_t& rays) const {
    const auto& tri = mesh_.triangles[hit.triangle];
    if (!FrontSide(mesh_, hit, ray.dir)) return glm::dvec3(0.0);  // the unlit back reflects nothing
    const double b[3] = {1.0 - hit.u - hit.v, hit.u, hit.v};
    glm::dvec3 hp(0.0), hn(0.0), albedo(0.0);
    for (int j = 0; j < 3; ++j) {
      hp += b[j] * glm::dvec3(mesh_.positions[tri[j]]);
      hn += b[j] * glm::dvec3(mesh_.normals[tri[j]]);
      albedo += b[j] * glm::dvec3(mesh_.albedo[tri[j]]);
    }
    if (glm::dot(hn, hn) == 0.0) return glm::dvec3(0.0);
    hn = glm::normalize(hn);
    // A textured surface's albedo at the hit itself (unfiltered: each path samples one point).
    if (mesh_.textured()) albedo = glm::dvec3(SurfaceAlbedo(mesh_, hit.triangle, hit.u, hit.v, 0.f));
    glm::dvec3 lo = Direct(hp, hn, rng.NextDouble(), rng.NextDouble(), rays);
    if (depth > 1) lo += Indirect(hp, hn, rng.NextDouble(), rng.NextDouble(), depth - 1, rng, rays);
    return albedo * lo;
  }

  const Mesh& mesh_;
  const Environment& env_;
  ReferenceOptions o_;
  EnvSampler sampler_;
  Bvh bvh_;
  float scale_;
  double lobe_weight_ = 1.0;
};

}  // namespace

Reference ComputeReference(const Mesh& mesh, const Environment& env, const ReferenceOptions& o) {
  if (o.samples < 2) throw Error("--samples: " + std::to_string(o.samples) + " is too few for a reference (expected >= 2)");
  if (o.material.glossy && !o.eye)
    throw Error("a glossy reference needs the camera's eye (internal: ReferenceOptions::eye unset)");
  const Estimator estimator(mesh, env, o);
  const std::size_t nv = mesh.vertex_count();
  const int half = o.samples / 2;
  Reference ref;
  ref.radiance.resize(nv);
  ref.error.resize(nv);
  // The block's vertices (all by default); vertex v's streams depend on v alone.
  const std::size_t first = std::min(o.block.begin, nv), last = std::min(o.block.end, nv);
  std::vector<std::uint64_t> chunk_rays(ChunkCount(last - first, 16), 0);
  Progress progress("reference", last - first);
  ParallelFor(last - first, 16, [&](std::size_t begin, std::size_t end) {
    std::uint64_t rays = 0;
    for (std::size_t v = first + begin; v < first + end; ++v) {
      Pcg32 rng_a(MixSeed(o.seed, 0), v), rng_b(MixSeed(o.seed, 1), v);
      Pcg32 lobe_a(MixSeed(MixSeed(o.seed, 0), kLobeStream), v);
      Pcg32 lobe_b(MixSeed(MixSeed(o.seed, 1), kLobeStream), v);
      const glm::dvec3 a = estimator.Vertex(v, half, rng_a, lobe_a, rays);
      const glm::dvec3 b = estimator.Vertex(v, half, rng_b, lobe_b, rays);
      ref.radiance[v] = 0.5 * (a + b);
      ref.error[v] = 0.5 * glm::abs(a - b);
    }
    chunk_rays[begin / 16] = rays;
    progress.Advance(end - begin);
  });
  SummarizeReference(ref);
  for (std::uint64_t r : chunk_rays) ref.rays += r;
  return ref;
}

void SummarizeReference(Reference& ref) {
  const std::size_t nv = ref.radiance.size();
  double e2 = 0, r2 = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    e2 += glm::dot(ref.error[v], ref.error[v]);
    r2 += glm::dot(ref.radiance[v], ref.radiance[v]);
  }
  const double denom = nv ? 3.0 * double(nv) : 1.0;
  ref.rms_error = std::sqrt(e2 / denom);
  ref.rms_radiance = std::sqrt(r2 / denom);
}

}  // namespace prt
