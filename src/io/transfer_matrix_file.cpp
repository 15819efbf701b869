#include "io/transfer_matrix_file.h"

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
  out.reserve(out.size() + nv * (9 + t.channels * (n + n * n)) * sizeof(float));
  for (std::size_t v = 0; v < nv; ++v) {
    for (const glm::vec3* a : {&mesh.positions[v], &mesh.normals[v], &mesh.albedo[v]}) out.append(reinterpret_cast<const char*>(a), sizeof *a);
    out.append(reinterpret_cast<const char*>(t.coeffs.data() + v * t.channels * n), t.channels * n * sizeof(float));
    out.append(reinterpret_cast<const char*>(t.matrices.data() + v * t.channels * n * n), t.channels * n * n * sizeof(float));
  }
  WriteFileAtomic(path, out);
}

TransferMatrixFile ReadTransferMatrixFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot be read (expected a transfer_matrices.bin written by prt precompute)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto bad = [&path](const std::string& why) {
    return Error(path + ": " + why + " (expected a transfer_matrices.bin written by prt precompute)");
  };
  if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) throw bad("not a transfer matrix file");
  std::size_t at = sizeof kMagic;
  const auto version = Take<std::uint32_t>(bytes, at);
  if (version != kVersion) throw bad("format version " + std::to_string(version));
  TransferMatrixFile f;
  f.lmax = int(Take<std::uint32_t>(bytes, at));
  f.channels = int(Take<std::uint32_t>(bytes, at));
  f.exponent = int(Take<std::uint32_t>(bytes, at));
  const auto nv = Take<std::uint64_t>(bytes, at);
  f.ks = Take<double>(bytes, at);
  if (f.lmax < 0 || f.lmax > kMaxLmax || (f.channels != 1 && f.channels != 3) || nv > (1ULL << 32))
    throw bad("corrupt header");
  const std::uint64_t n = CoeffCount(f.lmax);
  const std::uint64_t per_vertex = (9 + f.channels * (n + n * n)) * sizeof(float);
  const std::uint64_t expected = kHeaderBytes + (f.lmax + 1) * sizeof(double) + nv * per_vertex;
  if (bytes.size() != expected)
    throw bad(std::to_string(bytes.size()) + " bytes where the header implies " + std::to_string(expected));
  f.lobe.resize(f.lmax + 1);
  for (double& h : f.lobe) h = Take<double>(bytes, at);
  f.positions.resize(nv), f.normals.resize(nv), f.albedo.resize(nv);
  f.transfer.resize(nv * f.channels * n);
  f.matrices.resize(nv * f.channels * n * n);
  for (std::uint64_t v = 0; v < nv; ++v) {
    f.positions[v] = Take<glm::vec3>(bytes, at);
    f.normals[v] = Take<glm::vec3>(bytes, at);
    f.albedo[v] = Take<glm::vec3>(bytes, at);
    std::memcpy(f.transfer.data() + v * f.channels * n, bytes.data() + at, f.channels * n * sizeof(float));
    at += f.channels * n * sizeof(float);
    std::memcpy(f.matrices.data() + v * f.channels * n * n, bytes.data() + at, f.channels * n * n * sizeof(float));
    at += f.channels * n * n * sizeof(float);
  }
  return f;
}

}  // namespace prt
