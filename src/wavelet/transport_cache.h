#pragma once
/// \file
/// The binary cache of the wavelet transport (wavelet/transport.h), beside the SH one
/// (precompute_io/transport_cache.h) and under the same rules: `render --basis wavelet` skips
/// the precompute when nothing the transport depends on has changed, and never trusts the file:
/// one that is truncated, corrupted, of another format version, made from other inputs, or the
/// SH basis's cache is ignored with its reason, and the transport recomputed.
///
/// Layout (little-endian), a header of 96 bytes and then the arrays of WaveletTransport:
///   "PRTWAVEL"  8 bytes magic (the SH cache's is "PRTCACHE": neither reader takes the other's)
///   u32 format version (1), u32 face size F, i32 base_lmax (-1: no SH base),
///   i32 bounce lmax, u32 bounce channels, u32 probe count P,
///   u64 vertex count V, u64 kept details D (= offsets[V]), u64 bounce vertices B (0: no
///   bounces, else V), u64 key (WaveletTransportKey), u64 checksum (FNV-1a of the header with
///   this field 0, then of the arrays: a byte changed anywhere is refused),
///   f64 kept_energy, f64 seconds (the first computation's), u64 rays;
/// then
///   float base[V (base_lmax + 1)^2], float means[6 V], float scale[V], u64 offsets[V + 1],
///   u16 index[D], i16 value[D], float bounce[B channels (lmax + 1)^2],
///   u32 probes[P], float probe_coeffs[P 6 F^2].
/// Written to a temporary name and renamed (core/atomic_file.h).

#include <cstdint>
#include <optional>
#include <string>

#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "wavelet/options.h"
#include "wavelet/transport.h"

namespace prt {

/// Hash of everything the wavelet transport depends on: all that the SH key covers
/// (TransportKey: the mesh, its textures, every transport option the bounces read, prt's
/// version), which vertices no frame shows when some are hidden (they take one ray a texel),
/// the options that shape the stored coefficients (face size, budget, split, selection,
/// base_lmax) and the format version. Not --light-terms: a frame's light, not the transport.
std::uint64_t WaveletTransportKey(const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& options);

/// Writes `transport` with `key` to `path` atomically. Throws Error if it cannot, or if the
/// transport's arrays disagree with its counts (internal).
void WriteWaveletCache(const std::string& path, const WaveletTransport& transport, std::uint64_t key);

/// True if the file at `path` starts as every wavelet transport cache does (its 8-byte magic),
/// however damaged the rest; false for other files and for paths that cannot be read.
bool StartsLikeWaveletCache(const std::string& path);

/// Reads the cache at `path` if it is intact and was made with `key`; otherwise returns nothing
/// and sets `why` to the reason ("no cache yet", "made from other inputs", "an SH transport
/// cache (--basis sh), not a wavelet one", "checksum mismatch (corrupted)", ...).
std::optional<WaveletTransport> ReadWaveletCache(const std::string& path, std::uint64_t key, std::string& why);

}  // namespace prt
