#include "basis/cache_plan.h"

#include <filesystem>

#include <unistd.h>

#include "core/atomic_file.h"  // WriteProblem
#include "core/error.h"
#include "core/log.h"

namespace prt {

CachePlan PlanCache(const std::string& option, OutputFolder* folder, const std::string& name,
                    const std::vector<const Basis*>& bases) {
  namespace fs = std::filesystem;
  if (option == "none") return {"", false, bases};
  const bool given = !option.empty();
  if (!given && !folder) return {"", false, bases};
  const std::string path = given ? option : folder->dir() + "/" + name;
  const std::string what = (given ? "--cache: " : "cache: ") + path + ": ";
  const auto skip = [&](const std::string& why) {
    Warn(what + why + "; going on without the cache");
    return CachePlan{"", false, bases};
  };
  std::error_code ec;
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  if (fs::is_directory(path, ec)) return skip("is a folder (expected a file name)");
  if (!fs::exists(dir, ec)) return skip("folder '" + dir.string() + "' does not exist");
  if (!fs::is_directory(dir, ec)) return skip("'" + dir.string() + "' is a file, not a folder");
  // What is there already is replaced only when it is prt's: a cache (however damaged) at any
  // path, anything prt listed at the output folder's own cache name; an empty --cache file.
  // Never a device, pipe or socket, never another file (a typo must not cost the user a file).
  const fs::file_status link = fs::symlink_status(path, ec);
  if (fs::exists(link)) {
    if (!fs::is_regular_file(fs::status(path, ec))) return skip("is not a regular file: left alone");
    // In the output folder, a file prt listed as its own may be replaced whatever it holds, an
    // unlisted one only if it is a cache; a --cache file if it is a cache or empty.
    const bool listed = !given && !folder->IsForeign(name);
    bool cache = false;
    for (const Basis* b : bases) cache = cache || b->IsOwnCache(path);
    if (!listed && (!given || fs::file_size(path, ec) > 0) && !cache)
      return skip("exists and is not a prt transport cache: left as it is");
    if (fs::is_symlink(link)) {
      Warn(what + "is a symbolic link: the cache is read if it matches, but never replaced");
      return {path, false, bases};
    }
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    Warn(what + WriteProblem(path, errno) + ": the cache is read if it matches, but not updated");
    return {path, false, bases};
  }
  return {given ? path : folder->OutputInPlace(name), true, bases};
}

std::string OtherBasisCache(const Basis& basis, const std::string& path, const std::vector<const Basis*>& bases) {
  if (basis.IsOwnCache(path)) return "";
  for (const Basis* other : bases)
    if (other != &basis && other->IsOwnCache(path))
      return other->Noun() + " transport cache (--basis " + other->Name() + "), not " + basis.Noun() + " one";
  return "";
}

void UpdateCache(const CachePlan& cache, const std::string& why, const std::function<void()>& write) {
  if (why != "no cache yet") Summary("cache: " + cache.path + " ignored (" + why + "), recomputed");
  try {
    write();
  } catch (const Error& e) {
    Warn(std::string(e.what()) + "; the transport was computed but not cached");
  }
}

}  // namespace prt
