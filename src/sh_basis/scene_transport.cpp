// ComputeSceneTransport and CheckMatrixMemory (scene_transport.h): the SH transport of the
// scene, read from its cache or computed and cached by the policy every basis follows
// (basis/cache_plan.h), and the memory check of its transfer matrices.
#include "sh_basis/scene_transport.h"

#include <chrono>
#include <optional>

#include "core/error.h"
#include "core/log.h"
#include "core/memory.h"
#include "core/text.h"
#include "material/material.h"
#include "precompute/bounce_summary.h"
#include "precompute/sample_rule.h"
#include "precompute/transfer_matrix.h"
#include "precompute_io/transport_cache.h"

namespace prt {
namespace {

/// The share of the available memory the transfer matrices may take (the rest is for the mesh,
/// BVH, frames and the system).
constexpr double kMatrixMemoryShare = 0.6;

/// A vertex whose T_0 is below this share of the unoccluded T_0 sees (almost) no light: inside
/// an inside-out mesh only what leaks through holes in it, a few percent.
constexpr double kBlockedShare = 0.05;
/// Warn when more than this share of the vertices is blocked: a closed, right-way-out mesh on
/// its own has well under half of its vertices in full shadow.
constexpr double kBlockedWarnShare = 0.5;

void WarnIfMostlyBlocked(const Mesh& mesh, const Transport& transport, TransportMode mode) {
  if (mode == TransportMode::kUnshadowed || mesh.vertex_count() == 0) return;
  const double open_t0 = 0.28209479177387814;  // (A_0/pi) Y_00 = 1 * 1/(2 sqrt(pi))
  std::size_t blocked = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) blocked += transport.at(v, 0)[0] < kBlockedShare * open_t0;
  if (double(blocked) > kBlockedWarnShare * double(mesh.vertex_count()))
    Warn(std::to_string(blocked) + " of " + std::to_string(mesh.vertex_count()) +
         " vertices see almost no sky (less than 5% of an open one): is the mesh inside out (normals "
         "pointing inward) or enclosed? Check that faces wind counter-clockwise seen from outside and that "
         "normals point outward");
}

/// The run-summary line of a glossy material's fixed-view transfer: what was done and why it is
/// enough.
std::string GlossyLine(const TransportOptions& o, const TransportReport& r, const Transport& t) {
  if (o.matrices)
    return "material: " + o.material.Name() + ", transfer matrices for a view that moves: " +
           std::to_string(CoeffCount(o.lmax)) + "x" + std::to_string(CoeffCount(o.lmax)) + " per vertex" +
           (t.channels == 3 ? " and colour channel" : "") + " (" + ByteText(t.matrices.size() * sizeof(float)) +
           "), each frame's view applied by the lobe's zonal coefficients; they truncate the product of light, "
           "visibility and cosine to lmax before the lobe (prt report measures the difference from the "
           "fixed-camera vectors)" +
           (o.mode == TransportMode::kInterreflection ? "; blocked directions carry their hit points' light as diffuse surfaces" : "") +
           Formatted(" [%.3f s]", r.matrix_seconds);
  std::string line = "material: " + o.material.Name() +
                     ", fixed camera: one view-dependent transfer vector per vertex toward the eye (exact for the "
                     "band-limited light, the product of visibility, lobe and cosine not truncated; the camera does "
                     "not move, so no transfer matrices are needed); the lobe's unshadowed transfer by quadrature";
  if (o.mode != TransportMode::kUnshadowed)
    line += " minus what " + std::to_string(r.lobe_samples) + " lobe rays per vertex find blocked (" +
            std::to_string(r.lobe_rays) + " rays)";
  if (o.mode == TransportMode::kInterreflection)
    line += "; blocked lobe rays gather their hit points' light as diffuse surfaces (bounces up to B - 1 there)";
  return line + Formatted(" [%.3f s]", r.glossy_seconds);
}

/// How the transport's direction count was chosen: " (the sample rule's default at lmax L: ...;
/// --samples N overrides)" when it came from the rule, "" when --samples gave it or the transport
/// is unshadowed.
std::string SamplesOrigin(const TransportOptions& o, bool from_rule, bool every_vertex = false) {
  if (!from_rule || o.mode == TransportMode::kUnshadowed) return "";
  return " (the sample rule's default at lmax " + std::to_string(o.lmax) + ": " +
         (every_vertex ? SampleRuleTextEveryVertex(o.sampler) : SampleRuleText(o.sampler)) +
         "; it aims at frame 0 within 2 levels of a converged frame at every pixel, as measured at lmax 2 and 4; "
         "--samples N and --hidden-samples N override)";
}

/// How many directions the transport's vertices took, for its summary line.
std::string DirectionsText(bool from_rule, const TransportOptions& o, const TransportReport& r,
                           std::size_t vertices) {
  const std::string sampler = SamplerName(o.sampler);
  // One count when every vertex took it: no camera (precompute), or every vertex seen.
  if (r.hidden_directions == 0 || r.hidden_vertices == 0)
    return std::to_string(r.directions_per_vertex) + " " + sampler + " directions per vertex" +
           SamplesOrigin(o, from_rule, o.seen.empty());
  return std::to_string(r.directions_per_vertex) + " " + sampler + " directions for each of the " +
         std::to_string(vertices - r.hidden_vertices) + " vertices the camera sees, " +
         std::to_string(r.hidden_directions) + " for the " + std::to_string(r.hidden_vertices) +
         " it does not" + SamplesOrigin(o, from_rule);
}

}  // namespace

TransportOptions SceneTransportOptions(const TransportOptions& options, const Camera* camera, bool matrices) {
  TransportOptions topts = options;
  if (camera && !matrices) topts.eye = glm::dvec3(camera->eye);
  topts.matrices = matrices && options.material.glossy;
  return topts;
}

Transport ComputeSceneTransport(const Basis& sh, const Mesh& mesh, const TransportOptions& options, bool samples_from_rule,
                                const CachePlan& cache, const Camera* camera, bool matrices,
                                const ShardedTransport& sharded) {
  const TransportOptions topts = SceneTransportOptions(options, camera, matrices);
  // topts.seen is used only where the two counts differ (direction_pool.h, the cache key).
  TransportOptions every = topts;
  every.seen.clear();
  CacheSteps<Transport> steps;
  steps.key = TransportKey(mesh, topts);
  steps.every_key = TransportKey(mesh, every);
  steps.read = [](const std::string& path, std::uint64_t key, std::string& why) {
    return ReadTransportCache(path, key, why);
  };
  steps.taken = [&](Transport& t, bool all) {
    // A transport with --samples at every vertex (what precompute writes) holds at least what
    // this one needs at every vertex: taken as it is.
    Summary("transport: taken from the cache " + cache.path + " (same mesh and options" +
            (all ? ", with " + std::to_string(topts.samples) + " directions at every vertex, not only those the camera sees"
                 : std::string()) +
            ")");
    t.material = topts.material;
    WarnIfMostlyBlocked(mesh, t, topts.mode);
  };
  if (sharded.transport && sharded.key != steps.key)
    throw Error("the shards were made from another mesh or other options than those read now (their cache key " +
                Formatted("%016llx", static_cast<unsigned long long>(sharded.key)) + ", now " +
                Formatted("%016llx", static_cast<unsigned long long>(steps.key)) +
                ") (expected the same mesh, environment and options as the shards' tasks)");
  steps.compute = [&] {
    if (sharded.transport) {
      Summary("transport: " + std::string(TransportModeName(topts.mode)) + ", lmax " + std::to_string(topts.lmax) +
              ", assembled from " + std::to_string(sharded.shards) + " shards (" +
              std::to_string(sharded.transport->vertices) + " vertices), as one run computes it");
      Transport t = *sharded.transport;
      t.material = topts.material;
      WarnIfMostlyBlocked(mesh, t, topts.mode);
      return t;
    }
    const auto t0 = std::chrono::steady_clock::now();
    TransportReport r;
    Transport transport = ComputeTransport(mesh, topts, &r);
    const double seconds = SecondsSince(t0);
    std::string line = std::string("transport: ") + TransportModeName(topts.mode) + ", lmax " +
                       std::to_string(topts.lmax) + Formatted(" [%.3f s]", seconds);
    if (topts.mode == TransportMode::kUnshadowed) {
      line += "; closed form at every vertex: no BVH, no rays";
    } else {
      line += Formatted("; BVH %.3f s; ", r.bvh_seconds) + DirectionsText(samples_from_rule, topts, r, mesh.vertex_count()) +
              ", " + std::to_string(r.rays) + " rays (none below the horizon); " + std::to_string(r.closed_form_vertices) +
              " of " + std::to_string(mesh.vertex_count()) + " vertices unoccluded, given the exact closed form";
    }
    Summary(line);
    if (topts.mode == TransportMode::kInterreflection) ReportBounces(r, transport.channels);
    if (topts.material.glossy) Summary(GlossyLine(topts, r, transport));
    WarnIfMostlyBlocked(mesh, transport, topts.mode);
    return transport;
  };
  steps.write = [](const std::string& path, const Transport& t, std::uint64_t key) { WriteTransportCache(path, t, key); };
  return CachedOrComputed(sh, cache, steps);
}

void CheckMatrixMemory(const Mesh& mesh, TransportMode mode, int lmax) {
  const int channels = TransportChannels(mesh, mode);
  const std::uint64_t need = TransferMatrixBytes(mesh.vertex_count(), lmax, channels);
  const std::uint64_t available = AvailableMemoryBytes();
  const std::uint64_t budget = std::uint64_t(kMatrixMemoryShare * double(available));
  if (available == 0 || need <= budget) {
    Summary("transfer matrices: " + ByteText(need) + " for " + std::to_string(mesh.vertex_count()) + " vertices at lmax " +
            std::to_string(lmax) + (available ? " (" + ByteText(available) + " available)" : ""));
    return;
  }
  int fits = -1;
  while (fits + 1 <= lmax && TransferMatrixBytes(mesh.vertex_count(), fits + 1, channels) <= budget) ++fits;
  throw Error("--lmax " + std::to_string(lmax) + ": the transfer matrices would take " + ByteText(need) + " (" +
              std::to_string(mesh.vertex_count()) + " vertices x " + std::to_string(channels) + " x " +
              std::to_string(CoeffCount(lmax)) + "^2 floats), more than the " + ByteText(budget) +
              " prt allows itself (" + Formatted("%.0f%%", 100.0 * kMatrixMemoryShare) + " of the " + ByteText(available) +
              " available) (expected " +
              (fits >= 0 ? "--lmax " + std::to_string(fits) + " or lower" : "a mesh with fewer vertices") +
              ", or no --orbit: the fixed camera needs one vector per vertex)");
}

}  // namespace prt
