#pragma once
/// \file
/// Where a basis's transport cache is read and written, and the one policy every basis follows
/// with it: read the cache when it was made from the same inputs, else compute and write it.
/// The cache is an optimisation: a path that cannot be used is a warning (naming the cause) and
/// the run goes on without it; a file of another basis is recognised and named, never read as
/// this one's.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "basis/basis.h"
#include "core/output_folder.h"

namespace prt {

struct CachePlan {
  std::string path;   ///< empty: no cache
  bool write = true;  ///< false: read if present, never written (folder not writable)
  /// Every basis whose cache files are recognised (and named when found in another's place).
  std::vector<const Basis*> bases;
};

/// The plan for the `--cache` value `option` ("" = the file `name` in `folder`: each basis has
/// its own, Basis::CacheName; "none" = no cache), checked before any work. A file there already
/// is replaced only when it is prt's: a cache of any of `bases`, however damaged, or a file prt
/// listed under that name.
CachePlan PlanCache(const std::string& option, OutputFolder* folder, const std::string& name,
                    const std::vector<const Basis*>& bases);

/// The steps of one basis's cached transport of type T.
template <class T>
struct CacheSteps {
  std::uint64_t key;        ///< the inputs' key
  std::uint64_t every_key;  ///< the key of the same transport with every vertex computed as a seen one
  /// Reads the cache at `path` made with `key`; nullopt with `why` set when it cannot.
  std::function<std::optional<T>(const std::string& path, std::uint64_t key, std::string& why)> read;
  /// Says on the run summary that `t` was taken from the cache (`every`: made with every vertex
  /// computed as a seen one, though fewer were asked for) and finishes it for use.
  std::function<void(T& t, bool every)> taken;
  std::function<T()> compute;  ///< computes it, said on the run summary
  std::function<void(const std::string& path, const T& t, std::uint64_t key)> write;
};

/// Why the file at `path` is another of `bases`' cache than `basis`'s ("a wavelet transport cache
/// (--basis wavelet), not an SH one"), or "".
std::string OtherBasisCache(const Basis& basis, const std::string& path, const std::vector<const Basis*>& bases);

/// Says "cache: PATH ignored (WHY), recomputed" unless there was none yet, and writes `t` with
/// `write`; a failed write is a warning.
void UpdateCache(const CachePlan& cache, const std::string& why, const std::function<void()>& write);

/// The transport: read from the cache when that file was made from the same inputs (or from
/// every vertex computed as a seen one, which holds at least what fewer need), else computed
/// and written there when the plan allows.
template <class T>
T CachedOrComputed(const Basis& basis, const CachePlan& cache, const CacheSteps<T>& s) {
  std::string why;
  if (!cache.path.empty()) why = OtherBasisCache(basis, cache.path, cache.bases);
  if (!cache.path.empty() && why.empty()) {
    if (auto cached = s.read(cache.path, s.key, why)) {
      s.taken(*cached, false);
      return std::move(*cached);
    }
    std::string ignored;
    if (s.every_key != s.key) {
      if (auto cached = s.read(cache.path, s.every_key, ignored)) {
        s.taken(*cached, true);
        return std::move(*cached);
      }
    }
  }
  T t = s.compute();
  if (!cache.path.empty() && cache.write) UpdateCache(cache, why, [&] { s.write(cache.path, t, s.key); });
  return t;
}

}  // namespace prt
