#pragma once
/// \file
/// The shards of one farm job (precompute_io/transport_shard.h) checked and assembled into the
/// transport one run on one machine computes: every shard file of the basis's cache in a folder
/// must be whole, made by the same command for the same mesh and options (the same cache key),
/// and of one count N, with each index 0..N-1 present exactly once and their blocks covering
/// the mesh's vertices in order. A missing, damaged, renamed or foreign shard is refused with
/// its name and reason (Error) before anything is assembled.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "precompute/transport_types.h"

namespace prt {

struct AssembledShards {
  std::vector<std::string> command;  ///< the command every shard was made by, without --shard
  std::uint64_t key = 0;             ///< the whole run's cache key
  int count = 0;
  std::vector<std::string> files;    ///< the shard files, in index order
  Transport transport;               ///< every vertex's rows, as one run computes them
};

/// What every shard of a job records of itself, as its reader found it.
struct ShardIdentity {
  int index = 0;
  int count = 0;
  std::uint64_t key = 0;
  const std::vector<std::string>* command = nullptr;
  std::size_t vertices = 0;  ///< the whole mesh's
  VertexBlock block;
};

/// The checks every kind of shard set shares, fed the shards in index order: each holds the
/// index and count its name says, was made by shard 0's command with its key for its vertex
/// count, and its block starts where the one before ended; the last ends at the vertex count.
/// Each fault is an Error naming the file; `differs` names what else a foreign shard may differ
/// in ("mesh or options").
class ShardSetCheck {
 public:
  explicit ShardSetCheck(int count) : count_(count) {}
  /// Shard file `path`, named as shard `named` of the set; `same` false when a part of it other
  /// than the identity differs from shard 0 (its lmax, channels, ...).
  void Add(const std::string& path, int named, const ShardIdentity& s, const std::string& differs, bool same = true);
  /// After the last shard (`path`): its block ends at the vertex count.
  void Finish(const std::string& path) const;

  const std::vector<std::string>& command() const { return command_; }
  std::uint64_t key() const { return key_; }
  std::size_t vertices() const { return vertices_; }

 private:
  int count_;
  std::vector<std::string> command_;
  std::uint64_t key_ = 0;
  std::size_t vertices_ = 0;
  std::size_t next_ = 0;
};

/// The shard files of `cache_name` in `dir` by index: every one of a count N present once (Error
/// naming the folder and what is missing, or a second job's count, otherwise).
std::map<int, std::string> ShardFiles(const std::string& dir, const std::string& cache_name);

/// Assembles the shards of the cache `cache_name` in `dir`; Error when there are none or any
/// is refused.
AssembledShards AssembleShards(const std::string& dir, const std::string& cache_name);

}  // namespace prt
