#pragma once
/// \file
/// The rasterizer: draws triangles with per-vertex linear RGB colours, optionally times a
/// filtered texture per pixel, into a linear image, with a depth buffer, near-plane clipping and
/// optional supersampling.
///
/// The pipeline, one step per function in rasterizer.cpp:
///   1. vertices -> clip space (camera.h);
///   2. per triangle: clip against the near plane and a guard band (clip.h), project, snap and
///      set up edge functions and colour planes (triangle_setup.h);
///   3. sort the set-up triangles into bands of scanlines, keeping the drawing order (a counting
///      sort, in parallel over the setup's chunks);
///   4. per band, in parallel: fill each triangle's spans with a depth test (nearer wins; on an
///      exact tie the triangle drawn first stays), then resolve the K x K samples of every pixel
///      and put the background behind the uncovered ones.
/// Every band sees its triangles in input order, so the image does not depend on the number of
/// threads.

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/image.h"
#include "raster/camera.h"
#include "raster/tonemap.h"
#include "raster/triangle_setup.h"
#include "texture/texture.h"

namespace prt {

/// What shows where no triangle is: `radiance` if set, else the solid `color` (linear RGB).
struct Background {
  glm::vec3 color{0.f};
  /// Linear radiance seen along a unit world-space view direction (e.g. the environment,
  /// rotated by the caller). Called from several threads at once: must be thread-safe.
  std::function<glm::vec3(const glm::vec3& direction)> radiance;
};

/// A textured mesh's per-pixel albedo: each pixel of triangle i is colour * albedo + added, with
/// albedo = textures[triangle_texture[i]] sampled at the texture coordinates interpolated
/// perspective-correctly from corner_uv[3 i + c] (filtered by its mip levels at the pixel's own
/// footprint: texture/texture.h), and `added` interpolated from per-vertex colours like `colors`
/// (a glossy lobe, which the albedo does not scale; may be null). The arrays must outlive Draw.
struct RasterTexturing {
  const std::vector<glm::vec2>* corner_uv = nullptr;
  const std::vector<std::uint32_t>* triangle_texture = nullptr;
  const std::vector<std::shared_ptr<const Texture>>* textures = nullptr;
  const std::vector<glm::vec3>* added = nullptr;
};

/// How to draw.
struct RasterOptions {
  int ssaa = 1;                  ///< K: render K*W x K*H samples, box-filter to W x H; 1..8
  bool cull_back_faces = false;  ///< drop triangles clockwise on screen (counter-clockwise = front)
  Background background;
  const RasterTexturing* texturing = nullptr;  ///< null: per-vertex colours only
  /// With both set, each band of output rows is tone mapped into `*tone_mapped` (resized to the
  /// frame) as soon as it is resolved, while its rows are still in cache: the same bytes as
  /// ToneMapInto on the finished frame, without reading the frame back from memory.
  const ToneMapOptions* tone_map = nullptr;
  Image8* tone_mapped = nullptr;
  /// With tone mapping: false leaves the linear frame out (RasterImage::image and coverage come
  /// back empty): each band is drawn, resolved and tone mapped in cache, and only the 8-bit
  /// image reaches memory, what a render loop needs once its exposure is known.
  bool keep_linear = true;
};

/// Largest render target side in samples (width * ssaa and height * ssaa).
constexpr int kMaxTargetSide = 16384;

/// The drawn frame: linear radiance (background already filled in) and, per pixel, the covered
/// fraction of its K x K samples (0 = background only, 1 = fully covered).
struct RasterImage {
  ImageF image;
  std::vector<float> coverage;  ///< width * height, row-major like image
  ToneMapCounts tone_counts;    ///< what the fused tone mapping repaired (RasterOptions::tone_map)
};

/// Draws frame after frame, keeping its buffers between frames: after the first frame of a
/// given size, drawing allocates nothing (fresh memory costs a page fault per 4 KiB).
class Rasterizer {
 public:
  /// Draws `triangles` (vertex indices into `positions`, world space) with per-vertex `colors`
  /// (linear RGB, same length as positions) as seen by `camera` into a width x height image.
  /// The result stays valid until the next Draw or TakeFrame. Throws Error for an unusable
  /// camera, a bad size or ssaa, mismatched array lengths, or a vertex index out of range.
  const RasterImage& Draw(const Camera& camera, int width, int height,
                          const std::vector<glm::vec3>& positions,
                          const std::vector<std::array<std::uint32_t, 3>>& triangles,
                          const std::vector<glm::vec3>& colors, const RasterOptions& options = {});

  /// Moves the last frame out (the next Draw allocates a new one).
  RasterImage TakeFrame() { return std::move(frame_); }

 private:
  void SetUp(const Camera& camera, float aspect, int target_width, int target_height,
             const std::vector<glm::vec3>& positions,
             const std::vector<std::array<std::uint32_t, 3>>& triangles,
             const std::vector<glm::vec3>& colors, const RasterTexturing* texturing, bool cull_back_faces,
             int band_samples, int band_count);
  void Bin(int band_count);

  struct BandRange {
    int first, last;  ///< the bands a triangle's rows touch, inclusive
  };
  struct SetupChunk {
    std::vector<RasterTriangle> triangles;  ///< in input order
    std::vector<BandRange> bands;           ///< per triangle
    std::vector<TexturePlanes> textured;    ///< the textured triangles' planes, in order
  };

  RasterImage frame_;
  std::vector<glm::vec4> clip_;                      // per vertex, clip space
  std::vector<unsigned> outcodes_;                   // per vertex, clip.h Outcode
  std::vector<ScreenVertex> screen_;                 // per vertex inside every plane, projected
  std::vector<SetupChunk> chunks_;                   // set-up triangles per input chunk
  std::vector<std::size_t> band_start_;              // band b: binned_[band_start_[b] ...]
  std::vector<std::size_t> chunk_band_count_;        // SetUp's counts, then Bin's offsets, [chunk][band]
  std::vector<const RasterTriangle*> binned_;        // triangles per band, in input order
};

/// One frame with a temporary Rasterizer (see Rasterizer::Draw).
RasterImage Rasterize(const Camera& camera, int width, int height,
                      const std::vector<glm::vec3>& positions,
                      const std::vector<std::array<std::uint32_t, 3>>& triangles,
                      const std::vector<glm::vec3>& colors, const RasterOptions& options = {});

}  // namespace prt
