#pragma once
// stb_image_write's PNG of an 8-bit RGB image, deflated by zlib at `level` with every row
// filtered "sub": what prt's own encoder must write byte for byte. Empty if stb failed.
#include <string>

#include "core/image.h"

namespace test {
std::string StbPng(const prt::Image8& image, int level);
}  // namespace test
