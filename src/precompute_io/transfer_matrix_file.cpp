#include "precompute_io/transfer_matrix_file.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "precompute_io/glossy_file.h"
#include "sh/coeffs.h"

namespace prt {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'T', 'M', 'A', 'T', 'R', 'X'};

}  // namespace

void WriteTransferMatrixFile(const std::string& path, const Mesh& mesh, const Transport& t) {
  if (!t.material.glossy || t.matrices.empty()) throw Error(path + ": no transfer matrices to write (internal)");
  const std::size_t n = CoeffCount(t.lmax), nv = mesh.vertex_count();
  const std::string header = GlossyHeaderBytes(kMagic, t, nv, {});
  // Each vertex's record in place, as pieces of the mesh's and transport's own arrays: nothing
  // as large as the matrices is copied.
  std::vector<std::string_view> parts = {header};
  parts.reserve(1 + 5 * nv);
  for (std::size_t v = 0; v < nv; ++v) {
    AppendVertexStart(parts, mesh, t, v);
    parts.emplace_back(reinterpret_cast<const char*>(t.matrices.data() + v * t.channels * n * n),
                       t.channels * n * n * sizeof(float));
  }
  WriteFileAtomic(path, parts);
}

TransferMatrixFile ReadTransferMatrixFile(const std::string& path) {
  // The header, then each array read straight into its place (no copy of the whole file).
  GlossyFileStart in =
      OpenGlossyFile(path, kMagic, 0, "transfer matrix file", "a transfer_matrices.bin written by prt precompute");
  TransferMatrixFile f;
  f.lmax = in.lmax, f.channels = in.channels, f.exponent = in.exponent, f.ks = in.ks;
  const std::uint64_t n = CoeffCount(f.lmax), nv = in.vertices;
  const std::uint64_t per_vertex = VertexStartBytes(f.lmax, f.channels) + f.channels * n * n * sizeof(float);
  const std::uint64_t expected = in.header_bytes + nv * per_vertex;
  if (in.size != expected)
    throw in.Bad(std::to_string(in.size) + " bytes where the header implies " + std::to_string(expected));
  f.lobe = in.lobe;
  f.positions.resize(nv), f.normals.resize(nv), f.albedo.resize(nv);
  f.transfer.resize(nv * f.channels * n);
  f.matrices.resize(nv * f.channels * n * n);
  for (std::uint64_t v = 0; v < nv && in.in; ++v) {
    in.ReadVertexStart(v, f.positions, f.normals, f.albedo, f.transfer);
    in.Read(f.matrices.data() + v * f.channels * n * n, f.channels * n * n * sizeof(float));
  }
  if (!in.in) throw in.Bad("read failed");
  return f;
}

}  // namespace prt
