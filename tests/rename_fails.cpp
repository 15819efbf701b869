// A stand-in for the C library's rename(), preloaded into prt (LD_PRELOAD) by the tests of a
// failing rename: it fails with EACCES when it moves a file out of prt's staging folder to a
// destination that ends with $PRT_FAIL_RENAME_TO, and renames as usual otherwise. So the last step
// of a run, moving an output from staging into place, can be made to fail while every other
// rename (the user's file kept as .orig and put back) goes through.
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <dlfcn.h>

extern "C" int rename(const char* from, const char* to) {
  using Rename = int (*)(const char*, const char*);
  static const Rename real = reinterpret_cast<Rename>(::dlsym(RTLD_NEXT, "rename"));
  const char* suffix = std::getenv("PRT_FAIL_RENAME_TO");
  if (suffix && *suffix && std::strstr(from, "/.prt-staging/") && !std::strstr(to, "/.prt-staging/")) {
    const std::size_t n = std::strlen(to), m = std::strlen(suffix);
    if (n >= m && std::strcmp(to + n - m, suffix) == 0) {
      errno = EACCES;
      return -1;
    }
  }
  return real(from, to);
}
