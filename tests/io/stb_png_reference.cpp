// The reference the tests hold prt's PNG encoder (io/png_encoder.h) to: stb_image_write's PNG
// writer (Debian's libstb) with zlib's compress2 as its compressor and the "sub" filter forced,
// the path prt's frames were written by before it had its own encoder. Compiled here from the
// header, with internal linkage.
#include "tests/io/stb_png_reference.h"

#include <cstdlib>

#include <zlib.h>

namespace {

thread_local int t_level = 2;  // the level of this thread's current encoding

/// stb's compressor hook: the zlib stream of `data`, in a buffer stb releases with free().
unsigned char* ZlibCompress(unsigned char* data, int data_len, int* out_len, int /*quality*/) {
  uLongf size = compressBound(static_cast<uLong>(data_len));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (!out) return nullptr;
  if (compress2(out, &size, data, static_cast<uLong>(data_len), t_level) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_len = static_cast<int>(size);
  return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS ZlibCompress
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace test {
namespace {

void Append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

std::string StbPng(const prt::Image8& image, int level) {
  std::string out;
  t_level = level;
  // "sub" filter on every row, as fast as any and good on smooth rendered images. This copy's
  // settings are private to this file (internal linkage); set once, by a thread-safe static
  // initialisation, because several frames are encoded at once and stb only reads it.
  static const bool filter_set = (stbi_write_force_png_filter = 1, true);
  (void)filter_set;
  if (!stbi_write_png_to_func(Append, &out, image.width, image.height, 3, image.rgb.data(), 3 * image.width))
    out.clear();
  return out;
}

}  // namespace test
