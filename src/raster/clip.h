#pragma once
/// \file
/// Clipping in homogeneous clip space [1]: triangles crossing the near plane are cut along it
/// (not dropped, and never projected through w <= 0, which would wrap them around the screen).
/// The same Sutherland-Hodgman pass [2] also cuts against a guard band far outside the screen,
/// so that the fixed-point maths of triangle_setup.h never overflows; inside the band, the
/// edge functions themselves do the screen-edge clipping.
///
/// Watertightness: a new vertex on an edge is always interpolated from the inside end towards
/// the outside end, so two triangles sharing an edge get bit-identical cut points.
///
/// References:
///  [1] J. Blinn and M. Newell, "Clipping Using Homogeneous Coordinates", SIGGRAPH 1978.
///  [2] I. Sutherland and G. Hodgman, "Reentrant Polygon Clipping", CACM 17(1), 1974.

#include <array>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/triangle_setup.h"

namespace prt {

/// A vertex in clip space (OpenGL convention, w = depth along the view axis) with its colour.
struct ClipVertex {
  glm::vec4 position{0.f};
  glm::vec3 color{0.f};
  TextureCorner texture;  ///< a textured triangle's corner data, interpolated like colour
};

/// The planes kept: w >= near_w, |x| <= guard_x w, |y| <= guard_y w.
struct ClipPlanes {
  float near_w = 0.01f;
  float guard_x = 1.f;
  float guard_y = 1.f;
};

/// Guard band for a target of width x height pixels: NDC bounds that keep every screen
/// coordinate within half of kMaxScreenCoord. Precondition: width, height <= 16384.
ClipPlanes GuardBandPlanes(float near_w, int width, int height);

/// Bit i set when the position is outside plane i (near, +x, -x, +y, -y).
unsigned Outcode(const glm::vec4& position, const ClipPlanes& planes);

/// A convex polygon: a triangle cut by up to five planes has at most 3 + 5 vertices (the spare
/// room absorbs rounding on nearly degenerate input; beyond it vertices are dropped, never
/// written out of bounds).
constexpr int kMaxClipVertices = 12;
struct ClipPolygon {
  std::array<ClipVertex, kMaxClipVertices> vertex;
  int count = 0;
};

/// Clips triangle (a, b, c) against the planes whose bits are set in `mask` (normally the union
/// of the three outcodes). Vertex order, hence orientation, is preserved. count < 3 when nothing
/// is left.
ClipPolygon ClipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                         unsigned mask, const ClipPlanes& planes);

}  // namespace prt
