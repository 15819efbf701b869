// Fuzzes the image and environment loaders: the first byte picks the extension (png, jpg, hdr,
// exr), the rest is the file. Any bytes give an environment or an Error. Headers claiming
// images above 2048x2048 are checked (ImageSize) but not decoded, to keep each run small: the
// size limits themselves are covered by tests/app/test_bad_input.cpp.
#include "core/error.h"
#include "env/load_environment.h"
#include "fuzz/fuzz_support.h"
#include "io/image_load.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".png", ".jpg", ".hdr", ".exr"};
  const std::string path = prt::fuzz::WriteInput(data + 1, size - 1, kExtensions[data[0] % 4]);
  try {
    int w = 0, h = 0;
    prt::ImageSize(path, w, h);
    if (static_cast<long long>(w) * h > 2048LL * 2048) return 0;
    prt::LoadEnvironment(path, prt::CubeLayout::kStandard);
  } catch (const prt::Error&) {
  }
  return 0;
}
