#include "raster/triangle_setup.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace prt {
namespace {

using i64 = std::int64_t;
constexpr i64 kHalf = kSubpixelScale / 2;  // a pixel centre is at 256 x + 128

// floor(n / d) for d > 0 and |n| < 2^50. The double quotient is within 1/8 of the exact one,
// so its truncation is off by at most one, which the integer checks correct: exact, and
// cheaper than a 64-bit integer division.
i64 FloorDiv(i64 n, i64 d) {
  i64 q = static_cast<i64>(double(n) / double(d));
  if (q * d > n)
    --q;
  else if ((q + 1) * d <= n)
    ++q;
  return q;
}
i64 CeilDiv(i64 n, i64 d) { return -FloorDiv(-n, d); }

// floor(n / kSubpixelScale) and ceil(...): the arithmetic shift rounds towards minus infinity.
i64 FloorShift(i64 n) { return n >> kSubpixelBits; }
i64 CeilShift(i64 n) { return -((-n) >> kSubpixelBits); }

struct Fixed {
  i64 x, y;
};

bool Snap(const ScreenVertex& v, Fixed& out) {
  if (!(std::fabs(v.x) <= kMaxScreenCoord && std::fabs(v.y) <= kMaxScreenCoord)) return false;
  if (!(v.inv_w > 0.f && std::isfinite(v.inv_w))) return false;
  // Round to nearest, halves away from zero (a shared vertex always snaps the same way).
  const float x = v.x * kSubpixelScale, y = v.y * kSubpixelScale;
  out.x = static_cast<i64>(x + (x >= 0.f ? 0.5f : -0.5f));
  out.y = static_cast<i64>(y + (y >= 0.f ? 0.5f : -0.5f));
  return true;
}

// Edge from p to q of a triangle with positive area (in y-down screen space the inside is where
// E > 0). Top edge: horizontal with the inside below it (dx > 0); left edge: dy < 0.
EdgeFunction MakeEdge(const Fixed& p, const Fixed& q) {
  const i64 dx = q.x - p.x, dy = q.y - p.y;
  EdgeFunction e;
  e.a = static_cast<std::int32_t>(-dy);
  e.b = static_cast<std::int32_t>(dx);
  e.c = dy * p.x - dx * p.y;
  const bool top_left = (dy == 0 && dx > 0) || dy < 0;
  if (!top_left) e.c -= 1;
  return e;
}

// The plane through three (x, y, value) points, anchored at the first. `inv_det` is one over
// twice the signed area in pixels^2.
Plane MakePlane(const double x[3], const double y[3], double q0, double q1, double q2,
                double inv_det) {
  Plane p;
  p.at_ref = static_cast<float>(q0);
  p.ddx = static_cast<float>(((q1 - q0) * (y[2] - y[0]) - (q2 - q0) * (y[1] - y[0])) * inv_det);
  p.ddy = static_cast<float>(((q2 - q0) * (x[1] - x[0]) - (q1 - q0) * (x[2] - x[0])) * inv_det);
  return p;
}

}  // namespace

bool SetupTriangle(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
                   int width, int height, bool cull_back_faces, RasterTriangle& t,
                   const TextureCorner* corners, TexturePlanes* planes) {
  // Snap to the fixed-point grid.
  const ScreenVertex* v[3] = {&v0, &v1, &v2};
  const TextureCorner* tc[3] = {corners, corners + 1, corners + 2};
  Fixed f[3];
  for (int i = 0; i < 3; ++i)
    if (!Snap(*v[i], f[i])) return false;

  // Orientation: area2 < 0 is counter-clockwise as seen on screen (y points down), a front face.
  const i64 area2 = (f[1].x - f[0].x) * (f[2].y - f[0].y) - (f[2].x - f[0].x) * (f[1].y - f[0].y);
  if (area2 == 0) return false;
  if (area2 > 0 && cull_back_faces) return false;
  if (area2 < 0) {  // make the area positive so that "inside" means E > 0 on every edge
    std::swap(f[1], f[2]);
    std::swap(v[1], v[2]);
    std::swap(tc[1], tc[2]);
  }

  // Pixel bounds: centres 256 x + 128 inside the fixed-point bounding box, clipped to the target.
  const i64 min_x = std::min({f[0].x, f[1].x, f[2].x}), max_x = std::max({f[0].x, f[1].x, f[2].x});
  const i64 min_y = std::min({f[0].y, f[1].y, f[2].y}), max_y = std::max({f[0].y, f[1].y, f[2].y});
  t.x_min = static_cast<int>(std::max<i64>(0, CeilShift(min_x - kHalf)));
  t.x_max = static_cast<int>(std::min<i64>(width - 1, FloorShift(max_x - kHalf)));
  t.y_min = static_cast<int>(std::max<i64>(0, CeilShift(min_y - kHalf)));
  t.y_max = static_cast<int>(std::min<i64>(height - 1, FloorShift(max_y - kHalf)));
  if (t.x_min > t.x_max || t.y_min > t.y_max) return false;

  // Edge functions, edge i from vertex i to vertex i + 1.
  for (int i = 0; i < 3; ++i) t.edge[i] = MakeEdge(f[i], f[(i + 1) % 3]);

  // Perspective-correct attribute planes through the snapped positions.
  double x[3], y[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = double(f[i].x) / kSubpixelScale;
    y[i] = double(f[i].y) / kSubpixelScale;
  }
  const double inv_det = (double(kSubpixelScale) * kSubpixelScale) / double(std::abs(area2));
  double w[3];
  for (int i = 0; i < 3; ++i) w[i] = v[i]->inv_w;
  t.ref_x = static_cast<float>(x[0]);
  t.ref_y = static_cast<float>(y[0]);
  t.inv_w = MakePlane(x, y, w[0], w[1], w[2], inv_det);
  t.r_w = MakePlane(x, y, w[0] * v[0]->color.x, w[1] * v[1]->color.x, w[2] * v[2]->color.x, inv_det);
  t.g_w = MakePlane(x, y, w[0] * v[0]->color.y, w[1] * v[1]->color.y, w[2] * v[2]->color.y, inv_det);
  t.b_w = MakePlane(x, y, w[0] * v[0]->color.z, w[1] * v[1]->color.z, w[2] * v[2]->color.z, inv_det);
  t.textured = nullptr;
  if (corners && planes) {
    const auto plane = [&](auto value) {
      return MakePlane(x, y, w[0] * value(*tc[0]), w[1] * value(*tc[1]), w[2] * value(*tc[2]), inv_det);
    };
    planes->u_w = plane([](const TextureCorner& c) { return double(c.uv.x); });
    planes->v_w = plane([](const TextureCorner& c) { return double(c.uv.y); });
    planes->ar_w = plane([](const TextureCorner& c) { return double(c.added.x); });
    planes->ag_w = plane([](const TextureCorner& c) { return double(c.added.y); });
    planes->ab_w = plane([](const TextureCorner& c) { return double(c.added.z); });
  }
  return true;
}

Span RowSpan(const RasterTriangle& t, int y) {
  // Edge test at the centre X = 256 x + 128 of pixel x on this row:
  //   a (256 x + 128) + k >= 0,  with k = b Y + c.
  const i64 py = i64(y) * kSubpixelScale + kHalf;
  i64 lo = t.x_min, hi = t.x_max;
  for (const EdgeFunction& e : t.edge) {
    const i64 k = i64(e.b) * py + e.c + i64(e.a) * kHalf;  // value at x = 0
    const i64 step = i64(e.a) * kSubpixelScale;          // change per pixel
    if (step > 0)
      lo = std::max(lo, CeilDiv(-k, step));
    else if (step < 0)
      hi = std::min(hi, FloorDiv(k, -step));
    else if (k < 0)
      return {};
  }
  return {static_cast<int>(lo), static_cast<int>(std::max(lo, hi + 1))};
}

RowWalker::RowWalker(const RasterTriangle& t, int y_first)
    : t_(t), y_(y_first), scan_(t.x_max - t.x_min < kScanWidth) {
  if (!scan_) return;
  const i64 px = i64(t.x_min) * kSubpixelScale + kHalf, py = i64(y_first) * kSubpixelScale + kHalf;
  for (int i = 0; i < 3; ++i) edge_[i] = i64(t.edge[i].a) * px + i64(t.edge[i].b) * py + t.edge[i].c;
}


}  // namespace prt
