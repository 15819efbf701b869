#pragma once
/// \file
/// A wavelet transport made up for the tests of its cache (test_wavelet_cache.cpp, and the
/// binary's in test_wavelet_cache_cli.cpp).

#include <cmath>
#include <cstdint>
#include <vector>

#include "wavelet/transport.h"

namespace prt::test {

/// A transport with every field away from its default, the values awkward for a careless
/// writer (negative zero, a denormal, the int16 extremes, a count above 32 bits for rays).
inline WaveletTransport SyntheticWaveletTransport() {
  WaveletTransport t;
  t.face_size = 4;
  t.vertices = 5;
  t.base_lmax = 2;
  for (int i = 0; i < 5 * 9; ++i) t.base.push_back(0.25f * float(i) - 3.0f);
  t.base[7] = -0.0f;
  t.base[8] = 1e-40f;
  for (int i = 0; i < 30; ++i) t.means.push_back(0.01f * float(i) + 0.5f);
  t.scale = {1e-3f, 2e-3f, 0.0f, 4e-3f, 5e-3f};
  const std::vector<std::vector<std::uint16_t>> per_vertex = {{1, 7, 95}, {}, {0, 2, 3, 50, 94}, {6}, {10, 11}};
  t.offsets = {0};
  for (const auto& kept : per_vertex) {
    t.index.insert(t.index.end(), kept.begin(), kept.end());
    t.offsets.push_back(t.index.size());
  }
  for (std::size_t j = 0; j < t.index.size(); ++j) t.value.push_back(std::int16_t(int(j) * 5000 % 65535 - 32767));
  t.value[0] = -32767, t.value[1] = 32767;
  t.bounce.lmax = 1;
  t.bounce.channels = 3;
  t.bounce.vertices = 5;
  for (int i = 0; i < 5 * 3 * 4; ++i) t.bounce.coeffs.push_back(float(i) / 7.0f);
  t.probes = {0, 3};
  for (int i = 0; i < 2 * 96; ++i) t.probe_coeffs.push_back(std::sin(float(i)));
  t.kept_energy = 0.98765432101234;
  t.rays = 123456789012ULL;
  t.seconds = 1.25;
  return t;
}

}  // namespace prt::test
