// SceneWavelets (scene_wavelets.h): the wavelet transport of the scene, from its cache
// (wavelet/transport_cache.h) when nothing it depends on changed, else computed and cached, by
// the policy every basis follows (basis/cache_plan.h).
#include "wavelet/scene_wavelets.h"
#include "core/error.h"
#include "core/log.h"
#include "core/text.h"
#include "wavelet/summary.h"
#include "wavelet/transport_cache.h"

namespace prt {
namespace {

/// The run-summary line of a transport taken from the cache at `path`; `every` when it was made
/// with every vertex computed as a seen one, though fewer were asked for.
std::string CachedLine(const std::string& path, const WaveletTransport& t, const WaveletOptions& w, bool every) {
  const double kept = t.vertices ? double(t.Kept()) / double(t.vertices) : 0.0;
  return "transport: taken from the cache " + path + " (same mesh and options" +
         (every ? ", with " + std::to_string(w.split * w.split) +
                      " rays a texel at every vertex, not only those the camera sees"
                : std::string()) +
         "): Haar wavelets on a cube of 6 x " + std::to_string(t.face_size) + "^2 texels (--cube-size " +
         std::to_string(t.face_size) + "), " +
         Formatted("%.0f coefficients a vertex kept on average (--wavelet-terms %d), %.1f MB", kept, w.budget,
                   double(t.Bytes()) / 1e6) +
         (t.bounce.coeffs.empty() ? "" : ", the bounces in SH at lmax " + std::to_string(t.bounce.lmax));
}

}  // namespace

WaveletTransport SceneWavelets(const Basis& wavelet, const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& w,
                               const Environment& env, const CachePlan& cache) {
  TransportOptions every = sh;
  every.seen.clear();
  CacheSteps<WaveletTransport> steps;
  steps.key = WaveletTransportKey(mesh, sh, w);
  steps.every_key = WaveletTransportKey(mesh, every, w);
  steps.read = [](const std::string& path, std::uint64_t key, std::string& why) { return ReadWaveletCache(path, key, why); };
  // A transport whose every vertex was computed as a seen one holds at least what this one
  // needs at every vertex: taken as it is.
  steps.taken = [&](WaveletTransport& t, bool all) { Summary(CachedLine(cache.path, t, w, all)); };
  steps.compute = [&] { return ComputeSceneWavelets(mesh, sh, w, env); };
  steps.write = [](const std::string& path, const WaveletTransport& t, std::uint64_t key) { WriteWaveletCache(path, t, key); };
  return CachedOrComputed(wavelet, cache, steps);
}

}  // namespace prt
