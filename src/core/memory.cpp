#include "core/memory.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

#include "core/text.h"

namespace prt {

std::uint64_t MinorPageFaults() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<std::uint64_t>(usage.ru_minflt);
}


namespace {

/// The first number in `path`, if it holds one ("max" and missing files give nothing).
bool ReadNumber(const std::string& path, std::uint64_t& value) {
  std::ifstream in(path);
  return bool(in >> value);
}

/// What the process's memory control group still allows (cgroup v2, then v1); 0 if no limit.
std::uint64_t CgroupHeadroom() {
  std::uint64_t limit = 0, used = 0;
  if (ReadNumber("/sys/fs/cgroup/memory.max", limit) && ReadNumber("/sys/fs/cgroup/memory.current", used))
    return limit > used ? limit - used : 1;
  if (ReadNumber("/sys/fs/cgroup/memory/memory.limit_in_bytes", limit) && limit < (1ULL << 60) &&
      ReadNumber("/sys/fs/cgroup/memory/memory.usage_in_bytes", used))
    return limit > used ? limit - used : 1;
  return 0;
}

std::uint64_t SystemAvailable() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream fields(line.substr(13));
    std::uint64_t kib = 0;
    if (fields >> kib) return kib * 1024;
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  return pages > 0 && size > 0 ? std::uint64_t(pages) * std::uint64_t(size) : 0;
}

}  // namespace

std::uint64_t AvailableMemoryBytes() {
  const std::uint64_t system = SystemAvailable(), group = CgroupHeadroom();
  if (group == 0) return system;
  return system == 0 ? group : std::min(system, group);
}

std::string ByteText(std::uint64_t bytes) {
  const double b = double(bytes);
  if (b >= 1024.0 * 1024 * 1024) return Formatted("%.1f GiB", b / (1024.0 * 1024 * 1024));
  if (b >= 1024.0 * 1024) return Formatted("%.0f MiB", b / (1024.0 * 1024));
  return Formatted("%.0f KiB", b / 1024.0);
}

}  // namespace prt
