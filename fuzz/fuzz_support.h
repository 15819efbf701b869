#pragma once
/// \file
/// Shared by the fuzz targets: the loaders read files by path, so each input is written to a
/// temporary file (one per process, reused) with the extension that selects the decoder.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace prt::fuzz {

/// Writes `data` to /tmp/prt_fuzz_<pid><suffix> and returns the path.
inline std::string WriteInput(const std::uint8_t* data, std::size_t size, const std::string& suffix) {
  const std::string path = "/tmp/prt_fuzz_" + std::to_string(::getpid()) + suffix;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return path;
  if (size > 0) std::fwrite(data, 1, size, f);
  std::fclose(f);
  return path;
}

}  // namespace prt::fuzz
