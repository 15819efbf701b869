#include "precompute_io/glossy_file.h"

#include <cstring>
#include <filesystem>

#include "core/error.h"
#include "sh/coeffs.h"

namespace prt {
namespace {

constexpr std::uint32_t kVersion = 1;

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

std::string GlossyHeaderBytes(const char (&magic)[8], const Transport& t, std::uint64_t vertices,
                              const std::vector<std::uint32_t>& counts) {
  std::string out(magic, sizeof magic);
  Put(out, kVersion);
  Put(out, std::uint32_t(t.lmax));
  Put(out, std::uint32_t(t.channels));
  Put(out, std::uint32_t(t.material.lobe.exponent));
  Put(out, vertices);
  for (std::uint32_t c : counts) Put(out, c);
  Put(out, t.material.ks);
  for (double h : t.material.lobe.ZonalCoefficients(t.lmax)) Put(out, h);
  return out;
}

void AppendVertexStart(std::vector<std::string_view>& parts, const Mesh& mesh, const Transport& t, std::size_t v) {
  const std::size_t n = CoeffCount(t.lmax);
  const auto piece = [&parts](const void* data, std::size_t bytes) {
    parts.emplace_back(static_cast<const char*>(data), bytes);
  };
  piece(&mesh.positions[v], sizeof(glm::vec3));
  piece(&mesh.normals[v], sizeof(glm::vec3));
  piece(&mesh.albedo[v], sizeof(glm::vec3));
  piece(t.coeffs.data() + v * t.channels * n, t.channels * n * sizeof(float));
}

std::uint64_t VertexStartBytes(int lmax, int channels) {
  return (9 + std::uint64_t(channels) * CoeffCount(lmax)) * sizeof(float);
}

Error GlossyFileStart::Bad(const std::string& why) const { return Error(path + ": " + why + " (expected " + expected + ")"); }

void GlossyFileStart::Read(void* data, std::size_t bytes) { in.read(static_cast<char*>(data), std::streamsize(bytes)); }

void GlossyFileStart::ReadVertexStart(std::uint64_t v, std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                                      std::vector<glm::vec3>& albedo, std::vector<float>& transfer) {
  const std::uint64_t n = CoeffCount(lmax);
  Read(&positions[v], sizeof(glm::vec3));
  Read(&normals[v], sizeof(glm::vec3));
  Read(&albedo[v], sizeof(glm::vec3));
  Read(transfer.data() + v * channels * n, channels * n * sizeof(float));
}

GlossyFileStart OpenGlossyFile(const std::string& path, const char (&magic)[8], int count_fields, const std::string& kind,
                               const std::string& expected) {
  GlossyFileStart f;
  f.path = path;
  f.expected = expected;
  f.in.open(path, std::ios::binary);
  if (!f.in) throw f.Bad("cannot be read");
  std::error_code ec;
  f.size = std::filesystem::file_size(path, ec);
  // The fixed part of the header, then the lobe straight into its place.
  const std::size_t fixed = 8 + 4 * 4 + 8 + 4 * std::size_t(count_fields) + 8;
  std::string header(fixed, '\0');
  if (ec || f.size < fixed || !f.in.read(header.data(), std::streamsize(fixed)) ||
      std::memcmp(header.data(), magic, sizeof magic) != 0)
    throw f.Bad("not a " + kind);
  std::size_t at = sizeof magic;
  const auto version = Take<std::uint32_t>(header, at);
  if (version != kVersion) throw f.Bad("format version " + std::to_string(version));
  f.lmax = int(Take<std::uint32_t>(header, at));
  f.channels = int(Take<std::uint32_t>(header, at));
  f.exponent = int(Take<std::uint32_t>(header, at));
  f.vertices = Take<std::uint64_t>(header, at);
  for (int i = 0; i < count_fields; ++i) f.counts.push_back(Take<std::uint32_t>(header, at));
  f.ks = Take<double>(header, at);
  if (f.lmax < 0 || f.lmax > kMaxLmax || (f.channels != 1 && f.channels != 3) || f.vertices > (1ULL << 32))
    throw f.Bad("corrupt header");
  f.header_bytes = fixed + (std::uint64_t(f.lmax) + 1) * sizeof(double);
  // A shorter file is left for the caller's size check, which names both sizes.
  f.lobe.resize(std::size_t(f.lmax) + 1);
  if (f.size >= f.header_bytes) f.Read(f.lobe.data(), f.lobe.size() * sizeof(double));
  return f;
}

}  // namespace prt
