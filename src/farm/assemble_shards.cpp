#include "farm/assemble_shards.h"

#include <filesystem>
#include <map>
#include <optional>

#include "core/error.h"
#include "precompute_io/transport_shard.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

/// The indices of 0..count-1 not in `found`, as "3, 7" (at most 10 named).
std::string Missing(const std::map<int, std::string>& found, int count) {
  std::string list;
  int named = 0, missing = 0;
  for (int i = 0; i < count; ++i) {
    if (found.count(i)) continue;
    ++missing;
    if (named < 10) list += (named++ ? ", " : "") + std::to_string(i);
  }
  if (missing > named) list += " and " + std::to_string(missing - named) + " more";
  return list;
}

void Append(std::vector<float>& all, const std::vector<float>& rows) { all.insert(all.end(), rows.begin(), rows.end()); }

}  // namespace

std::map<int, std::string> ShardFiles(const std::string& dir, const std::string& cache_name) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error(dir + ": no such folder (expected the --out DIR the shards were written to)");
  // The shard files by index, and their count as named.
  std::map<int, std::string> named;
  std::optional<int> count;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    int index = 0, n = 0;
    const std::string name = entry.path().filename().string();
    if (!IsShardFileName(name, cache_name, index, n)) continue;
    if (count && *count != n)
      throw Error(dir + "/" + name + ": a shard of " + std::to_string(n) + ", beside shards of " + std::to_string(*count) +
                  " (expected the shards of one job: remove the other job's)");
    count = n;
    named[index] = entry.path().string();
  }
  if (ec) throw Error(dir + ": cannot be listed (" + ec.message() + ")");
  if (!count)
    throw Error(dir + ": no shards of " + cache_name + " (expected files " + cache_name +
                ".shard-IIIII-of-NNNNN, written by prt precompute, render or reference --shard I/N --out " + dir + ")");
  if (int(named.size()) != *count || named.rbegin()->first >= *count)
    throw Error(dir + ": shard" + (*count - int(named.size()) > 1 ? "s " : " ") + Missing(named, *count) + " of " +
                std::to_string(*count) + " missing (expected every shard 0.." + std::to_string(*count - 1) +
                "; run the missing tasks again)");
  return named;
}

void ShardSetCheck::Add(const std::string& path, int named, const ShardIdentity& s, const std::string& differs,
                        bool same) {
  if (s.index != named || s.count != count_)
    throw Error(path + ": holds shard " + std::to_string(s.index) + " of " + std::to_string(s.count) +
                ", not the one its name says (expected the file as prt named it)");
  if (named == 0) {
    command_ = *s.command;
    key_ = s.key;
    vertices_ = s.vertices;
  } else if (*s.command != command_ || s.key != key_ || s.vertices != vertices_ || !same) {
    throw Error(path + ": made " + (*s.command != command_ ? "by another command" : "from another " + differs) +
                " than shard 0 (expected the shards of one job: remove the foreign one and run its task again)");
  }
  if (s.block.begin != next_)
    throw Error(path + ": its vertices start at " + std::to_string(s.block.begin) + ", not " + std::to_string(next_) +
                " where the shard before it ends (corrupted)");
  next_ = s.block.end;
}

void ShardSetCheck::Finish(const std::string& path) const {
  if (next_ != vertices_)
    throw Error(path + ": its vertices end at " + std::to_string(next_) + ", not at the mesh's " +
                std::to_string(vertices_) + " (corrupted)");
}

AssembledShards AssembleShards(const std::string& dir, const std::string& cache_name) {
  const std::map<int, std::string> named = ShardFiles(dir, cache_name);
  AssembledShards out;
  out.count = int(named.size());
  ShardSetCheck check(out.count);
  for (const auto& [index, path] : named) {
    std::string why;
    std::optional<TransportShard> s = ReadTransportShard(path, why);
    if (!s) throw Error(path + ": " + why + " (expected a whole shard: run task " + std::to_string(index) + " again)");
    const bool same = index == 0 || (s->rows.lmax == out.transport.lmax && s->rows.channels == out.transport.channels);
    check.Add(path, index, {s->index, s->count, s->key, &s->command, s->rows.vertices, s->block}, "mesh or options", same);
    if (index == 0) {
      out.transport.lmax = s->rows.lmax;
      out.transport.channels = s->rows.channels;
      out.transport.vertices = s->rows.vertices;
    } else if (s->rows.glossy.empty() != out.transport.glossy.empty() ||
               s->rows.matrices.empty() != out.transport.matrices.empty()) {
      throw Error(path + ": holds other parts than shard 0 (corrupted)");
    }
    Append(out.transport.coeffs, s->rows.coeffs);
    Append(out.transport.glossy, s->rows.glossy);
    Append(out.transport.matrices, s->rows.matrices);
    out.files.push_back(path);
  }
  check.Finish(named.rbegin()->second);
  out.command = check.command();
  out.key = check.key();
  return out;
}

}  // namespace prt
