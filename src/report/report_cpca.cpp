#include "report/report_cpca.h"

#include <chrono>
#include <cmath>

#include "core/constants.h"
#include "core/log.h"
#include "core/text.h"
#include "cpca/cpca_transfer.h"
#include "precompute/shade.h"
#include "precompute/transfer_matrix.h"
#include "core/markdown_table.h"

namespace prt {
namespace {

/// Every vertex of every view, as one list.
void Append(std::vector<glm::vec3>& all, const std::vector<glm::vec3>& some) { all.insert(all.end(), some.begin(), some.end()); }

}  // namespace

std::vector<glm::dvec3> OrbitEyes(const glm::dvec3& eye, const glm::dvec3& target, int count) {
  std::vector<glm::dvec3> eyes;
  const glm::dvec3 d = eye - target;
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * kPi * i / count, c = std::cos(a), s = std::sin(a);
    eyes.push_back(target + glm::dvec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z));
  }
  return eyes;
}

CpcaStudy RunCpcaStudy(const Mesh& mesh, const Transport& t, const ShRgb& light, const std::vector<glm::dvec3>& eyes,
                       const std::vector<int>& clusters, const std::vector<int>& terms) {
  CpcaStudy study;
  study.lmax = t.lmax;
  study.channels = t.channels;
  study.views = int(eyes.size());
  study.exponent = t.material.lobe.exponent;
  study.vertices = t.vertices;
  study.full_bytes = TransferMatrixBytes(t.vertices, t.lmax, t.channels);
  // The full matrices' radiance, once.
  std::vector<glm::vec3> full_glossy, full_total, diffuse;
  diffuse = ShadeDiffuse(mesh, t, light);
  for (const glm::dvec3& eye : eyes) {
    const std::vector<glm::vec3> g = GlossyFromMatrices(mesh, t, t.material, light, eye);
    Append(full_glossy, g);
    for (std::size_t v = 0; v < g.size(); ++v) full_total.push_back(diffuse[v] + g[v]);
  }
  for (int c : clusters)
    for (int k : terms) {
      CpcaStudyRow row;
      row.clusters = c, row.terms = k;
      CpcaOptions o;
      o.clusters = c, o.terms = k;
      const auto t0 = std::chrono::steady_clock::now();
      const CpcaTransfer cpca = CompressTransferMatrices(t, o);
      row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      row.frobenius = CpcaRelativeError(cpca.model, t.matrices.data());
      std::vector<glm::vec3> glossy, total;
      for (const glm::dvec3& eye : eyes) {
        const std::vector<glm::vec3> g = GlossyFromCpca(mesh, cpca, t.material, light, eye);
        Append(glossy, g);
        for (std::size_t v = 0; v < g.size(); ++v) total.push_back(diffuse[v] + g[v]);
      }
      row.glossy = CompareVertices(glossy, full_glossy);
      row.total = CompareVertices(total, full_total);
      row.bytes = cpca.model.Bytes();
      row.memory_ratio = double(row.bytes) / double(study.full_bytes);
      study.rows.push_back(row);
    }
  Summary(Formatted("report: CPCA of the lmax %d transfer matrices swept, %zu settings", t.lmax, study.rows.size()));
  return study;
}

std::string CpcaMarkdown(const CpcaStudy& d) {
  std::string s = Formatted(
      "\n### Transfer matrices compressed by clustered PCA (shadowed, lmax %d, N %d)\n\n"
      "Each vertex's matrix (per channel: %d) is its cluster's mean plus K weighted principal matrices "
      "(cpca/cpca.h; `prt render --orbit` uses them, `--cpca C,K`). `matrices` is the relative Frobenius error over "
      "all %zu vertices; `glossy` and `total` the relative RMS of the lobe's and the rendered radiance against the "
      "full matrices' over %d views on an orbit about the target (every vertex of every view). Memory: the clusters' "
      "means and directions plus K weights and a cluster index per row, against the full matrices' %s MiB.\n\n",
      d.lmax, d.exponent, d.channels, d.vertices, d.views, Formatted("%.3g", double(d.full_bytes) / 1048576.0).c_str());
  s += MarkdownHeader({"clusters", "terms", "matrices error", "glossy error", "total error", "memory ratio", "MiB",
                       "compression seconds"});
  for (const auto& r : d.rows)
    s += MarkdownRow({std::to_string(r.clusters), std::to_string(r.terms), Formatted("%.3g%%", 100.0 * r.frobenius),
                      Formatted("%.3g%%", 100.0 * r.glossy.relative), Formatted("%.3g%%", 100.0 * r.total.relative),
                      Formatted("%.4f", r.memory_ratio), Formatted("%.3g", double(r.bytes) / 1048576.0),
                      Formatted("%.3g", r.seconds)});
  return s;
}

std::string CpcaCsvRows(const CpcaStudy& d, int samples, const std::string& material) {
  // As the matrix rows (report_glossy_write.cpp): total_* the rendered radiance against the full
  // matrices, lobe_relative the glossy part's, sampling_relative the matrices' Frobenius error,
  // matrix_bytes the compressed bytes, seconds the compression.
  std::string s;
  for (const auto& r : d.rows)
    s += Formatted("shadowed,fibonacci,%d,%d,%d,%.6g,,,%.6g,%.6g,%.6g,%.6g,,", samples, samples, d.lmax, r.seconds,
                   r.frobenius, r.total.rms, r.total.max, r.total.relative) +
         material +
         Formatted(",glossy-cpca-%dx%d,%.6g,,%llu\n", r.clusters, r.terms, r.glossy.relative,
                   static_cast<unsigned long long>(r.bytes));
  return s;
}

}  // namespace prt
