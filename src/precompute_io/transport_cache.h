#pragma once
/// \file
/// The binary transport cache: lets `render` skip the precompute when nothing it depends on
/// has changed. Never trusted: a file that is truncated, corrupted, from another format
/// version or made from other inputs is ignored with a note, and the transport recomputed.
///
/// Layout (little-endian):
///   "PRTCACHE"  8 bytes magic
///   u32 format version (2), u32 lmax, u32 channels, u32 parts (1: G follows, 2: matrices follow)
///   u64 vertex count, u64 key (hash of every input, see TransportKey), u64 payload checksum
///   float T[vertices * channels * n], n = (lmax+1)^2; then (parts & 1) float G[the same count];
///   then (parts & 2) float M[vertices * channels * n * n]
/// Written to a temporary name and renamed (core/atomic_file.h).

#include <cstdint>
#include <optional>
#include <string>

#include "geometry/mesh.h"
#include "precompute/transport.h"

namespace prt {

/// Hash of everything the transport depends on: the mesh's positions, normals, albedo and
/// triangles, and every option of `options` (a glossy material's eye included).
std::uint64_t TransportKey(const Mesh& mesh, const TransportOptions& options);

/// Writes `transport` with `key` to `path` atomically. Throws Error if it cannot.
void WriteTransportCache(const std::string& path, const Transport& transport, std::uint64_t key);

/// True if the file at `path` starts as every prt transport cache does (its 8-byte magic), however
/// damaged the rest; false for other files and for paths that cannot be read.
bool StartsLikeTransportCache(const std::string& path);

/// Reads the cache at `path` if it is intact and was made with `key`; otherwise returns
/// nothing and sets `why` to the reason ("no cache yet", "checksum mismatch", ...).
std::optional<Transport> ReadTransportCache(const std::string& path, std::uint64_t key, std::string& why);

}  // namespace prt
