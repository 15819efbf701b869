// The glossy part of `prt bench transport`, on the demo scene (albedo 0.5, so that KS 0.4 keeps
// energy) seen from the demo camera, at one lmax, with all threads:
//   - the shadowed diffuse precompute against the fixed-camera glossy one (phong:50,0.4: T and G),
//     timed side by side -> ratio_glossy_vs_diffuse_precompute;
//   - the transfer matrices' precompute (T and M) and their memory;
//   - one orbit frame's shading (every vertex from its matrix, toward the eye) against one diffuse
//     frame's (every vertex's L.T), timed side by side -> ratio_matrix_frame_vs_diffuse_frame. A
//     frame there is the per-vertex shading only: the light's rotation (microseconds) and the
//     rasterization, the same for both, are left out. The same with the rasterization of
//     render's default frame (640x480, 2x2 supersampling) added to both ->
//     ratio_matrix_frame_vs_diffuse_frame_with_raster, what a render loop sees;
//   - the matrices compressed by clustered PCA at render's default --cpca (cpca/cpca_transfer.h):
//     the compression's time, bytes against the full matrices' (ratio_cpca_bytes_vs_matrices),
//     its error, and the orbit frame shaded from it against the diffuse frame
//     (ratio_cpca_frame_vs_diffuse_frame, with the rasterization too) and the full matrix frame.

#include <algorithm>
#include <string>

#include "app/render_args.h"
#include "bench/bench.h"
#include "core/parallel.h"
#include "cpca/cpca_transfer.h"
#include "env/procedural.h"
#include "geometry/bvh_kernels.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "material/material.h"
#include "precompute/error_metrics.h"
#include "precompute/light.h"
#include "precompute/shade.h"
#include "precompute/transfer_matrix.h"
#include "precompute/transport.h"
#include "raster/camera.h"
#include "raster/rasterizer.h"

namespace prt::bench {

DemoFrameDrawer::DemoFrameDrawer() {
  const RenderOptions demo = WithDemoCamera({});
  camera_.eye = glm::vec3(*demo.eye);
  camera_.target = glm::vec3(*demo.target);
  camera_.fov_deg = float(*demo.fov);
  raster_.ssaa = demo.ssaa;
  width_ = demo.width;
  height_ = demo.height;
}

void DemoFrameDrawer::Draw(const Mesh& mesh, const std::vector<glm::vec3>& colors) {
  rasterizer_.Draw(camera_, width_, height_, mesh.positions, mesh.triangles, colors, raster_);
}

void BenchGlossy(int runs, int threads, int samples, int lmax) {
  SetThreadCount(threads);
  Mesh mesh = MakeDemoScene();
  SetUniformAlbedo(mesh, glm::vec3(0.5f));
  const glm::dvec3 eye = *WithDemoCamera({}).eye;
  const Material material = ParseMaterial("phong:50,0.4");
  Print("glossy_threads", double(ThreadCount()));
  Print("glossy_material", material.Name());
  Print("glossy_vertices", double(mesh.vertex_count()));
  Print("glossy_lmax", double(lmax));
  Print("glossy_samples", double(samples));

  TransportOptions diffuse;
  diffuse.lmax = lmax;
  diffuse.samples = samples;
  TransportOptions glossy = diffuse;
  glossy.material = material;
  glossy.eye = eye;
  TransportOptions matrices = glossy;
  matrices.matrices = true;
  Print("glossy_lobe_rays_per_vertex", double(LobeSamplesOf(samples)));

  // Precompute: diffuse and fixed-camera glossy side by side, then the matrices.
  const SideBySide pre = TimeSideBySide(runs, [&] { ComputeTransport(mesh, diffuse, nullptr); },
                                        [&] { ComputeTransport(mesh, glossy, nullptr); });
  Print("transport_diffuse_shadowed_s", pre.ours);
  Print("transport_glossy_vector_s", pre.theirs);
  Print("ratio_glossy_vs_diffuse_precompute", pre.ratio);
  Transport m;
  const double matrix_s = MedianSeconds(runs, [&] { m = ComputeTransport(mesh, matrices, nullptr); });
  Print("transport_matrices_s", matrix_s);
  Print("transport_matrices_bytes", double(TransferMatrixBytes(mesh.vertex_count(), lmax, m.channels)));
  Print("ratio_matrices_vs_diffuse_precompute", matrix_s / pre.ours);

  // One frame's shading of every vertex.
  const Transport d = ComputeTransport(mesh, diffuse, nullptr);
  const ShRgb light = ProjectLight(*MakeSky(SkyParams{}), lmax);
  const SideBySide frame = TimeSideBySide(std::max(runs, 9), [&] { ShadeVertices(mesh, d, light); },
                                          [&] { ShadeVertices(mesh, m, light, true, &eye); });
  Print("frame_diffuse_shading_ms", 1e3 * frame.ours);
  Print("frame_matrix_shading_ms", 1e3 * frame.theirs);
  Print("ratio_matrix_frame_vs_diffuse_frame", frame.ratio);

  // The same orbit frame from the matrices compressed by clustered PCA at render's default --cpca.
  const CpcaOptions co = RenderJobOptions{}.cpca;
  CpcaTransfer cpca;
  const double cpca_s = MedianSeconds(std::min(runs, 3), [&] { cpca = CompressTransferMatrices(m, co); });
  const double full_bytes = double(TransferMatrixBytes(mesh.vertex_count(), lmax, m.channels));
  Print("cpca_clusters", double(co.clusters));
  Print("cpca_terms", double(co.terms));
  Print("cpca_compress_s", cpca_s);
  Print("cpca_bytes", double(cpca.model.Bytes()));
  Print("ratio_cpca_bytes_vs_matrices", double(cpca.model.Bytes()) / full_bytes);
  Print("cpca_matrices_relative_error", CpcaRelativeError(cpca.model, m.matrices.data()));
  Print("cpca_glossy_relative_error",
        CompareVertices(GlossyFromCpca(mesh, cpca, m.material, light, eye), ShadeGlossy(mesh, m, light, &eye)).relative);
  const SideBySide cpca_frame = TimeSideBySide(std::max(runs, 9), [&] { ShadeVertices(mesh, d, light); },
                                               [&] { ShadeVerticesCpca(mesh, m, cpca, light, true, eye); });
  Print("frame_cpca_shading_ms", 1e3 * cpca_frame.theirs);
  Print("ratio_cpca_frame_vs_diffuse_frame", cpca_frame.ratio);
  const SideBySide cpca_matrix = TimeSideBySide(std::max(runs, 9), [&] { ShadeVertices(mesh, m, light, true, &eye); },
                                                [&] { ShadeVerticesCpca(mesh, m, cpca, light, true, eye); });
  Print("ratio_cpca_frame_vs_matrix_frame", cpca_matrix.ratio);

  DemoFrameDrawer drawer;
  const auto draw = [&](const std::vector<glm::vec3>& colors) { drawer.Draw(mesh, colors); };
  const SideBySide drawn = TimeSideBySide(std::max(runs, 9), [&] { draw(ShadeVertices(mesh, d, light)); },
                                          [&] { draw(ShadeVertices(mesh, m, light, true, &eye)); });
  Print("frame_diffuse_with_raster_ms", 1e3 * drawn.ours);
  Print("frame_matrix_with_raster_ms", 1e3 * drawn.theirs);
  Print("ratio_matrix_frame_vs_diffuse_frame_with_raster", drawn.ratio);
  const SideBySide drawn_cpca = TimeSideBySide(std::max(runs, 9), [&] { draw(ShadeVertices(mesh, d, light)); },
                                               [&] { draw(ShadeVerticesCpca(mesh, m, cpca, light, true, eye)); });
  Print("frame_cpca_with_raster_ms", 1e3 * drawn_cpca.theirs);
  Print("ratio_cpca_frame_vs_diffuse_frame_with_raster", drawn_cpca.ratio);
  SetThreadCount(0);
}

}  // namespace prt::bench
