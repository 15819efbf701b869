#include "precompute_io/cpca_matrix_file.h"

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "sh/coeffs.h"

namespace prt {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'T', 'C', 'P', 'C', 'A', 'M'};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 8 + 4 * 4 + 8 + 4 * 2 + 8;

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

void WriteCpcaMatrixFile(const std::string& path, const Mesh& mesh, const Transport& t, const CpcaTransfer& cpca) {
  const CpcaModel& m = cpca.model;
  const std::size_t n = CoeffCount(t.lmax), nv = mesh.vertex_count();
  if (!t.material.glossy || cpca.lmax != t.lmax || cpca.channels != t.channels || m.rows != nv * t.channels ||
      m.dim != int(n * n))
    throw Error(path + ": no compressed transfer matrices of this mesh to write (internal)");
  std::string out(kMagic, sizeof kMagic);
  Put(out, kVersion);
  Put(out, std::uint32_t(t.lmax));
  Put(out, std::uint32_t(t.channels));
  Put(out, std::uint32_t(t.material.lobe.exponent));
  Put(out, std::uint64_t(nv));
  Put(out, std::uint32_t(m.clusters));
  Put(out, std::uint32_t(m.terms));
  Put(out, t.material.ks);
  for (double h : t.material.lobe.ZonalCoefficients(t.lmax)) Put(out, h);
  std::vector<std::string_view> parts = {out};
  const auto piece = [&parts](const void* data, std::size_t bytes) {
    parts.emplace_back(static_cast<const char*>(data), bytes);
  };
  piece(m.means.data(), m.means.size() * sizeof(float));
  piece(m.principal.data(), m.principal.size() * sizeof(float));
  for (std::size_t v = 0; v < nv; ++v) {
    piece(&mesh.positions[v], sizeof(glm::vec3));
    piece(&mesh.normals[v], sizeof(glm::vec3));
    piece(&mesh.albedo[v], sizeof(glm::vec3));
    piece(t.coeffs.data() + v * t.channels * n, t.channels * n * sizeof(float));
    for (int c = 0; c < t.channels; ++c) {
      const std::size_t row = v * t.channels + c;
      piece(&m.cluster[row], sizeof(std::uint32_t));
      piece(m.weights.data() + row * m.terms, m.terms * sizeof(float));
    }
  }
  WriteFileAtomic(path, parts);
}

CpcaMatrixFile ReadCpcaMatrixFile(const std::string& path) {
  const auto bad = [&path](const std::string& why) {
    return Error(path + ": " + why + " (expected a transfer_matrices_cpca.bin written by prt precompute --cpca)");
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) throw bad("cannot be read");
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  std::string header(kHeaderBytes, '\0');
  if (ec || size < kHeaderBytes || !in.read(header.data(), kHeaderBytes) ||
      std::memcmp(header.data(), kMagic, sizeof kMagic) != 0)
    throw bad("not a compressed transfer matrix file");
  std::size_t at = sizeof kMagic;
  const auto version = Take<std::uint32_t>(header, at);
  if (version != kVersion) throw bad("format version " + std::to_string(version));
  CpcaMatrixFile f;
  CpcaTransfer& t = f.cpca;
  CpcaModel& m = t.model;
  t.lmax = int(Take<std::uint32_t>(header, at));
  t.channels = int(Take<std::uint32_t>(header, at));
  f.exponent = int(Take<std::uint32_t>(header, at));
  const auto nv = Take<std::uint64_t>(header, at);
  const auto clusters = Take<std::uint32_t>(header, at), terms = Take<std::uint32_t>(header, at);
  f.ks = Take<double>(header, at);
  if (t.lmax < 0 || t.lmax > kMaxLmax || (t.channels != 1 && t.channels != 3) || nv > (1ULL << 32))
    throw bad("corrupt header");
  const std::uint64_t n = CoeffCount(t.lmax), dim = n * n, rows = nv * t.channels;
  if (clusters < 1 || clusters > rows || terms > dim) throw bad("corrupt header (clusters or terms)");
  const std::uint64_t per_vertex = (9 + t.channels * n) * sizeof(float) + t.channels * (4 + terms * sizeof(float));
  const std::uint64_t expected =
      kHeaderBytes + (t.lmax + 1) * sizeof(double) + clusters * (1 + terms) * dim * sizeof(float) + nv * per_vertex;
  if (size != expected) throw bad(std::to_string(size) + " bytes where the header implies " + std::to_string(expected));
  const auto read = [&in](void* data, std::size_t bytes) { in.read(static_cast<char*>(data), std::streamsize(bytes)); };
  t.vertices = nv;
  m.dim = int(dim), m.clusters = int(clusters), m.terms = int(terms), m.rows = rows;
  f.lobe.resize(t.lmax + 1);
  read(f.lobe.data(), f.lobe.size() * sizeof(double));
  m.means.resize(clusters * dim);
  m.principal.resize(clusters * terms * dim);
  read(m.means.data(), m.means.size() * sizeof(float));
  read(m.principal.data(), m.principal.size() * sizeof(float));
  f.positions.resize(nv), f.normals.resize(nv), f.albedo.resize(nv);
  f.transfer.resize(nv * t.channels * n);
  m.cluster.resize(rows);
  m.weights.resize(rows * terms);
  for (std::uint64_t v = 0; v < nv && in; ++v) {
    read(&f.positions[v], sizeof(glm::vec3));
    read(&f.normals[v], sizeof(glm::vec3));
    read(&f.albedo[v], sizeof(glm::vec3));
    read(f.transfer.data() + v * t.channels * n, t.channels * n * sizeof(float));
    for (int c = 0; c < t.channels; ++c) {
      const std::uint64_t row = v * t.channels + c;
      read(&m.cluster[row], sizeof(std::uint32_t));
      read(m.weights.data() + row * terms, terms * sizeof(float));
      if (m.cluster[row] >= clusters) throw bad("vertex " + std::to_string(v) + " names cluster " +
                                                std::to_string(m.cluster[row]) + " of " + std::to_string(clusters));
    }
  }
  if (!in) throw bad("read failed");
  return f;
}

}  // namespace prt
