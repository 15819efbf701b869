#include "report/report_image.h"

#include "raster/exposure.h"
#include "raster/rasterizer.h"
#include "raster/tonemap.h"

namespace prt {

RenderOptions ReportRenderOptions(int width, int height) {
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.frames = 1;
  o.tonemap = ToneCurve::kSrgb;
  o.exposure = 0.0;
  o.ssaa = 1;
  return o;
}

Image8 DrawVertexColors(const Mesh& mesh, const std::vector<glm::vec3>& colors, const Environment& env,
                        const Camera& camera, const RenderOptions& o, double* exposure_used) {
  RasterOptions ro;
  ro.ssaa = o.ssaa;
  ro.background.color = o.background_color;
  if (o.env_background)
    ro.background.radiance = [&env](const glm::vec3& d) { return glm::vec3(env.Radiance(glm::dvec3(d))); };
  const RasterImage frame = Rasterize(camera, o.width, o.height, mesh.positions, mesh.triangles, colors, ro);
  ToneMapOptions tone;
  tone.curve = o.tonemap;
  const double ev = o.exposure ? *o.exposure : AutoExposureEv(frame, o.tonemap);
  if (exposure_used) *exposure_used = ev;
  tone.exposure_ev = float(ev);
  return ToneMap(frame.image, tone).image;
}

std::vector<glm::vec3> ToFloat(const std::vector<glm::dvec3>& colors) {
  return std::vector<glm::vec3>(colors.begin(), colors.end());
}

}  // namespace prt
