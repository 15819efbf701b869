#include "precompute_io/transport_txt.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/parallel.h"

namespace prt {

namespace {

/// Exact powers of ten in double: 10^0 .. 10^22.
constexpr double kPow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                               1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

/// "00" "01" ... "99".
constexpr char kDigitPairs[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// |d| * 10^p, rounded once (p in -22 .. 22, where 10^|p| is exact), or -1 outside that range.
inline double ScaleByPow10(double a, int p) {
  if (p >= 0) return p <= 22 ? a * kPow10[p] : -1.0;
  return p >= -22 ? a / kPow10[-p] : -1.0;
}

/// Writes exactly what printf("%.7g", double(value)) writes (C locale) at `p` and returns its
/// end; at most 16 characters. The 7 significant digits come from one correctly rounded
/// product or quotient of |value| by an exact power of ten, whose error (at most half an ulp
/// of a number below 10^7, 1e-9) cannot move a rounding decision unless the digits beyond the
/// seventh are within 1e-7 of one half: those values (near ties), non-finite ones and the few
/// outside 1e-16 .. 1e28 go through std::to_chars, which rounds the exact binary value as printf
/// does. Checked against std::to_chars on all 2^32 float bit patterns, and against snprintf on
/// every 13th of them.
char* FormatG7(float value, char* p) {
  const double d = value;
  if (d == 0.0) {
    if (std::signbit(d)) *p++ = '-';
    *p++ = '0';
    return p;
  }
  const auto fallback = [&]() {
    if (!std::isfinite(d)) return p + std::snprintf(p, 17, "%.7g", d);
    return std::to_chars(p, p + 16, d, std::chars_format::general, 7).ptr;
  };
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  const int biased = static_cast<int>((bits >> 23) & 0xFFu);
  if (biased == 0 || biased == 0xFF) return fallback();  // subnormal (below 1e-37), inf, nan
  const double a = std::fabs(d);
  // a in [2^(e2 - 1), 2^e2): floor(log10(a)) is floor(log10(2) (e2 - 1)) or one more
  // (78913 / 2^18 is log10(2) to 6 digits, exact floors for |e2| < 1000).
  const int e2 = biased - 126;
  int e10 = ((e2 - 1) * 78913) >> 18;
  double s = ScaleByPow10(a, 6 - e10);
  if (s >= 1e7) s = ScaleByPow10(a, 6 - ++e10);
  if (!(s >= 1e6 && s < 1e7)) return fallback();
  const std::uint32_t whole = static_cast<std::uint32_t>(s);  // floor: s > 0
  const double frac = s - static_cast<double>(whole);         // exact
  if (std::fabs(frac - 0.5) < 1e-7) return fallback();
  std::uint32_t digits = whole + (frac > 0.5 ? 1u : 0u);
  if (digits == 10000000u) digits = 1000000u, ++e10;  // 9999999.5.. rounds up to 10^7
  char dig[7];  // two digits at a time: fewer dependent divisions
  const std::uint32_t r5 = digits % 100000, r3 = r5 % 1000;
  std::memcpy(dig, kDigitPairs + 2 * (digits / 100000), 2);
  std::memcpy(dig + 2, kDigitPairs + 2 * (r5 / 1000), 2);
  std::memcpy(dig + 4, kDigitPairs + 2 * (r3 / 10), 2);
  dig[6] = static_cast<char>('0' + r3 % 10);
  int last = 6;  // last significant digit after trailing zeros are dropped (%g drops them)
  while (last > 0 && dig[last] == '0') --last;
  if (value < 0.0f) *p++ = '-';
  if (e10 < -4 || e10 >= 7) {  // %e style: d.dddddde+XX
    *p++ = dig[0];
    if (last > 0) {
      *p++ = '.';
      for (int i = 1; i <= last; ++i) *p++ = dig[i];
    }
    *p++ = 'e';
    int x = e10;
    *p++ = x < 0 ? '-' : '+';
    if (x < 0) x = -x;
    if (x >= 100) *p++ = static_cast<char>('0' + x / 100), x %= 100;
    *p++ = static_cast<char>('0' + x / 10);
    *p++ = static_cast<char>('0' + x % 10);
    return p;
  }
  if (e10 >= 0) {  // %f style, e10 + 1 digits before the point
    for (int i = 0; i <= e10; ++i) *p++ = dig[i];
    if (last > e10) {
      *p++ = '.';
      for (int i = e10 + 1; i <= last; ++i) *p++ = dig[i];
    }
    return p;
  }
  *p++ = '0';  // e10 in -4 .. -1: 0.000ddddddd
  *p++ = '.';
  for (int i = -1; i > e10; --i) *p++ = '0';
  for (int i = 0; i <= last; ++i) *p++ = dig[i];
  return p;
}

/// The corners `FormatTransportTxt` and `FormatVertexRadianceTxt` write: every face of the file.
const std::vector<std::array<std::uint32_t, 3>>& FileFaces(const Mesh& mesh) {
  return mesh.file_triangles.empty() ? mesh.triangles : mesh.file_triangles;
}

}  // namespace

std::size_t FileFaceCount(const Mesh& mesh) { return FileFaces(mesh).size(); }

std::size_t FileVertexCount(const Mesh& mesh) {
  if (mesh.file_triangles.empty()) return mesh.vertex_count();
  std::size_t count = 0;
  for (const auto& tri : mesh.file_triangles)
    for (std::uint32_t v : tri) count = std::max(count, std::size_t(v) + 1);
  return count;
}

std::string FormatVertexRadianceTxt(const Mesh& mesh, const std::vector<glm::vec3>& radiance) {
  std::string out = std::to_string(FileVertexCount(mesh)) + "\n";
  const auto& faces = FileFaces(mesh);
  out.reserve(out.size() + faces.size() * 3 * 48);
  char row[96];
  for (const auto& tri : faces)
    for (std::uint32_t v : tri) {
      const glm::vec3& c = radiance[v];
      std::snprintf(row, sizeof row, "%.9g %.9g %.9g\n", double(c.x), double(c.y), double(c.z));
      out += row;
    }
  return out;
}

std::string FormatTransportTxt(const Mesh& mesh, const Transport& transport, int channel) {
  const int count = CoeffCount(transport.lmax);
  std::string out = std::to_string(mesh.vertex_count()) + "\n";
  const auto& faces = FileFaces(mesh);
  // Faces in fixed chunks, each formatted into its own part on any thread, then joined in
  // order: the text does not depend on the thread count.
  constexpr std::size_t kFacesPerChunk = 1024;
  constexpr std::size_t kMaxNumber = 17;  // FormatG7's 16 characters and the separator
  std::vector<std::string> parts(ChunkCount(faces.size(), kFacesPerChunk));
  ParallelFor(faces.size(), kFacesPerChunk, [&](std::size_t begin, std::size_t end) {
    std::string& part = parts[begin / kFacesPerChunk];
    part.resize((end - begin) * 3 * count * kMaxNumber);
    char* p = part.data();
    for (std::size_t f = begin; f < end; ++f) {
      for (std::uint32_t v : faces[f]) {
        const float* t = transport.at(v, channel);
        for (int k = 0; k < count; ++k) {
          p = FormatG7(t[k], p);
          *p++ = k + 1 < count ? ' ' : '\n';
        }
      }
    }
    part.resize(static_cast<std::size_t>(p - part.data()));
  });
  std::size_t size = out.size();
  for (const std::string& part : parts) size += part.size();
  out.reserve(size);
  for (const std::string& part : parts) out += part;
  return out;
}

}  // namespace prt
