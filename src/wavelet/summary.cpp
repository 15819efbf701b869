#include "wavelet/summary.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/log.h"
#include "core/text.h"
#include "precompute/bounce_summary.h"
#include "wavelet/light_cube.h"
#include "wavelet/shade.h"
#include "wavelet/texel_sh.h"

namespace prt {
namespace {

/// Relative RMS difference, over the probes, of the direct light the kept coefficients give and
/// the one every coefficient gives, under `env` as frame 0 sees it (its light kept as the
/// options keep it).
double TruncationCost(const WaveletTransport& t, const Environment& env, const WaveletOptions& w) {
  const CubeGrid grid(t.face_size);
  CubeRgb rgb;
  const std::unique_ptr<TexelSh> base = t.base_lmax >= 0 ? std::make_unique<TexelSh>(grid, t.base_lmax) : nullptr;
  const WaveletLight light = TurnedWaveletLight(LightCube(env, grid), glm::dmat3(1.0), w.light_terms,
                                                SelectionWeights(grid.size(), w.light_selection), base.get(), rgb);
  double num = 0.0, den = 0.0;
  for (std::size_t p = 0; p < t.probes.size(); ++p) {
    const glm::vec3 full = ShadeDense(t.probe_coeffs.data() + p * grid.texels(), light) +
                           glm::vec3(BaseDirectLight(t, t.probes[p], light));
    const glm::vec4 kept = DirectLight(t, t.probes[p], light);
    for (int c = 0; c < 3; ++c) num += std::pow(double(kept[c]) - full[c], 2.0), den += double(full[c]) * full[c];
  }
  return den > 0 ? std::sqrt(num / den) : 0.0;
}

}  // namespace

WaveletTransport ComputeSceneWavelets(const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& w,
                                      const Environment& env) {
  TransportReport r;
  const WaveletTransport t = ComputeWaveletTransport(mesh, sh, w, &r);
  const std::size_t texels = std::size_t(6) * w.face_size * w.face_size;
  const double kept = t.vertices ? double(t.Kept()) / double(t.vertices) : 0.0;
  std::string line = std::string("transport: ") + TransportModeName(sh.mode) + " in Haar wavelets on a cube of 6 x " +
                     std::to_string(w.face_size) + "^2 texels (--cube-size " + std::to_string(w.face_size) + ")" +
                     Formatted(" [%.3f s]", t.seconds) + "; ";
  std::size_t hidden = 0;
  for (std::uint8_t s : sh.seen) hidden += s == 0;
  if (sh.mode == TransportMode::kUnshadowed) {
    line += "no rays (nothing blocks); ";
  } else {
    line += std::to_string(w.split * w.split) + " jittered rays per texel" +
            (hidden ? " (1 for the " + std::to_string(hidden) + " vertices no frame shows)" : std::string()) + ", " +
            std::to_string(t.rays) + " rays (none below the horizon); ";
  }
  if (t.base_lmax >= 0)
    line += "its smooth part in SH to lmax " + std::to_string(t.base_lmax) + " (" +
            std::to_string(CoeffCount(t.base_lmax)) + " floats a vertex), and of what that leaves out ";
  line += std::string(t.base_lmax >= 0 ? "" : "each vertex keeps ") + "its " + std::to_string(w.budget) +
          " most important of " + std::to_string(texels) +
          " wavelet coefficients (--wavelet-terms; its 6 faces' means, then the details by " + SelectionName(w.selection) +
          " weight, quantised to 16 bits)" +
          Formatted(": %.0f on average, %.2f%% of their energy kept, %.0f bytes a vertex in all (%.1f MB)", kept,
                    100.0 * t.kept_energy, double(t.Bytes()) / double(std::max<std::size_t>(t.vertices, 1)),
                    double(t.Bytes()) / 1e6);
  Summary(line);
  Summary("wavelet truncation: frame 0's direct light at " + std::to_string(t.probes.size()) +
          " sample vertices differs from their unkept transport's by " +
          Formatted("%.3g%%", 100.0 * TruncationCost(t, env, w)) + " RMS (relative)" +
          (w.light_terms > 0 ? ", the light kept to its " + std::to_string(w.light_terms) +
                                         " most important coefficients (--light-terms)"
                                   : ", every light coefficient used (--light-terms 0)"));
  if (sh.mode == TransportMode::kInterreflection) {
    Summary("bounced light: in SH at lmax " + std::to_string(sh.lmax) +
            " (low frequency; interreflection's direct part is left to the wavelets) [" +
            Formatted("%.3f s", r.direct_seconds + r.bounce_seconds) + "]");
    ReportBounces(r, t.bounce.channels);
  }
  return t;
}

}  // namespace prt
