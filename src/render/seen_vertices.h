#pragma once
/// \file
/// The vertices a render's frames show: those of every triangle that covers a sample of some
/// frame after the depth test.
///
/// Per-vertex transport reaches the picture only through the triangles drawn: a pixel is the
/// interpolation of its visible triangle's three vertex colours. A vertex no frame shows (facing
/// away, behind other surfaces, outside the view) changes the picture only through the light it
/// bounces, which a receiver gathers from many hit points at once. So the transport spends its
/// directions on the vertices seen (precompute/sample_rule.h). The test is exact for the
/// frames drawn: each frame's camera (the orbit included; of a long orbit 360 cameras spread
/// evenly over it) is drawn once by the rasterizer that draws the frames, at the frame's
/// supersampled resolution, with each triangle's number as its colour, and the vertices of
/// every triangle left in a sample are marked. The light's turn changes no visibility. The pass
/// holds the triangles with corners of their own while it runs: three positions, three colours
/// and three indices, 84 bytes a triangle.

#include <cstdint>
#include <vector>

#include "geometry/mesh.h"
#include "raster/camera.h"
#include "render/render_options.h"

namespace prt {

/// Per vertex of `mesh`, 1 if a frame of the render `options` describes, seen from `camera`
/// (orbited as the frames are), shows a triangle of it, else 0.
std::vector<std::uint8_t> SeenVertices(const Mesh& mesh, const Camera& camera, const RenderOptions& options);

}  // namespace prt
