#include "raster/rasterizer.h"

#include <algorithm>
#include <atomic>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "core/error.h"
#include "core/parallel.h"
#include "raster/clip.h"
#include "raster/triangle_setup.h"

namespace prt {
namespace {

constexpr int kBandRows = 8;                // output rows per parallel band
constexpr std::size_t kVertexGrain = 16384;  // vertices per transform chunk
constexpr std::size_t kTriangleGrain = 4096; // triangles per setup chunk

constexpr std::size_t kPrefetchAhead = 8;    // triangles fetched ahead of the fill

// Asks for the cache lines of a set-up triangle before it is filled.
void Prefetch(const RasterTriangle* t) {
  const char* p = reinterpret_cast<const char*>(t);
  for (std::size_t offset = 0; offset < sizeof(RasterTriangle); offset += 64) __builtin_prefetch(p + offset);
}

// Size of the sample grid (the output size times K).
struct Target {
  int width, height;
};

void Validate(const Camera& camera, int width, int height, const std::vector<glm::vec3>& positions,
              const std::vector<std::array<std::uint32_t, 3>>& triangles,
              const std::vector<glm::vec3>& colors, const RasterOptions& options) {
  CheckCamera(camera);
  if (options.ssaa < 1 || options.ssaa > 8)
    throw Error("--ssaa: " + std::to_string(options.ssaa) + " (expected 1 to 8)");
  if (width < 1 || height < 1 || width > kMaxTargetSide / options.ssaa ||
      height > kMaxTargetSide / options.ssaa)
    throw Error("--size: " + std::to_string(width) + "x" + std::to_string(height) +
                " (expected 1 to " + std::to_string(kMaxTargetSide) + " pixels a side, times --ssaa)");
  if (colors.size() != positions.size())
    throw Error("rasterizer: " + std::to_string(colors.size()) + " colours for " +
                std::to_string(positions.size()) + " vertices (expected one per vertex)");
  if (const RasterTexturing* tx = options.texturing) {
    if (!tx->corner_uv || !tx->triangle_texture || !tx->textures || tx->corner_uv->size() != 3 * triangles.size() ||
        tx->triangle_texture->size() != triangles.size() || (tx->added && tx->added->size() != positions.size()))
      throw Error("rasterizer: texturing arrays do not match the mesh (expected 3 coordinates per triangle, one "
                  "texture per triangle and one added colour per vertex)");
    for (std::uint32_t index : *tx->triangle_texture)
      if (index >= tx->textures->size() || !(*tx->textures)[index])
        throw Error("rasterizer: texture " + std::to_string(index) + " does not exist (expected < " +
                    std::to_string(tx->textures->size()) + ")");
  }
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (std::uint32_t index : triangles[i])
      if (index >= positions.size())
        throw Error("rasterizer: triangle " + std::to_string(i) + " uses vertex " +
                    std::to_string(index) + " (expected < " + std::to_string(positions.size()) + ")");
}

ScreenVertex Project(const ClipVertex& c, Target target) {
  ScreenVertex s;
  s.inv_w = 1.f / c.position.w;
  s.x = (c.position.x * s.inv_w + 1.f) * 0.5f * static_cast<float>(target.width);
  s.y = (1.f - c.position.y * s.inv_w) * 0.5f * static_cast<float>(target.height);
  s.color = c.color;
  return s;
}

// Clips, projects and sets up one input triangle; appends 0 or more raster triangles. `screen`
// holds the projected vertices of the triangles inside every plane (outcodes all zero).
// With `texture` (textured triangles), each emitted triangle's texture planes are appended to
// `planes` and its `textured` holds their index until the chunk is complete (see SetUp).
void SetupOne(const ClipVertex (&v)[3], const ScreenVertex* const (&screen)[3], const unsigned (&outcode)[3],
              const ClipPlanes& planes, Target target, bool cull, std::vector<RasterTriangle>& out,
              const Texture* texture = nullptr, std::vector<TexturePlanes>* texture_planes = nullptr) {
  if (outcode[0] & outcode[1] & outcode[2]) return;  // entirely outside one plane
  const auto emit = [&](const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                        const TextureCorner* corners) {
    out.emplace_back();
    TexturePlanes tp;
    if (!SetupTriangle(a, b, c, target.width, target.height, cull, out.back(), texture ? corners : nullptr, &tp)) {
      out.pop_back();
      return;
    }
    if (!texture) return;
    tp.texture = texture;
    out.back().textured = reinterpret_cast<const TexturePlanes*>(texture_planes->size());  // an index for now
    texture_planes->push_back(tp);
  };
  if ((outcode[0] | outcode[1] | outcode[2]) == 0) {
    const TextureCorner corners[3] = {v[0].texture, v[1].texture, v[2].texture};
    emit(*screen[0], *screen[1], *screen[2], corners);
    return;
  }
  // Crosses a plane: clip to a convex polygon and draw it as a fan.
  const ClipPolygon poly =
      ClipTriangle(v[0], v[1], v[2], outcode[0] | outcode[1] | outcode[2], planes);
  ScreenVertex s[kMaxClipVertices];
  for (int i = 0; i < poly.count; ++i) s[i] = Project(poly.vertex[i], target);
  for (int i = 1; i + 1 < poly.count; ++i) {
    const TextureCorner corners[3] = {poly.vertex[0].texture, poly.vertex[i].texture, poly.vertex[i + 1].texture};
    emit(s[0], s[i], s[i + 1], corners);
  }
}

// The textured fill of one pixel: colour times the texture's albedo at the perspective-correct
// (u, v), filtered at the pixel's footprint (the derivatives of u = (u/w) / (1/w) across and
// down the screen), plus the added colour.
inline glm::vec3 TexturedColor(const TexturePlanes& p, const glm::vec3& color, float scale, float u_w, float v_w,
                               const Plane& inv_w_plane, const glm::vec3& added_w) {
  const float u = u_w * scale, v = v_w * scale;
  const glm::vec2 d_dx((p.u_w.ddx - u * inv_w_plane.ddx) * scale, (p.v_w.ddx - v * inv_w_plane.ddx) * scale);
  const glm::vec2 d_dy((p.u_w.ddy - u * inv_w_plane.ddy) * scale, (p.v_w.ddy - v * inv_w_plane.ddy) * scale);
  return color * p.texture->Sample({u, v}, p.texture->LodOf(d_dx, d_dy)) + added_w * scale;
}

// FillRows for a textured triangle.
void FillRowsTextured(const RasterTriangle& t, int row_begin, int row_end, int band_y0, int width, float* depth,
                      glm::vec3* color) {
  const TexturePlanes& p = *t.textured;
  const int y_first = std::max(t.y_min, row_begin), y_end = std::min(t.y_max + 1, row_end);
  if (y_first >= y_end) return;
  RowWalker rows(t, y_first);
  const auto at = [](const Plane& q, float dx, float dy) { return q.at_ref + q.ddx * dx + q.ddy * dy; };
  for (int y = y_first; y < y_end; ++y) {
    const Span span = rows.Next();
    if (span.begin >= span.end) continue;
    const float dy = static_cast<float>(y) + 0.5f - t.ref_y;
    const std::size_t row = static_cast<std::size_t>(y - band_y0) * width;
    for (int x = span.begin; x < span.end; ++x) {
      const float dx = static_cast<float>(x) + 0.5f - t.ref_x;
      const float inv_w = at(t.inv_w, dx, dy);
      if (!(inv_w > depth[row + x])) continue;  // depth test: nearer wins, first drawn keeps ties
      depth[row + x] = inv_w;
      const float scale = 1.f / inv_w;
      const glm::vec3 shade(at(t.r_w, dx, dy) * scale, at(t.g_w, dx, dy) * scale, at(t.b_w, dx, dy) * scale);
      const glm::vec3 added_w(at(p.ar_w, dx, dy), at(p.ag_w, dx, dy), at(p.ab_w, dx, dy));
      color[row + x] = TexturedColor(p, shade, scale, at(p.u_w, dx, dy), at(p.v_w, dx, dy), t.inv_w, added_w);
    }
  }
}

// Fills the rows [row_begin, row_end) of one triangle; depth and colour hold the band, whose
// first sample row is band_y0. Depth is 1/w: larger is nearer, 0 means empty.
void FillRows(const RasterTriangle& t, int row_begin, int row_end, int band_y0, int width,
              float* depth, glm::vec3* color) {
  if (t.textured) {
    FillRowsTextured(t, row_begin, row_end, band_y0, width, depth, color);
    return;
  }
  const int y_first = std::max(t.y_min, row_begin), y_end = std::min(t.y_max + 1, row_end);
  if (y_first >= y_end) return;
  RowWalker rows(t, y_first);
  for (int y = y_first; y < y_end; ++y) {
    const Span span = rows.Next();
    if (span.begin >= span.end) continue;
    // Plane values at the first pixel centre of the span, then steps along x.
    const float dx = static_cast<float>(span.begin) + 0.5f - t.ref_x;
    const float dy = static_cast<float>(y) + 0.5f - t.ref_y;
    const float w0 = t.inv_w.at_ref + t.inv_w.ddx * dx + t.inv_w.ddy * dy;
    const float r0 = t.r_w.at_ref + t.r_w.ddx * dx + t.r_w.ddy * dy;
    const float g0 = t.g_w.at_ref + t.g_w.ddx * dx + t.g_w.ddy * dy;
    const float b0 = t.b_w.at_ref + t.b_w.ddx * dx + t.b_w.ddy * dy;
    const std::size_t row = static_cast<std::size_t>(y - band_y0) * width;
    for (int x = span.begin; x < span.end; ++x) {
      const float i = static_cast<float>(x - span.begin);
      const float inv_w = w0 + t.inv_w.ddx * i;
      if (!(inv_w > depth[row + x])) continue;  // depth test: nearer wins, first drawn keeps ties
      depth[row + x] = inv_w;
      const float scale = 1.f / inv_w;
      color[row + x] = glm::vec3((r0 + t.r_w.ddx * i) * scale, (g0 + t.g_w.ddx * i) * scale,
                                 (b0 + t.b_w.ddx * i) * scale);
    }
  }
}

// p[0 .. n) = c; a grey (the usual background) as one run of floats, which vectorises.
void FillColor(glm::vec3* p, std::size_t n, const glm::vec3& c) {
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "pixels are three packed floats");
  if (c.x == c.y && c.y == c.z)
    std::fill_n(reinterpret_cast<float*>(p), 3 * n, c.x);
  else
    std::fill_n(p, n, c);
}

// Band-local sample buffers, reused by each worker thread across bands and frames.
struct BandBuffers {
  std::vector<float> depth;
  std::vector<glm::vec3> color;  // supersampled: the samples' colours
  std::vector<glm::vec3> rows;   // the linear frame not kept: the band's resolved rows
};

// Where Resolve writes the output rows [row_begin, row_end) of a frame of width x height:
// `image` and `coverage` (null: not kept) point at row row_begin's first pixel.
struct ResolveTarget {
  int width, height;
  glm::vec3* image;
  float* coverage;
};

// Writes output rows [row_begin, row_end): the average of the covered samples of each pixel, the
// background behind the uncovered ones, and the covered fraction. With one sample per pixel
// (k = 1) the covered colours (and a solid background) are in the target's rows already.
void Resolve(const BandBuffers& band, int row_begin, int row_end, int band_y0, int k,
             const Background& background, const ViewRays& rays, const ResolveTarget& target) {
  const int width = target.width, height = target.height;
  const std::size_t stride = static_cast<std::size_t>(width) * k;  // samples per row
  const float inv_samples = 1.f / static_cast<float>(k * k);
  if (k == 1) {  // the background is solid (there already) or looked up for the uncovered pixels
    for (int oy = row_begin; oy < row_end; ++oy) {
      const std::size_t row = static_cast<std::size_t>(oy - row_begin) * width;
      const float* depth = &band.depth[static_cast<std::size_t>(oy - band_y0) * width];
      if (float* coverage = target.coverage ? target.coverage + row : nullptr)
        for (int ox = 0; ox < width; ++ox) coverage[ox] = depth[ox] > 0.f ? 1.f : 0.f;
      if (!background.radiance) continue;
      glm::vec3* out = target.image + row;
      const float ndc_y = 1.f - (static_cast<float>(oy) + 0.5f) / static_cast<float>(height) * 2.f;
      for (int ox = 0; ox < width; ++ox) {
        if (depth[ox] > 0.f) continue;
        const float ndc_x = (static_cast<float>(ox) + 0.5f) / static_cast<float>(width) * 2.f - 1.f;
        out[ox] = background.radiance(rays.Direction(ndc_x, ndc_y));
      }
    }
    return;
  }
  for (int oy = row_begin; oy < row_end; ++oy) {
    const std::size_t row = static_cast<std::size_t>(oy - row_begin) * width;
    glm::vec3* out = target.image + row;
    const float ndc_y = 1.f - (static_cast<float>(oy) + 0.5f) / static_cast<float>(height) * 2.f;
    for (int ox = 0; ox < width; ++ox) {
      glm::vec3 sum(0.f);
      int covered = 0;
      for (int sy = oy * k - band_y0; sy < (oy + 1) * k - band_y0; ++sy)
        for (std::size_t s = sy * stride + ox * k; s < sy * stride + (ox + 1) * k; ++s)
          if (band.depth[s] > 0.f) sum += band.color[s], ++covered;
      const float coverage = static_cast<float>(covered) * inv_samples;
      if (target.coverage) target.coverage[row + ox] = coverage;
      out[ox] = sum * inv_samples;
      if (covered == k * k) continue;
      glm::vec3 back = background.color;
      if (background.radiance) {
        const float ndc_x = (static_cast<float>(ox) + 0.5f) / static_cast<float>(width) * 2.f - 1.f;
        back = background.radiance(rays.Direction(ndc_x, ndc_y));
      }
      out[ox] += (1.f - coverage) * back;
    }
  }
}

}  // namespace

void Rasterizer::SetUp(const Camera& camera, float aspect, int target_width, int target_height,
                       const std::vector<glm::vec3>& positions,
                       const std::vector<std::array<std::uint32_t, 3>>& triangles,
                       const std::vector<glm::vec3>& colors, const RasterTexturing* texturing,
                       bool cull_back_faces, int band_samples, int band_count) {
  const Target target{target_width, target_height};
  // Vertices to clip space, with their outcodes, and projected when inside every plane (a
  // vertex is shared by about six triangles: it is projected once).
  const glm::mat4 view_projection = ProjectionMatrix(camera, aspect) * ViewMatrix(camera);
  const ClipPlanes planes = GuardBandPlanes(camera.near_plane, target.width, target.height);
  clip_.resize(positions.size());
  outcodes_.resize(positions.size());
  screen_.resize(positions.size());
  ParallelFor(positions.size(), kVertexGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      clip_[i] = view_projection * glm::vec4(positions[i], 1.f);
      outcodes_[i] = Outcode(clip_[i], planes);
      if (outcodes_[i] == 0) screen_[i] = Project({clip_[i], colors[i], {}}, target);
    }
  });
  // Triangle setup in fixed chunks; chunk c's output keeps the input order. Each chunk also
  // notes its triangles' bands and counts them per band, for Bin.
  const std::size_t chunks = ChunkCount(triangles.size(), kTriangleGrain);
  const std::size_t bands = static_cast<std::size_t>(band_count);
  chunks_.resize(chunks);
  chunk_band_count_.assign(chunks * bands, 0);  // [chunk][band]
  ParallelFor(triangles.size(), kTriangleGrain, [&](std::size_t begin, std::size_t end) {
    const std::size_t c = begin / kTriangleGrain;
    std::vector<RasterTriangle>& out = chunks_[c].triangles;
    std::vector<TexturePlanes>& textured = chunks_[c].textured;
    out.clear();
    textured.clear();
    for (std::size_t i = begin; i < end; ++i) {
      const auto& tri = triangles[i];
      const unsigned codes[3] = {outcodes_[tri[0]], outcodes_[tri[1]], outcodes_[tri[2]]};
      const ScreenVertex* const screen[3] = {&screen_[tri[0]], &screen_[tri[1]], &screen_[tri[2]]};
      ClipVertex v[3] = {{clip_[tri[0]], colors[tri[0]], {}}, {clip_[tri[1]], colors[tri[1]], {}},
                         {clip_[tri[2]], colors[tri[2]], {}}};
      if (!texturing) {
        SetupOne(v, screen, codes, planes, target, cull_back_faces, out);
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        v[k].texture.uv = (*texturing->corner_uv)[3 * i + k];
        if (texturing->added) v[k].texture.added = (*texturing->added)[tri[k]];
      }
      const Texture* texture = (*texturing->textures)[(*texturing->triangle_texture)[i]].get();
      SetupOne(v, screen, codes, planes, target, cull_back_faces, out, texture, &textured);
    }
    // The chunk's planes no longer move: turn the indices into pointers.
    if (texturing)
      for (RasterTriangle& t : out)
        t.textured = &textured[reinterpret_cast<std::size_t>(t.textured)];
    std::vector<BandRange>& ranges = chunks_[c].bands;
    ranges.resize(out.size());
    std::size_t* count = &chunk_band_count_[c * bands];
    for (std::size_t t = 0; t < out.size(); ++t) {
      ranges[t] = {out[t].y_min / band_samples, out[t].y_max / band_samples};
      for (int b = ranges[t].first; b <= ranges[t].last; ++b) ++count[b];
    }
  });
}

void Rasterizer::Bin(int band_count) {
  // A counting sort by band (the counts come from SetUp), in parallel over the setup chunks: a
  // triangle spanning several bands is listed in each, and every band lists its triangles in
  // chunk order, then input order within a chunk, whatever the thread count.
  const std::size_t chunks = chunks_.size(), bands = static_cast<std::size_t>(band_count);
  // Exclusive prefix sums in (band, chunk) order: where chunk c starts writing in band b.
  band_start_.assign(bands + 1, 0);
  std::size_t total = 0;
  for (std::size_t b = 0; b < bands; ++b) {
    band_start_[b] = total;
    for (std::size_t c = 0; c < chunks; ++c) {
      const std::size_t n = chunk_band_count_[c * bands + b];
      chunk_band_count_[c * bands + b] = total;
      total += n;
    }
  }
  band_start_[bands] = total;
  binned_.resize(total);
  ParallelFor(chunks, 1, [&](std::size_t c, std::size_t) {
    std::size_t* fill = &chunk_band_count_[c * bands];
    const SetupChunk& chunk = chunks_[c];
    for (std::size_t t = 0; t < chunk.triangles.size(); ++t)
      for (int b = chunk.bands[t].first; b <= chunk.bands[t].last; ++b) binned_[fill[b]++] = &chunk.triangles[t];
  });
}

const RasterImage& Rasterizer::Draw(const Camera& camera, int width, int height,
                                    const std::vector<glm::vec3>& positions,
                                    const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                    const std::vector<glm::vec3>& colors,
                                    const RasterOptions& options) {
  Validate(camera, width, height, positions, triangles, colors, options);
  const int k = options.ssaa;
  const Target target{width * k, height * k};
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const int band_samples = kBandRows * k;
  const int band_count = (height + kBandRows - 1) / kBandRows;
  SetUp(camera, aspect, target.width, target.height, positions, triangles, colors, options.texturing,
        options.cull_back_faces, band_samples, band_count);
  Bin(band_count);

  // Fill, resolve (and tone map) each band.
  const Background& background = options.background;
  const ViewRays rays = MakeViewRays(camera, aspect);
  Image8* toned = options.tone_map ? options.tone_mapped : nullptr;
  const bool linear = !toned || options.keep_linear;
  if (toned) {
    toned->width = width;
    toned->height = height;
    toned->rgb.resize(3 * static_cast<std::size_t>(width) * height);
  }
  if (linear) {
    frame_.image.width = width;
    frame_.image.height = height;
    frame_.image.pixels.resize(static_cast<std::size_t>(width) * height);
    frame_.coverage.resize(static_cast<std::size_t>(width) * height);
  } else {  // not drawn: nothing stale may pass for this frame (the buffers stay for the next)
    frame_.image.width = frame_.image.height = 0;
    frame_.image.pixels.clear();
    frame_.coverage.clear();
  }
  std::atomic<std::size_t> negative{0}, nan{0};  // the tone map's repairs: integer sums, any thread count
  ParallelFor(band_count, 1, [&](std::size_t band, std::size_t) {
    thread_local BandBuffers buffers;
    const int y0 = static_cast<int>(band) * band_samples;
    const int y1 = std::min(y0 + band_samples, target.height);
    const int row_begin = y0 / k, row_end = y1 / k;
    const std::size_t samples = static_cast<std::size_t>(y1 - y0) * target.width;
    const std::size_t pixels = static_cast<std::size_t>(row_end - row_begin) * width;
    if (buffers.depth.size() < samples) buffers.depth.resize(samples);
    std::fill_n(buffers.depth.begin(), samples, 0.f);
    // The band's output rows: the frame's own, or (the linear frame not kept) a band buffer that
    // stays in cache until it is tone mapped.
    ResolveTarget out{width, height, nullptr, nullptr};
    if (linear) {
      out.image = &frame_.image.at(0, row_begin);
      out.coverage = &frame_.coverage[static_cast<std::size_t>(row_begin) * width];
    } else {
      if (buffers.rows.size() < pixels) buffers.rows.resize(pixels);
      out.image = buffers.rows.data();
    }
    // One sample per pixel: the triangles fill the output rows, over a solid background put
    // there first. Supersampled: a band buffer of samples, resolved into the rows afterwards.
    glm::vec3* color = nullptr;
    if (k == 1) {
      color = out.image;
      if (!background.radiance) FillColor(color, samples, background.color);
    } else {
      if (buffers.color.size() < samples) buffers.color.resize(samples);
      color = buffers.color.data();
    }
    const std::size_t first = band_start_[band], last = band_start_[band + 1];
    for (std::size_t i = first; i < last; ++i) {
      // A band's triangles lie all over the setup's output: fetch ahead (a no-op on the result).
      if (i + kPrefetchAhead < last) Prefetch(binned_[i + kPrefetchAhead]);
      FillRows(*binned_[i], y0, y1, y0, target.width, buffers.depth.data(), color);
    }
    Resolve(buffers, row_begin, row_end, y0, k, background, rays, out);
    if (toned) {
      const ToneMapCounts c = ToneMapPixels(out.image, pixels, *options.tone_map,
                                            &toned->rgb[3 * static_cast<std::size_t>(row_begin) * width]);
      negative += c.negative_pixels;
      nan += c.nan_pixels;
    }
  });
  frame_.tone_counts.negative_pixels = negative;
  frame_.tone_counts.nan_pixels = nan;
  return frame_;
}

RasterImage Rasterize(const Camera& camera, int width, int height,
                      const std::vector<glm::vec3>& positions,
                      const std::vector<std::array<std::uint32_t, 3>>& triangles,
                      const std::vector<glm::vec3>& colors, const RasterOptions& options) {
  Rasterizer rasterizer;
  rasterizer.Draw(camera, width, height, positions, triangles, colors, options);
  return rasterizer.TakeFrame();
}

}  // namespace prt
