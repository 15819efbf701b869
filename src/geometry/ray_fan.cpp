#include "geometry/ray_fan.h"

#include <algorithm>
#include <cmath>

#include "geometry/box_test.h"
#include "geometry/triangle.h"

namespace prt {
namespace {

// Interleaves the low 16 bits of x and y (Morton / Z order).
std::uint32_t Morton2(std::uint32_t x, std::uint32_t y) {
  auto spread = [](std::uint32_t v) {
    v &= 0xFFFFu;
    v = (v | (v << 8)) & 0x00FF00FFu;
    v = (v | (v << 4)) & 0x0F0F0F0Fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
  };
  return spread(x) | (spread(y) << 1);
}

}  // namespace

RayFan MakeRayFan(const std::vector<glm::vec3>& directions) {
  RayFan fan;
  fan.directions = directions;
  // Sort key: cube face (axis permutation) first, then Morton order of the face coordinates.
  struct Keyed {
    std::uint64_t key;
    std::uint32_t index;
  };
  std::vector<Keyed> keyed;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const glm::vec3& d = directions[i];
    const ShearedRay r = MakeShearedRay(d);
    const int face = r.kz * 2 + (d[r.kz] < 0.0f ? 1 : 0);
    auto quantise = [](float x) {  // x in [-1, 1] -> [0, 65535]
      return static_cast<std::uint32_t>(std::clamp((x + 1.0f) * 32767.5f, 0.0f, 65535.0f));
    };
    const float az = std::abs(d[r.kz]);
    const std::uint32_t m = Morton2(quantise(d[r.kx] / az), quantise(d[r.ky] / az));
    keyed.push_back({(static_cast<std::uint64_t>(face) << 32) | m, static_cast<std::uint32_t>(i)});
  }
  std::sort(keyed.begin(), keyed.end(),
            [](const Keyed& a, const Keyed& b) { return a.key < b.key || (a.key == b.key && a.index < b.index); });
  for (const Keyed& k : keyed) {
    const glm::vec3& d = directions[k.index];
    fan.rays.push_back(FanRay{d, SafeInverse(d), MakeShearedRay(d), k.index});
  }
  return fan;
}

}  // namespace prt
