#include "precompute_io/transfer_matrix_file.h"

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "sh/coeffs.h"

namespace prt {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'T', 'M', 'A', 'T', 'R', 'X'};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 8 + 4 * 4 + 8 + 8;

template <class T>
void Put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
T Take(const std::string& in, std::size_t& at) {
  T value;
  std::memcpy(&value, in.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

}  // namespace

void WriteTransferMatrixFile(const std::string& path, const Mesh& mesh, const Transport& t) {
  if (!t.material.glossy || t.matrices.empty()) throw Error(path + ": no transfer matrices to write (internal)");
  const std::size_t n = CoeffCount(t.lmax), nv = mesh.vertex_count();
  std::string out(kMagic, sizeof kMagic);
  Put(out, kVersion);
  Put(out, std::uint32_t(t.lmax));
  Put(out, std::uint32_t(t.channels));
  Put(out, std::uint32_t(t.material.lobe.exponent));
  Put(out, std::uint64_t(nv));
  Put(out, t.material.ks);
  for (double h : t.material.lobe.ZonalCoefficients(t.lmax)) Put(out, h);
  // Each vertex's record in place, as pieces of the mesh's and transport's own arrays: nothing
  // as large as the matrices is copied.
  std::vector<std::string_view> parts = {out};
  parts.reserve(1 + 5 * nv);
  const auto piece = [&parts](const void* data, std::size_t bytes) {
    parts.emplace_back(static_cast<const char*>(data), bytes);
  };
  for (std::size_t v = 0; v < nv; ++v) {
    piece(&mesh.positions[v], sizeof(glm::vec3));
    piece(&mesh.normals[v], sizeof(glm::vec3));
    piece(&mesh.albedo[v], sizeof(glm::vec3));
    piece(t.coeffs.data() + v * t.channels * n, t.channels * n * sizeof(float));
    piece(t.matrices.data() + v * t.channels * n * n, t.channels * n * n * sizeof(float));
  }
  WriteFileAtomic(path, parts);
}

TransferMatrixFile ReadTransferMatrixFile(const std::string& path) {
  const auto bad = [&path](const std::string& why) {
    return Error(path + ": " + why + " (expected a transfer_matrices.bin written by prt precompute)");
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) throw bad("cannot be read");
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  // The header, then each array read straight into its place (no copy of the whole file).
  std::string header(kHeaderBytes, '\0');
  if (ec || size < kHeaderBytes || !in.read(header.data(), kHeaderBytes) ||
      std::memcmp(header.data(), kMagic, sizeof kMagic) != 0)
    throw bad("not a transfer matrix file");
  std::size_t at = sizeof kMagic;
  const auto version = Take<std::uint32_t>(header, at);
  if (version != kVersion) throw bad("format version " + std::to_string(version));
  TransferMatrixFile f;
  f.lmax = int(Take<std::uint32_t>(header, at));
  f.channels = int(Take<std::uint32_t>(header, at));
  f.exponent = int(Take<std::uint32_t>(header, at));
  const auto nv = Take<std::uint64_t>(header, at);
  f.ks = Take<double>(header, at);
  if (f.lmax < 0 || f.lmax > kMaxLmax || (f.channels != 1 && f.channels != 3) || nv > (1ULL << 32))
    throw bad("corrupt header");
  const std::uint64_t n = CoeffCount(f.lmax);
  const std::uint64_t per_vertex = (9 + f.channels * (n + n * n)) * sizeof(float);
  const std::uint64_t expected = kHeaderBytes + (f.lmax + 1) * sizeof(double) + nv * per_vertex;
  if (size != expected) throw bad(std::to_string(size) + " bytes where the header implies " + std::to_string(expected));
  const auto read = [&in](void* data, std::size_t bytes) { in.read(static_cast<char*>(data), std::streamsize(bytes)); };
  f.lobe.resize(f.lmax + 1);
  read(f.lobe.data(), f.lobe.size() * sizeof(double));
  f.positions.resize(nv), f.normals.resize(nv), f.albedo.resize(nv);
  f.transfer.resize(nv * f.channels * n);
  f.matrices.resize(nv * f.channels * n * n);
  for (std::uint64_t v = 0; v < nv && in; ++v) {
    read(&f.positions[v], sizeof(glm::vec3));
    read(&f.normals[v], sizeof(glm::vec3));
    read(&f.albedo[v], sizeof(glm::vec3));
    read(f.transfer.data() + v * f.channels * n, f.channels * n * sizeof(float));
    read(f.matrices.data() + v * f.channels * n * n, f.channels * n * n * sizeof(float));
  }
  if (!in) throw bad("read failed");
  return f;
}

}  // namespace prt
