#pragma once
/// \file
/// Pictures for `reference` and `report`: a mesh with given per-vertex radiance, drawn by the
/// same rasterizer, camera choice (ChooseCamera), environment background and tone mapping as
/// `render` draws frame 0, so that the image of the ground truth and the image of a PRT result
/// differ only where their vertex colours do, and image PSNR measures exactly that.

#include <vector>

#include <glm/vec3.hpp>

#include "core/image.h"
#include "env/environment.h"
#include "geometry/mesh.h"
#include "raster/camera.h"
#include "render/render_options.h"

namespace prt {

/// The render options the report pictures use: 320 x 240 unless `width`/`height` say otherwise,
/// the plain sRGB curve at exposure 0 without supersampling (so PSNR compares vertex colours
/// through the simplest fixed mapping), everything else as `render`'s defaults.
RenderOptions ReportRenderOptions(int width = 320, int height = 240);

/// The mesh drawn with per-vertex linear radiance `colors` over the unturned environment, seen
/// by `camera`, tone-mapped as `options` say (frame 0 of `render`). With automatic exposure
/// the EV is measured on this picture (raster/exposure.h) and stored in `exposure_used`.
Image8 DrawVertexColors(const Mesh& mesh, const std::vector<glm::vec3>& colors, const Environment& env,
                        const Camera& camera, const RenderOptions& options, double* exposure_used = nullptr);

/// Double-precision colours to float, as the rasterizer takes them.
std::vector<glm::vec3> ToFloat(const std::vector<glm::dvec3>& colors);

}  // namespace prt
