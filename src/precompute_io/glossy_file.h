#pragma once
/// \file
/// What the two files of a glossy material's matrices share (transfer_matrix_file.h and
/// cpca_matrix_file.h): the header and the start of every vertex's record, little-endian, no
/// padding.
///
///   char[8]  magic
///   u32      format version (1), lmax, channels (1 or 3), Phong exponent N
///   u64      vertex count V
///   u32      the file's own counts (none for transfer_matrices.bin; clusters and terms for
///            transfer_matrices_cpca.bin)
///   f64      KS, then the lobe's zonal coefficients h[lmax + 1]
///   per vertex, first: f32 position[3], normal[3], albedo[3], T[channels][n]
/// The reader checks the magic, the version and the counts above, each failure an Error that
/// names the file and what it expected.

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "core/error.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"

namespace prt {

/// The header of `transport`'s material for `vertices` vertices, with the file's own `counts`.
std::string GlossyHeaderBytes(const char (&magic)[8], const Transport& transport, std::uint64_t vertices,
                              const std::vector<std::uint32_t>& counts);

/// Appends vertex v's position, normal, albedo and diffuse transfer to `parts`, as views of the
/// mesh's and transport's own arrays (nothing is copied).
void AppendVertexStart(std::vector<std::string_view>& parts, const Mesh& mesh, const Transport& transport,
                       std::size_t v);

/// An open file of the family, read up to its first vertex record (the lobe only when the file
/// is at least that long: the caller's check of the whole size names a shorter one).
struct GlossyFileStart {
  std::ifstream in;
  std::uint64_t size = 0;            ///< the file's bytes
  std::uint64_t header_bytes = 0;    ///< up to the first vertex record
  int lmax = 0, channels = 1, exponent = 1;
  std::uint64_t vertices = 0;
  std::vector<std::uint32_t> counts;  ///< the file's own
  double ks = 0.0;
  std::vector<double> lobe;
  /// Error(path: why (expected `expected`)).
  Error Bad(const std::string& why) const;
  /// Reads `bytes` into `data` (the stream's state says whether it worked).
  void Read(void* data, std::size_t bytes);
  /// Reads vertex v's position, normal, albedo and transfer into their arrays (sized already).
  void ReadVertexStart(std::uint64_t v, std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                       std::vector<glm::vec3>& albedo, std::vector<float>& transfer);

  std::string path, expected;
};

/// Opens `path` and reads its header with `count_fields` counts of its own. Throws Error
/// ("cannot be read", "not a `kind`", "format version N", "corrupt header") naming the file and
/// `expected` (what it should have been).
GlossyFileStart OpenGlossyFile(const std::string& path, const char (&magic)[8], int count_fields, const std::string& kind,
                               const std::string& expected);

/// Bytes of one vertex record's start: position, normal, albedo and T.
std::uint64_t VertexStartBytes(int lmax, int channels);

}  // namespace prt
