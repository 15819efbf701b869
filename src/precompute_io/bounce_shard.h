#pragma once
/// \file
/// The files of interreflected transport computed as a farm job in stages
/// (precompute/bounce_stages.h):
///
/// - A bounce shard: one block's rows of one stage, in double precision (what the next stage
///   gathers from, as the one-machine run keeps it). Named `<cache>.bounce-K.shard-IIIII-of-NNNNN`.
///   Beside stage 0's, a file of the block's hits on the lit side of a surface (the others send
///   no light), which every later stage of the block reads again and no merge reads:
///   `<cache>.hits.shard-IIIII-of-NNNNN`.
/// - The bounce state: what the merges have assembled so far, every vertex's last bounce and the
///   sum of the bounces, with the direct energy and whether the bounces stopped. Named
///   `<cache>.bounces`.
///
/// Both carry the whole run's cache key and the command that made them, are checksummed (FNV-1a's
/// step over 8-byte words) and written to a temporary name renamed when whole (core/atomic_file.h).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "precompute/hit_light.h"
#include "precompute/transport_types.h"

namespace prt {

struct BounceShard {
  int index = 0, count = 1, stage = 0;
  std::uint64_t key = 0;
  std::vector<std::string> command;
  VertexBlock block;
  std::uint64_t vertices = 0;            ///< the bounce mesh's vertex count
  int channels = 1, coefficients = 1;    ///< the bounces' channels (bounce_stages.h) and coefficients
  int bounces = 1;                       ///< --bounces
  double tolerance = 0.0;                ///< the share of the direct energy below which they stop
  std::uint64_t own = 0;                 ///< the output's vertices, first of the bounce mesh's
  std::uint64_t front_hits = 0;          ///< stage 0: the block's front hits among the output's vertices
  /// The block's rows: stage 0 the direct transfer (coefficients a vertex), stage k bounce k
  /// (channels x coefficients a vertex).
  std::vector<double> rows;
  std::vector<std::vector<VertexHit>> hits;  ///< stage 0: each of the block's vertices' hits
};

/// `<cache_name>.bounce-K`: the name whose shard files (ShardFileName) stage K's are.
std::string BounceStageName(const std::string& cache_name, int stage);
/// `<cache_name>.hits`: the name whose shard files hold each block's hits (stage kHitsStage),
/// beside stage 0's rows: only the block's own later stages read them, never a merge.
std::string BounceHitsName(const std::string& cache_name);
/// The stage number of a hits file: its rows are empty, its hits the block's.
inline constexpr int kHitsStage = -1;

void WriteBounceShard(const std::string& path, const BounceShard& shard);
std::optional<BounceShard> ReadBounceShard(const std::string& path, std::string& why);

struct BounceState {
  std::uint64_t key = 0;
  std::vector<std::string> command;
  int shards = 0;              ///< the job's shard count, the same at every stage
  int bounces = 0;             ///< --bounces: the job's last stage
  int stage = 0;               ///< the last stage assembled (0: the direct pass)
  bool done = false;           ///< no more bounces: the last, or stopped early
  std::string stop;            ///< why the bounces ended, for the summary
  int channels = 1, coefficients = 1;
  std::uint64_t vertices = 0, own = 0;
  double direct_energy = 0.0;
  std::vector<double> current;   ///< bounce `stage` of every vertex
  std::vector<double> transfer;  ///< the direct transfer and every bounce through `stage`
};

/// `<cache_name>.bounces`.
std::string BounceStateName(const std::string& cache_name);
void WriteBounceState(const std::string& path, const BounceState& state);
std::optional<BounceState> ReadBounceState(const std::string& path, std::string& why);
/// The bounce state at `path`, nullopt when there is none; Error naming it when it is damaged.
std::optional<BounceState> LoadBounceState(const std::string& path);

}  // namespace prt
