#include "raster/clip.h"

#include "raster/triangle_setup.h"

namespace prt {
namespace {

constexpr int kPlaneCount = 5;

// Signed distance-like value of p for plane i: >= 0 inside.
float Distance(const glm::vec4& p, int plane, const ClipPlanes& c) {
  switch (plane) {
    case 0: return p.w - c.near_w;
    case 1: return c.guard_x * p.w - p.x;
    case 2: return c.guard_x * p.w + p.x;
    case 3: return c.guard_y * p.w - p.y;
    default: return c.guard_y * p.w + p.y;
  }
}

// The point where the edge from `in` (inside) to `out` (outside) crosses the plane.
ClipVertex Cut(const ClipVertex& in, float d_in, const ClipVertex& out, float d_out) {
  const float t = d_in / (d_in - d_out);
  return {in.position + t * (out.position - in.position), in.color + t * (out.color - in.color),
          {in.texture.uv + t * (out.texture.uv - in.texture.uv), in.texture.added + t * (out.texture.added - in.texture.added)}};
}

}  // namespace

ClipPlanes GuardBandPlanes(float near_w, int width, int height) {
  // Screen x = (ndc + 1) / 2 * width stays within +-kMaxScreenCoord / 2 when
  // |ndc| <= kMaxScreenCoord / width - 1 (>= 1 for targets up to 16384 pixels).
  ClipPlanes p;
  p.near_w = near_w;
  p.guard_x = kMaxScreenCoord / static_cast<float>(width) - 1.f;
  p.guard_y = kMaxScreenCoord / static_cast<float>(height) - 1.f;
  return p;
}

unsigned Outcode(const glm::vec4& position, const ClipPlanes& planes) {
  unsigned code = 0;
  for (int i = 0; i < kPlaneCount; ++i)
    if (!(Distance(position, i, planes) >= 0.f)) code |= 1u << i;  // NaN counts as outside
  return code;
}

ClipPolygon ClipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                         unsigned mask, const ClipPlanes& planes) {
  ClipPolygon poly;
  poly.vertex[0] = a;
  poly.vertex[1] = b;
  poly.vertex[2] = c;
  poly.count = 3;
  for (int plane = 0; plane < kPlaneCount && poly.count >= 3; ++plane) {
    if (!(mask & (1u << plane))) continue;
    // One Sutherland-Hodgman pass: keep inside vertices, add a cut point on crossing edges.
    ClipPolygon next;
    for (int i = 0; i < poly.count; ++i) {
      const ClipVertex& p = poly.vertex[i];
      const ClipVertex& q = poly.vertex[(i + 1) % poly.count];
      const float dp = Distance(p.position, plane, planes);
      const float dq = Distance(q.position, plane, planes);
      const int room = static_cast<int>(next.vertex.size());
      if (dp >= 0.f && next.count < room) next.vertex[next.count++] = p;
      if ((dp >= 0.f) != (dq >= 0.f) && next.count < room)
        next.vertex[next.count++] = dp >= 0.f ? Cut(p, dp, q, dq) : Cut(q, dq, p, dp);
    }
    poly = next;
  }
  if (poly.count < 3) poly.count = 0;
  return poly;
}

}  // namespace prt
