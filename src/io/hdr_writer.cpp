#include "io/hdr_writer.h"

#include <cmath>

#include "core/error.h"

namespace prt {

std::string EncodeHdr(const ImageF& image) {
  if (image.width <= 0 || image.height <= 0) throw Error("HDR encoder: empty image (expected at least 1x1)");
  std::string out = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(image.height) + " +X " +
                    std::to_string(image.width) + "\n";
  out.reserve(out.size() + 4 * image.pixels.size());
  for (const glm::vec3& p : image.pixels) {
    float c[3];
    for (int i = 0; i < 3; ++i) c[i] = std::isfinite(p[i]) && p[i] > 0.0f ? p[i] : 0.0f;
    const float m = std::fmax(c[0], std::fmax(c[1], c[2]));
    if (m < 1e-32f) {
      out.append(4, '\0');
      continue;
    }
    int e = 0;
    const float mantissa = std::frexp(m, &e);  // m = mantissa 2^e, mantissa in [0.5, 1)
    const float scale = mantissa * 256.0f / m;
    for (int i = 0; i < 3; ++i) out += static_cast<char>(static_cast<unsigned char>(std::fmin(c[i] * scale, 255.0f)));
    out += static_cast<char>(static_cast<unsigned char>(e + 128));
  }
  return out;
}

}  // namespace prt
