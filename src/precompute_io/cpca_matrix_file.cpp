#include "precompute_io/cpca_matrix_file.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "precompute_io/glossy_file.h"
#include "sh/coeffs.h"

namespace prt {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'T', 'C', 'P', 'C', 'A', 'M'};

}  // namespace

void WriteCpcaMatrixFile(const std::string& path, const Mesh& mesh, const Transport& t, const CpcaTransfer& cpca) {
  const CpcaModel& m = cpca.model;
  const std::size_t n = CoeffCount(t.lmax), nv = mesh.vertex_count();
  if (!t.material.glossy || cpca.lmax != t.lmax || cpca.channels != t.channels || m.rows != nv * t.channels ||
      m.dim != int(n * n))
    throw Error(path + ": no compressed transfer matrices of this mesh to write (internal)");
  const std::string header =
      GlossyHeaderBytes(kMagic, t, nv, {std::uint32_t(m.clusters), std::uint32_t(m.terms)});
  std::vector<std::string_view> parts = {header};
  const auto piece = [&parts](const void* data, std::size_t bytes) {
    parts.emplace_back(static_cast<const char*>(data), bytes);
  };
  piece(m.means.data(), m.means.size() * sizeof(float));
  piece(m.principal.data(), m.principal.size() * sizeof(float));
  for (std::size_t v = 0; v < nv; ++v) {
    AppendVertexStart(parts, mesh, t, v);
    for (int c = 0; c < t.channels; ++c) {
      const std::size_t row = v * t.channels + c;
      piece(&m.cluster[row], sizeof(std::uint32_t));
      piece(m.weights.data() + row * m.terms, m.terms * sizeof(float));
    }
  }
  WriteFileAtomic(path, parts);
}

CpcaMatrixFile ReadCpcaMatrixFile(const std::string& path) {
  GlossyFileStart in = OpenGlossyFile(path, kMagic, 2, "compressed transfer matrix file",
                                      "a transfer_matrices_cpca.bin written by prt precompute --cpca");
  CpcaMatrixFile f;
  CpcaTransfer& t = f.cpca;
  CpcaModel& m = t.model;
  t.lmax = in.lmax, t.channels = in.channels, f.exponent = in.exponent, f.ks = in.ks;
  const std::uint64_t nv = in.vertices, clusters = in.counts[0], terms = in.counts[1];
  const std::uint64_t n = CoeffCount(t.lmax), dim = n * n, rows = nv * t.channels;
  if (clusters < 1 || clusters > rows || terms > dim) throw in.Bad("corrupt header (clusters or terms)");
  const std::uint64_t per_vertex = VertexStartBytes(t.lmax, t.channels) + t.channels * (4 + terms * sizeof(float));
  const std::uint64_t expected = in.header_bytes + clusters * (1 + terms) * dim * sizeof(float) + nv * per_vertex;
  if (in.size != expected)
    throw in.Bad(std::to_string(in.size) + " bytes where the header implies " + std::to_string(expected));
  f.lobe = in.lobe;
  t.vertices = nv;
  m.dim = int(dim), m.clusters = int(clusters), m.terms = int(terms), m.rows = rows;
  m.means.resize(clusters * dim);
  m.principal.resize(clusters * terms * dim);
  in.Read(m.means.data(), m.means.size() * sizeof(float));
  in.Read(m.principal.data(), m.principal.size() * sizeof(float));
  f.positions.resize(nv), f.normals.resize(nv), f.albedo.resize(nv);
  f.transfer.resize(nv * t.channels * n);
  m.cluster.resize(rows);
  m.weights.resize(rows * terms);
  for (std::uint64_t v = 0; v < nv && in.in; ++v) {
    in.ReadVertexStart(v, f.positions, f.normals, f.albedo, f.transfer);
    for (int c = 0; c < t.channels; ++c) {
      const std::uint64_t row = v * t.channels + c;
      in.Read(&m.cluster[row], sizeof(std::uint32_t));
      in.Read(m.weights.data() + row * terms, terms * sizeof(float));
      if (m.cluster[row] >= clusters)
        throw in.Bad("vertex " + std::to_string(v) + " names cluster " + std::to_string(m.cluster[row]) + " of " +
                     std::to_string(clusters));
    }
  }
  if (!in.in) throw in.Bad("read failed");
  return f;
}

}  // namespace prt
