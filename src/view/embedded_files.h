#pragma once
/// \file
/// The files of src/view/page/ as the build embedded them (scripts/embed-files.cmake writes
/// their definition into the build folder): prt view serves them from memory, never from disk.

#include <cstddef>

namespace prt::embedded {

struct File {
  const char* name;            ///< its path under src/view/page/
  const unsigned char* bytes;  ///< its bytes, followed by a 0 that size does not count
  std::size_t size;
};

extern const File kFiles[];
extern const std::size_t kFileCount;

}  // namespace prt::embedded
