#pragma once
/// \file
/// One screen-space triangle made ready for scanline filling: vertices snapped to a fixed-point
/// grid, three integer edge functions with the top-left fill rule, and the planes that give
/// perspective-correct colour.
///
/// Coverage is decided exactly in integers [1, 2]: pixel (x, y) is covered when all three edge
/// functions at its centre (x + 1/2, y + 1/2) are positive, or zero on a top or left edge. Two
/// triangles sharing an edge therefore cover each pixel along it exactly once. RowSpan turns the
/// three edge tests into one [begin, end) interval per scanline.
///
/// Colour is interpolated perspective-correctly [3]: 1/w and colour/w are affine functions of
/// the screen position, so they are stored as planes and colour = (colour/w) / (1/w) per pixel.
/// Texture coordinates of a textured triangle likewise, with their own planes (TexturePlanes).
///
/// References:
///  [1] J. Pineda, "A Parallel Algorithm for Polygon Rasterization", SIGGRAPH 1988.
///  [2] Microsoft, "Direct3D 11.3 Functional Specification", section 15.6 (rasterization rules:
///      8 bits of sub-pixel precision, the top-left rule).
///  [3] P. Heckbert and H. Moreton, "Interpolation for Polygon Texture Mapping and Shading",
///      in State of the Art in Computer Graphics, Springer 1991.

#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "texture/texture.h"

namespace prt {

/// Sub-pixel precision: coordinates are snapped to 1/256 pixel.
constexpr int kSubpixelBits = 8;
constexpr int kSubpixelScale = 1 << kSubpixelBits;
/// Largest |screen coordinate| in pixels SetupTriangle accepts. Keeps every edge-function
/// product below 2^49, well inside int64. The clipper keeps vertices within half of it.
constexpr float kMaxScreenCoord = 32768.f;

/// A projected vertex. Screen space: pixels, x right, y down, pixel (i, j) has its centre at
/// (i + 0.5, j + 0.5).
struct ScreenVertex {
  float x = 0.f, y = 0.f;
  float inv_w = 1.f;       ///< 1 / clip w, > 0 (1 for a flat screen-space triangle)
  glm::vec3 color{0.f};   ///< linear RGB
};

/// E(X, Y) = a X + b Y + c on fixed-point coordinates; a pixel centre is inside when E >= 0.
/// The top-left rule is folded into c (non top-left edges get c - 1, so E = 0 is outside).
struct EdgeFunction {
  std::int32_t a = 0, b = 0;
  std::int64_t c = 0;
};

/// value(x, y) = at_ref + ddx (x - ref_x) + ddy (y - ref_y), with x, y in pixels.
struct Plane {
  float at_ref = 0.f, ddx = 0.f, ddy = 0.f;
};

/// What a textured triangle's corner adds to its ScreenVertex: texture coordinates, and a colour
/// added after the albedo multiplies the vertex colour (a glossy lobe's radiance).
struct TextureCorner {
  glm::vec2 uv{0.f};
  glm::vec3 added{0.f};
};

/// A textured triangle's extra planes: (u, v)/w and added/w, and its texture.
struct TexturePlanes {
  Plane u_w, v_w, ar_w, ag_w, ab_w;
  const Texture* texture = nullptr;
};

/// A triangle ready to fill. Bounds are the inclusive pixel range that may be covered, already
/// clipped to the render target.
struct RasterTriangle {
  EdgeFunction edge[3];
  int x_min = 0, x_max = -1, y_min = 0, y_max = -1;
  float ref_x = 0.f, ref_y = 0.f;  ///< where the planes are anchored (the first vertex)
  Plane inv_w, r_w, g_w, b_w;      ///< 1/w and colour/w
  /// Textured: the pixel's colour is colour * albedo(u, v) + added; null for a plain triangle.
  const TexturePlanes* textured = nullptr;
};

/// Snaps and sets up a triangle for a width x height target into `t`. Returns false (and `t` is
/// unspecified) when the triangle covers no pixel centre of the target, has zero area, is
/// back-facing and cull_back_faces is set (front faces are counter-clockwise on screen, the
/// OpenGL default), or has a coordinate beyond kMaxScreenCoord or a non-positive inv_w.
/// With `corners` (three, in vertex order) the texture planes are set up into `*planes` too.
bool SetupTriangle(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
                   int width, int height, bool cull_back_faces, RasterTriangle& t,
                   const TextureCorner* corners = nullptr, TexturePlanes* planes = nullptr);

/// Pixels [begin, end) of scanline y covered by the triangle (empty when begin >= end).
/// Precondition: y in [t.y_min, t.y_max].
struct Span {
  int begin = 0, end = 0;
};
Span RowSpan(const RasterTriangle& t, int y);

/// Triangles at most this many pixels wide have their spans found by stepping (RowWalker).
constexpr int kScanWidth = 32;

/// The spans of a triangle's rows from y_first down, one per Next(): the same spans as RowSpan.
/// A triangle at most kScanWidth pixels wide (the common case in a dense mesh, where most
/// triangles cover a few pixels) is walked without any division: the three edge functions are
/// stepped across the row's pixel centres and the covered centres form one interval (the
/// triangle is convex); RowSpan's two divisions per edge and row would cost more than that.
class RowWalker {
 public:
  RowWalker(const RasterTriangle& t, int y_first);
  Span Next();

 private:
  const RasterTriangle& t_;
  int y_;
  bool scan_;
  std::int64_t edge_[3] = {0, 0, 0};  ///< scan_: edge values at the centre of (x_min, y_)
};

inline Span RowWalker::Next() {
  if (!scan_) return RowSpan(t_, y_++);
  // Bit i: the centre of pixel x_min + i is inside all three edges (no value negative).
  const int n = t_.x_max - t_.x_min + 1;
  const std::int64_t step0 = std::int64_t(t_.edge[0].a) * kSubpixelScale, step1 = std::int64_t(t_.edge[1].a) * kSubpixelScale,
            step2 = std::int64_t(t_.edge[2].a) * kSubpixelScale;
  std::int64_t e0 = edge_[0], e1 = edge_[1], e2 = edge_[2];
  std::uint32_t inside = 0;
  for (int i = 0; i < n; ++i, e0 += step0, e1 += step1, e2 += step2)
    inside |= static_cast<std::uint32_t>((e0 | e1 | e2) >= 0) << i;
  for (int i = 0; i < 3; ++i) edge_[i] += std::int64_t(t_.edge[i].b) * kSubpixelScale;
  ++y_;
  if (inside == 0) return {};
  return {t_.x_min + __builtin_ctz(inside), t_.x_min + 32 - __builtin_clz(inside)};
}

}  // namespace prt
