#include "report/report_glossy.h"

#include <algorithm>
#include <chrono>

#include <glm/common.hpp>
#include <cmath>
#include <limits>
#include <map>

#include "core/log.h"
#include "core/text.h"
#include "material/lobe.h"
#include "precompute/light.h"
#include "precompute/reference.h"
#include "precompute/shade.h"
#include "precompute/transfer_matrix.h"
#include "basis/timed_transport.h"

namespace prt {
namespace {

using Clock = std::chrono::steady_clock;

/// The radiance of one (N, lmax) of the vector path, kept for the matrix path's comparison.
struct VectorShading {
  std::vector<glm::vec3> total, lobe;
};

/// The reference's radiance and its lobe part (glossy minus diffuse reference).
struct References {
  std::vector<glm::dvec3> total, lobe;
};

}  // namespace

GlossyConfig MakeGlossyConfig(bool quick, int user_exponent, double ks, std::uint64_t seed) {
  GlossyConfig c;
  c.ks = ks;
  c.seed = seed;
  c.cpca_exponent = user_exponent;
  if (std::find(c.exponents.begin(), c.exponents.end(), user_exponent) == c.exponents.end()) {
    c.exponents.push_back(user_exponent);
    std::sort(c.exponents.begin(), c.exponents.end());
  }
  if (quick) {
    c.vector_lmax = {1, 2, 3, 4, 6, 8};
    c.matrix_lmax = {1, 2, 3, 4};
    c.samples = 512;
    c.lobe_samples = 256;
    c.reference_samples = 2048;
  }
  return c;
}

GlossyStudy RunGlossyStudy(const Mesh& mesh, const Environment& env, const glm::dvec3& eye, const GlossyConfig& c) {
  GlossyStudy study;
  study.ks = c.ks;
  study.eye = eye;
  study.samples = c.samples;
  study.lobe_samples = c.lobe_samples;
  study.reference_samples = c.reference_samples;
  // Every lmax of the matrix sweep needs the vector path's row beside it.
  std::vector<int> vector_lmax = c.vector_lmax;
  vector_lmax.insert(vector_lmax.end(), c.matrix_lmax.begin(), c.matrix_lmax.end());
  std::sort(vector_lmax.begin(), vector_lmax.end());
  vector_lmax.erase(std::unique(vector_lmax.begin(), vector_lmax.end()), vector_lmax.end());
  const ShRgb light = ProjectLight(env, vector_lmax.back());
  for (int n : c.exponents) {
    GlossyExponent e;
    e.exponent = n;
    const Lobe lobe{LobeKind::kPhong, n};
    e.share_lmax = LmaxForShare(lobe, kLobeShareWarning, kMaxLmax);
    if (LobeBandShare(lobe, e.share_lmax) < kLobeShareWarning) e.share_lmax = -1;  // not within kMaxLmax
    study.exponents.push_back(e);
  }

  std::map<std::pair<int, int>, VectorShading> kept;  // shadowed (N, lmax) of the matrix sweep
  std::map<int, References> shadowed_references;      // by N
  for (TransportMode mode : {TransportMode::kUnshadowed, TransportMode::kShadowed}) {
    // The diffuse reference: the glossy ones minus it leave the lobe's part alone.
    ReferenceOptions ro;
    ro.mode = mode;
    ro.samples = c.reference_samples;
    ro.seed = c.seed + 1000;
    ro.eye = eye;
    const Reference diffuse = ComputeReference(mesh, env, ro);

    TransportOptions to;
    to.mode = mode;
    to.sampler = Sampler::kFibonacci;
    to.samples = c.samples;
    to.lobe_samples = c.lobe_samples;
    to.seed = c.seed;
    to.eye = eye;
    for (GlossyExponent& e : study.exponents) {
      const int n = e.exponent;
      GlossyNeed& need = mode == TransportMode::kShadowed ? e.shadowed : e.unshadowed;
      ro.material = GlossyMaterial(Lobe{LobeKind::kPhong, n}, c.ks);
      const auto t0 = Clock::now();
      const Reference glossy = ComputeReference(mesh, env, ro);
      need.reference_seconds = SecondsSince(t0);
      need.reference_rms_error = glossy.rms_radiance > 0 ? glossy.rms_error / glossy.rms_radiance : 0.0;
      References ref{glossy.radiance, std::vector<glm::dvec3>(glossy.radiance.size())};
      double lobe2 = 0.0;
      for (std::size_t v = 0; v < ref.lobe.size(); ++v) {
        ref.lobe[v] = glossy.radiance[v] - diffuse.radiance[v];
        lobe2 += glm::dot(ref.lobe[v], ref.lobe[v]);
      }
      const double count = 3.0 * double(std::max<std::size_t>(1, ref.lobe.size()));
      need.lobe_share = glossy.rms_radiance > 0 ? std::sqrt(lobe2 / count) / glossy.rms_radiance : 0.0;

      to.material = GlossyMaterial(Lobe{LobeKind::kPhong, n}, c.ks);
      need.best_lobe_error = std::numeric_limits<double>::infinity();
      for (int l : vector_lmax) {
        GlossyVectorRow row;
        row.mode = mode;
        row.exponent = n;
        row.lmax = l;
        to.lmax = l;
        int directions = 0;
        const Transport t = TimedTransport(mesh, to, row.seconds, directions);
        const ShRgb part = FirstBands(light, l);
        VectorShading s{ShadeVertices(mesh, t, part), ShadeGlossy(mesh, t, part)};
        row.total = CompareVertices(s.total, ref.total);
        row.lobe = CompareVertices(s.lobe, ref.lobe);
        row.band_share = LobeBandShare(to.material.lobe, l);
        if (row.lobe.relative < need.best_lobe_error) need.best_lobe_error = row.lobe.relative, need.best_lmax = l;
        if (need.needed_lmax < 0 && row.lobe.relative <= kLobeTarget) need.needed_lmax = l;
        study.vector_rows.push_back(row);
        const bool matrix_lmax = std::find(c.matrix_lmax.begin(), c.matrix_lmax.end(), l) != c.matrix_lmax.end();
        if (mode == TransportMode::kShadowed && matrix_lmax) kept[{n, l}] = std::move(s);
      }
      if (mode == TransportMode::kShadowed) shadowed_references[n] = std::move(ref);
      Summary(Formatted("report: glossy phong:%d %s, vector path swept, lmax %d..%d", n, TransportModeName(mode),
                        vector_lmax.front(), vector_lmax.back()));
    }
  }

  // Shadowed, the matrices do not depend on the lobe: one run per lmax, shaded for every exponent.
  TransportOptions to;
  to.mode = TransportMode::kShadowed;
  to.sampler = Sampler::kFibonacci;
  to.samples = c.samples;
  to.seed = c.seed;
  to.matrices = true;
  to.material = GlossyMaterial(Lobe{LobeKind::kPhong, c.exponents.front()}, c.ks);
  for (int l : c.matrix_lmax) {
    to.lmax = l;
    double seconds = 0.0;
    int directions = 0;
    Transport t = TimedTransport(mesh, to, seconds, directions);
    const ShRgb part = FirstBands(light, l);
    for (int n : c.exponents) {
      t.material = GlossyMaterial(Lobe{LobeKind::kPhong, n}, c.ks);
      GlossyMatrixRow row;
      row.exponent = n;
      row.lmax = l;
      row.seconds = seconds;
      row.bytes = TransferMatrixBytes(mesh.vertex_count(), l, t.channels);
      const std::vector<glm::vec3> total = ShadeVertices(mesh, t, part, true, &eye);
      const std::vector<glm::vec3> lobe = ShadeGlossy(mesh, t, part, &eye);
      const References& ref = shadowed_references.at(n);
      row.total = CompareVertices(total, ref.total);
      row.lobe = CompareVertices(lobe, ref.lobe);
      const VectorShading& s = kept.at({n, l});
      row.vs_vector = CompareVertices(total, s.total);
      row.lobe_vs_vector = CompareVertices(lobe, s.lobe);
      study.matrix_rows.push_back(row);
    }
    if (l == c.cpca_lmax && !c.cpca_clusters.empty()) {
      // The compressed matrices against these, from an orbit of eyes about the mesh's centre.
      glm::dvec3 lo(mesh.positions.front()), hi = lo;
      for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
      t.material = GlossyMaterial(Lobe{LobeKind::kPhong, c.cpca_exponent}, c.ks);
      study.cpca = RunCpcaStudy(mesh, t, part, OrbitEyes(eye, 0.5 * (lo + hi), c.cpca_views), c.cpca_clusters,
                                c.cpca_terms);
    }
  }
  if (!c.matrix_lmax.empty())
    Summary(Formatted("report: glossy transfer matrices swept, lmax %d..%d", c.matrix_lmax.front(), c.matrix_lmax.back()));
  return study;
}

}  // namespace prt
