#include "wavelet/transport.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/error.h"
#include "core/log.h"
#include "core/parallel.h"
#include "core/progress.h"
#include "core/rng.h"
#include "geometry/bvh.h"
#include "geometry/ray.h"
#include "geometry/ray_fan.h"
#include "env/cube_faces.h"
#include "wavelet/cube_grid.h"
#include "wavelet/haar.h"
#include "wavelet/texel_sh.h"

namespace prt {
namespace {

constexpr std::size_t kProbes = 64;  ///< vertices whose unkept transport is kept too

/// One jittered fan: split^2 directions per texel, in texel order, each with its sub-square's
/// solid angle.
struct JitterSet {
  std::vector<glm::dvec3> dirs;
  std::vector<double> solid_angles;
  RayFan fan;
};

JitterSet MakeJitterSet(const CubeGrid& grid, int split, std::uint64_t seed, int set) {
  JitterSet s;
  grid.SubTexels(split, s.dirs, s.solid_angles);
  // Move each direction to a random point of its sub-square (face coordinates), keeping the
  // sub-square's exact solid angle.
  Pcg32 rng(seed, static_cast<std::uint64_t>(set));
  const int n = grid.size() * split;
  const double sub = 2.0 / n;
  for (std::size_t k = 0; k < s.dirs.size(); ++k) {
    // Sub-square k of texel t sits at (row, col) of the face's n x n sub-grid.
    const std::size_t t = k / (std::size_t(split) * split), i = (k / split) % split, j = k % split;
    const std::size_t rest = t % grid.face_texels();
    const int face = static_cast<int>(t / grid.face_texels());
    const std::size_t row = (rest / grid.size()) * split + i, col = (rest % grid.size()) * split + j;
    const double a = -1.0 + (double(col) + rng.NextDouble()) * sub, b = -1.0 + (double(row) + rng.NextDouble()) * sub;
    s.dirs[k] = grid.FacePoint(face, a, b);
  }
  std::vector<glm::vec3> dirs(s.dirs.begin(), s.dirs.end());
  s.fan = MakeRayFan(dirs);
  return s;
}

/// Integral over each texel of w dw (Arvo's vector irradiance): for a texel wholly above the
/// horizon of n, the clamped cosine is n . phi_t. With F even, every texel lies wholly on one
/// side of each axis plane, so each component is a clamped cosine about that axis.
std::vector<glm::dvec3> TexelVectors(const CubeGrid& grid) {
  std::vector<glm::dvec3> phi(grid.texels());
  for (std::size_t t = 0; t < grid.texels(); ++t) {
    // The three axis components: ClampedCosine of a texel wholly on one side of each plane.
    const glm::dvec3 d = grid.Direction(t);
    glm::dvec3 p(0.0);
    for (int a = 0; a < 3; ++a) {
      glm::dvec3 e(0.0);
      e[a] = d[a] >= 0 ? 1.0 : -1.0;
      p[a] = e[a] * grid.ClampedCosine(t, e);
    }
    phi[t] = p;
  }
  return phi;
}

/// The corners of every texel on the face planes (unnormalised: only their side of a plane
/// through the centre is read), (F + 1)^2 per face.
std::vector<glm::dvec3> CornerPoints(const CubeGrid& grid) {
  const int size = grid.size();
  const auto& frames = FaceFrames(CubeLayout::kStandard);
  std::vector<glm::dvec3> corners;
  for (int f = 0; f < 6; ++f)
    for (int i = 0; i <= size; ++i)
      for (int j = 0; j <= size; ++j)
        corners.push_back(frames[f].n + (-1.0 + 2.0 * j / size) * frames[f].u + (-1.0 + 2.0 * i / size) * frames[f].v);
  return corners;
}

/// Texel t's corners' side of the horizon from their dots with n (`dots`, CornerPoints' order):
/// +1 all above, -1 all below, 0 straddling.
int Side(const CubeGrid& grid, std::size_t t, const std::vector<double>& dots) {
  const int size = grid.size();
  const std::size_t face = t / grid.face_texels(), rest = t % grid.face_texels();
  const std::size_t row = rest / size, col = rest % size, stride = size + 1;
  const double* d = dots.data() + face * stride * stride + row * stride + col;
  const int above = (d[0] >= 0.0) + (d[1] >= 0.0) + (d[stride] >= 0.0) + (d[stride + 1] >= 0.0);
  return above == 4 ? 1 : above == 0 ? -1 : 0;
}

}  // namespace

WaveletTransport ComputeWaveletTransport(const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& options,
                                         TransportReport* report) {
  const auto t0 = std::chrono::steady_clock::now();
  // From 2: then no texel straddles an axis plane (TexelVectors).
  if (options.face_size < 2 || options.face_size > kMaxWaveletFace)
    throw Error("wavelet cube face size " + std::to_string(options.face_size) + ": from 2 to " +
                std::to_string(kMaxWaveletFace) + " (coefficient indices are 16-bit)");
  const CubeGrid grid(options.face_size);
  const std::size_t texels = grid.texels(), nv = mesh.vertex_count();
  WaveletTransport out;
  out.face_size = options.face_size;
  out.vertices = nv;

  const bool traced = sh.mode != TransportMode::kUnshadowed;
  const Bvh bvh = traced ? Bvh::Build(mesh) : Bvh{};
  // Vertices no frame shows (sh.seen) reach the picture only through --vertex-radiance: one ray
  // per texel for them.
  bool any_hidden = false;
  for (std::size_t v = 0; v < sh.seen.size() && v < nv; ++v) any_hidden |= sh.seen[v] == 0;
  std::vector<JitterSet> sets, hidden_sets;
  if (traced)
    for (int s = 0; s < kJitterSets; ++s) {
      sets.push_back(MakeJitterSet(grid, options.split, sh.seed, s));
      if (any_hidden && options.split > 1) hidden_sets.push_back(MakeJitterSet(grid, 1, MixSeed(sh.seed, 1), s));
    }
  const std::vector<glm::dvec3> phi = TexelVectors(grid);
  const std::vector<glm::dvec3> corners = CornerPoints(grid);
  const std::vector<double> weights = SelectionWeights(options.face_size, options.selection);
  const float scene_scale = traced ? bvh.SceneScale() : 1.0f;
  // The smooth part in SH first (texel_sh.h): the wavelets then keep only what it leaves out.
  std::unique_ptr<TexelSh> base;
  if (options.base_lmax >= 0) base = std::make_unique<TexelSh>(grid, options.base_lmax);
  const int base_count = base ? base->count() : 0;
  out.base_lmax = base ? options.base_lmax : -1;
  out.base.resize(static_cast<std::size_t>(base_count) * nv);

  for (std::size_t p = 0; p < kProbes && p < nv; ++p) out.probes.push_back(static_cast<std::uint32_t>(p * nv / std::min(kProbes, nv)));
  out.probe_coeffs.resize(out.probes.size() * texels);

  // Each vertex's kept coefficients into its own slot first (counts vary), then packed in
  // vertex order: the same result for any thread count.
  std::vector<std::vector<std::uint16_t>> kept_index(nv);
  std::vector<std::vector<std::int16_t>> kept_value(nv);
  out.means.resize(6 * nv);
  out.scale.resize(nv);
  std::vector<double> kept_energy(nv, 1.0);
  std::atomic<std::uint64_t> rays{0};
  Progress progress("wavelet transport", nv);
  ParallelFor(nv, 16, [&](std::size_t begin, std::size_t end) {
    std::vector<double> t(texels), scratch, dots(corners.size()), s(base_count);
    std::vector<std::uint8_t> blocked;
    std::vector<std::uint32_t> kept;
    std::uint64_t local_rays = 0;
    for (std::size_t v = begin; v < end; ++v) {
      const glm::dvec3 n(mesh.normals[v]);
      const bool hidden = !hidden_sets.empty() && v < sh.seen.size() && sh.seen[v] == 0;
      const std::vector<JitterSet>& pool = hidden ? hidden_sets : sets;
      const JitterSet* set = traced ? &pool[MixSeed(sh.seed ^ 0x9e3779b9ULL, v) % pool.size()] : nullptr;
      const int per_texel = hidden ? 1 : options.split * options.split;
      if (set) {
        const glm::vec3 origin = OffsetRayOrigin(mesh.positions[v], mesh.normals[v], scene_scale);
        bvh.OccludedFan(set->fan, origin, mesh.normals[v], std::numeric_limits<float>::infinity(), blocked);
      }
      for (std::size_t c = 0; c < corners.size(); ++c) dots[c] = glm::dot(n, corners[c]);
      for (std::size_t k = 0; k < texels; ++k) {
        const int side = Side(grid, k, dots);
        double cosine = side > 0 ? std::max(0.0, glm::dot(n, phi[k])) : side < 0 ? 0.0 : grid.ClampedCosine(k, n);
        if (cosine > 0.0 && set) {
          // The open share of the texel, each ray weighted by cos times its solid angle.
          double open = 0.0, all = 0.0;
          for (int r = 0; r < per_texel; ++r) {
            const std::size_t i = k * per_texel + r;
            const double c = glm::dot(n, set->dirs[i]);
            if (c <= 0.0) continue;
            ++local_rays;
            const double w = c * set->solid_angles[i];
            all += w;
            open += blocked[i] ? 0.0 : w;
          }
          if (all > 0.0) cosine *= open / all;
        }
        t[k] = cosine / kPi;
      }
      if (base) {
        // Stored as floats, and subtracted as stored: then sum_t L_t T_t is exactly the base's
        // sum_j s_j l_j plus the residual's, whatever the rounding.
        base->Project(t.data(), s.data());
        for (int j = 0; j < base_count; ++j) {
          const float stored = static_cast<float>(s[j]);
          out.base[v * base_count + j] = stored;
          s[j] = stored;
        }
        base->Subtract(s.data(), t.data());
      }
      for (int f = 0; f < 6; ++f) HaarForward(t.data() + f * grid.face_texels(), options.face_size, scratch);
      const auto probe = std::find(out.probes.begin(), out.probes.end(), static_cast<std::uint32_t>(v));
      if (probe != out.probes.end())
        std::copy(t.begin(), t.end(), out.probe_coeffs.begin() + (probe - out.probes.begin()) * texels);
      double all = 0.0, part = 0.0;
      for (double x : t) all += x * x;
      // The faces' means exactly, then the most important details, quantised.
      for (int f = 0; f < 6; ++f) {
        double& mean = t[f * grid.face_texels()];
        out.means[6 * v + f] = static_cast<float>(mean);
        part += mean * mean;
        mean = 0.0;
      }
      KeepLargest(t.data(), weights, static_cast<std::size_t>(std::max(options.budget - 6, 0)), kept);
      double largest = 0.0;
      for (std::uint32_t k : kept) largest = std::max(largest, std::abs(t[k]));
      const double step = largest / kQuantSteps;
      out.scale[v] = static_cast<float>(step);
      kept_index[v].resize(kept.size());
      kept_value[v].resize(kept.size());
      for (std::size_t j = 0; j < kept.size(); ++j) {
        kept_index[v][j] = static_cast<std::uint16_t>(kept[j]);
        kept_value[v][j] = static_cast<std::int16_t>(std::lround(t[kept[j]] / step));
        part += t[kept[j]] * t[kept[j]];
      }
      kept_energy[v] = all > 0.0 ? part / all : 1.0;
    }
    rays += local_rays;
    progress.Advance(end - begin);
  });

  out.offsets.assign(nv + 1, 0);
  for (std::size_t v = 0; v < nv; ++v) out.offsets[v + 1] = out.offsets[v] + kept_index[v].size();
  out.index.reserve(out.offsets[nv]);
  out.value.reserve(out.offsets[nv]);
  double energy = 0.0;
  for (std::size_t v = 0; v < nv; ++v) {
    out.index.insert(out.index.end(), kept_index[v].begin(), kept_index[v].end());
    out.value.insert(out.value.end(), kept_value[v].begin(), kept_value[v].end());
    energy += kept_energy[v];
  }
  out.kept_energy = nv ? energy / double(nv) : 1.0;
  out.rays = rays;
  out.seconds = SecondsSince(t0);

  TransportReport local;
  TransportReport& r = report ? *report : local;
  r = TransportReport{};
  if (sh.mode == TransportMode::kInterreflection) out.bounce = ComputeBouncedTransport(mesh, sh, &r);
  return out;
}

}  // namespace prt
