// SceneWavelets (pipeline.h): the wavelet transport of the scene, from its cache
// (wavelet/transport_cache.h) when nothing it depends on changed, else computed and cached. The
// same rules as the SH transport's (ComputeSceneTransport, pipeline.cpp): the same --cache option
// and run-summary lines, the same reuse of a transport whose every vertex was computed as a seen
// one, the same refusal of a stale or damaged file.
#include "app/pipeline.h"
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

WaveletTransport SceneWavelets(const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& w,
                               const Environment& env, const CachePlan& cache) {
  const std::uint64_t key = WaveletTransportKey(mesh, sh, w);
  std::string why;
  if (!cache.path.empty()) {
    if (auto cached = ReadWaveletCache(cache.path, key, why)) {
      Summary(CachedLine(cache.path, *cached, w, false));
      return std::move(*cached);
    }
    // A transport whose every vertex was computed as a seen one holds at least what this one
    // needs at every vertex: taken as it is.
    TransportOptions every = sh;
    every.seen.clear();
    const std::uint64_t every_key = WaveletTransportKey(mesh, every, w);
    std::string ignored;
    if (every_key != key) {
      if (auto cached = ReadWaveletCache(cache.path, every_key, ignored)) {
        Summary(CachedLine(cache.path, *cached, w, true));
        return std::move(*cached);
      }
    }
  }
  WaveletTransport t = ComputeSceneWavelets(mesh, sh, w, env);
  if (!cache.path.empty() && cache.write) {
    if (why != "no cache yet") Summary("cache: " + cache.path + " ignored (" + why + "), recomputed");
    try {
      WriteWaveletCache(cache.path, t, key);
    } catch (const Error& e) {
      Warn(std::string(e.what()) + "; the transport was computed but not cached");
    }
  }
  return t;
}

}  // namespace prt
