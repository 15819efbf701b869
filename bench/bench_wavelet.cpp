// `prt bench wavelet`: what a frame costs in the wavelet basis beside SH, on the demo scene
// (33,985 vertices) seen from the demo camera, with all threads:
//   - one frame's shading: SH lmax 4 and lmax 16 (the light turned by its band matrices, then
//     every vertex's L.T) against wavelets at the default cube and budget (the environment
//     turned and resampled onto the cube, its Haar transform, then every vertex's sparse dot
//     product), each pair timed side by side -> ratio_wavelet_vs_sh4_shading,
//     ratio_wavelet_vs_sh16_shading;
//   - the same with the rasterization of render's default frame (640x480, 2x2 supersampling)
//     added -> ratio_wavelet_vs_sh16_frame_with_raster (the aim: under 2);
//   - the wavelet light alone (resampling and transform) and with the light cut to 256 terms.
// Shading cost does not depend on the coefficients' values, so the transports are the
// unshadowed ones (no rays: the bench measures frames, not the precompute).

#include <algorithm>

#include "app/pipeline.h"
#include "bench/bench.h"
#include "core/parallel.h"
#include "env/procedural.h"
#include "geometry/procedural.h"
#include "precompute/light.h"
#include "wavelet/transport.h"
#include "sh_basis/frame_light.h"
#include "wavelet/frame_light.h"

namespace prt::bench {

int BenchWavelet(Args& args) {
  const int runs = args.Int("--runs", 9, 1, 1000);
  SetThreadCount(args.Int("--threads", 0, 0, 1024));
  const Mesh mesh = MakeDemoScene();
  const auto sky = MakeSky(SkyParams{});
  const glm::dvec3 axis(0, 1, 0);
  Print("wavelet_vertices", double(mesh.vertex_count()));
  Print("wavelet_threads", double(ThreadCount()));

  TransportOptions o;
  o.mode = TransportMode::kUnshadowed;
  o.lmax = 4;
  const Transport sh4 = ComputeTransport(mesh, o, nullptr);
  o.lmax = 16;
  const Transport sh16 = ComputeTransport(mesh, o, nullptr);
  const WaveletOptions w;
  const WaveletTransport wt = ComputeWaveletTransport(mesh, o, w, nullptr);
  Print("wavelet_cube_size", double(w.face_size));
  Print("wavelet_terms", double(w.budget));
  Print("wavelet_bytes_per_vertex", double(wt.Bytes()) / double(mesh.vertex_count()));
  Print("sh16_bytes_per_vertex", double(sh16.coeffs.size() * sizeof(float)) / double(mesh.vertex_count()));

  const ShRgb light = ProjectLight(*sky, 16);
  const auto l4 = MakeShFrameLight(sh4, light, axis);
  const auto l16 = MakeShFrameLight(sh16, light, axis);
  const auto lw = MakeWaveletFrameLight(wt, *sky, light, axis, 0, WaveletOptions{}.selection);
  const auto lw256 = MakeWaveletFrameLight(wt, *sky, light, axis, 256, WaveletOptions{}.selection);
  double angle = 0.0;
  const auto frame = [&](FrameLight& l) {
    angle += 0.01;
    l.Turn(angle);
    return l.Shade(mesh, true, nullptr);
  };
  const int n = std::max(runs, 9);
  // TimeSideBySide's ratio is the second's time over the first's.
  const SideBySide vs4 = TimeSideBySide(n, [&] { frame(*l4); }, [&] { frame(*lw); });
  const SideBySide vs16 = TimeSideBySide(n, [&] { frame(*l16); }, [&] { frame(*lw); });
  Print("frame_sh4_shading_ms", 1e3 * vs4.ours);
  Print("frame_sh16_shading_ms", 1e3 * vs16.ours);
  Print("frame_wavelet_shading_ms", 1e3 * vs16.theirs);
  Print("ratio_wavelet_vs_sh4_shading", vs4.ratio);
  Print("ratio_wavelet_vs_sh16_shading", vs16.ratio);
  Print("frame_wavelet_light_ms", 1e3 * MedianSeconds(n, [&] { angle += 0.01; lw->Turn(angle); }));
  Print("frame_wavelet_light_256_terms_ms", 1e3 * MedianSeconds(n, [&] { angle += 0.01; lw256->Turn(angle); }));

  DemoFrameDrawer drawer;
  const auto draw = [&](FrameLight& l) { drawer.Draw(mesh, frame(l)); };
  const SideBySide drawn = TimeSideBySide(n, [&] { draw(*l16); }, [&] { draw(*lw); });
  Print("frame_sh16_with_raster_ms", 1e3 * drawn.ours);
  Print("frame_wavelet_with_raster_ms", 1e3 * drawn.theirs);
  Print("ratio_wavelet_vs_sh16_frame_with_raster", drawn.ratio);
  SetThreadCount(0);
  return 0;
}

}  // namespace prt::bench
