#include "core/log.h"

#include <atomic>
#include <cstdio>

namespace prt {
namespace {
std::atomic<bool> g_quiet{false};
}

double SecondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void SetQuiet(bool quiet) { g_quiet = quiet; }
bool IsQuiet() { return g_quiet; }

void Warn(const std::string& message) {
  if (!g_quiet) std::fprintf(stderr, "prt: warning: %s\n", message.c_str());
}

void Summary(const std::string& line) {
  if (!g_quiet) std::fprintf(stderr, "%s\n", line.c_str());
}

}  // namespace prt
