// CompressSceneMatrices (scene_transport.h): a glossy --orbit's transfer matrices compressed by
// clustered PCA (cpca/cpca_transfer.h), said on the run summary with the memory and the error.
//
// The defaults of --cpca (render/render_options.h: 256 clusters, 4 terms), measured on the demo
// scene (MakeDemoScene, 33 985 vertices, shadowed, 1024 directions, lmax 4, phong:50,0.4 under the
// sky, 8 views on an orbit; report/report_cpca.h): 0.046 of the matrices' memory (3.7 of 81 MiB),
// relative error 2.9 % in the matrices (Frobenius), 2.1 % in the glossy and 0.8 % in the rendered
// radiance; 64 x 8 is 3.0 % glossy at 0.031 of the memory but shades 9 products a vertex instead
// of 5; 256 x 8 halves the error at twice the per-vertex work. A frame's shading then costs
// 2.9-3.3 diffuse frames (the full matrices: 6.4-7.5; `prt bench transport`, 2 threads).
#include <algorithm>
#include <chrono>

#include "sh_basis/scene_transport.h"
#include "core/log.h"
#include "core/memory.h"
#include "core/text.h"
#include "precompute/transfer_matrix.h"

namespace prt {

CpcaTransfer CompressSceneMatrices(Transport& transport, int clusters, int terms) {
  // A mesh of few vertices: no more clusters than leave the model smaller than the matrices.
  const std::size_t matrices = transport.vertices * transport.channels;
  const int fitting = int(std::max<std::size_t>(1, matrices / (std::size_t(terms) + 1)));
  CpcaOptions o;
  o.clusters = std::min(clusters, fitting);
  o.terms = terms;
  const auto t0 = std::chrono::steady_clock::now();
  CpcaTransfer cpca = CompressTransferMatrices(transport, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double error = CpcaRelativeError(cpca.model, transport.matrices.data());
  const std::uint64_t full = transport.matrices.size() * sizeof(float), bytes = cpca.model.Bytes();
  const std::size_t rows = cpca.model.rows;
  Summary("cpca: the transfer matrices compressed by clustered PCA to " + std::to_string(cpca.model.clusters) +
          " clusters x " + std::to_string(cpca.model.terms) + " terms (--cpca " + std::to_string(clusters) + "," +
          std::to_string(terms) + "; --cpca off for the full matrices" +
          (o.clusters < clusters ? "; fewer clusters: " + std::to_string(matrices) + " matrices hold at most " +
                                       std::to_string(fitting) + " clusters of " + std::to_string(terms + 1) + " terms"
                                 : "") +
          "): " + ByteText(bytes) + " instead of " + ByteText(full) + Formatted(" (%.4f of the memory)", double(bytes) / double(full)) +
          Formatted(", relative error %.3g%% (Frobenius, over all %zu vertex matrices of this mesh)", 100.0 * error, rows) +
          "; each frame's light goes through each cluster's matrices once" + Formatted(" [%.3f s]", seconds));
  // The full matrices stay in the cache (written already); the frames need only the compressed ones.
  std::vector<float>().swap(transport.matrices);
  return cpca;
}

}  // namespace prt
