#include "app/render_options.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "raster/rasterizer.h"
#include "sh/coeffs.h"

#include <cstdlib>

namespace prt {

const char* const kRenderOptionsHelp =
    "render options:\n"
    "  --frames N          frames over the turns, 1..100000 (default 120)\n"
    "  --size WxH          frame size in pixels, each 1..16384 (default 640x480)\n"
    "  --out DIR           output folder for frame_0000.png ... (default out/render)\n"
    "  --axis X,Y,Z        rotation axis of the light (default 0,1,0: world up)\n"
    "  --turns T           full turns of the light over all frames (default 1)\n"
    "  --background B      env | black | R,G,B (linear, each >= 0) (default env: the environment,\n"
    "                      turning with the light)\n"
    "  --tonemap T         srgb | reinhard | aces (default srgb)\n"
    "  --exposure EV       radiance is scaled by 2^EV before tone mapping, -20..20 (default 0)\n"
    "  --ssaa K            K x K supersampling, 1..8 (default 1)\n"
    "  --view V            radiance | irradiance | albedo | transport:K | light (default radiance):\n"
    "                      the final colour, the lighting alone (albedo 1), the albedo, the K-th\n"
    "                      transport coefficient in false colour with a legend, or the light as\n"
    "                      the SH coefficients reconstruct it (on the mesh: in the normal's direction)\n"
    "  --eye X,Y,Z --target X,Y,Z --up X,Y,Z --fov DEGREES\n"
    "                      the camera; what is not given comes from automatic framing of the mesh,\n"
    "                      and the run summary prints the camera used in this same syntax\n";

RenderOptions ReadRenderOptions(Args& args, const RenderOptions& d) {
  RenderOptions o = d;
  o.frames = args.Int("--frames", d.frames, 1, 100000);
  if (const auto size = args.String("--size")) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    std::istringstream ss(*size);
    if (!(ss >> w >> x >> h) || x != 'x' || (ss >> extra) || w < 1 || h < 1 || w > 16384 || h > 16384)
      throw UsageError("--size: '" + *size + "' is not a size (expected WxH, each from 1 to 16384)", args.command());
    o.width = w, o.height = h;
  }
  o.out = args.String("--out", d.out);
  if (const auto axis = args.Vec3("--axis")) {
    if (std::sqrt(axis->x * axis->x + axis->y * axis->y + axis->z * axis->z) < 1e-12)
      throw UsageError("--axis: must not be zero", args.command());
    o.axis = *axis;
  }
  o.turns = args.Double("--turns", d.turns, -1e6, 1e6);
  const std::string bg = args.String("--background", d.env_background ? "env" : "black");
  if (bg == "env") {
    o.env_background = true;
  } else if (bg == "black") {
    o.env_background = false, o.background_color = glm::vec3(0.0f);
  } else {
    std::istringstream ss(bg);
    glm::dvec3 c;
    char c1 = 0, c2 = 0;
    if (!(ss >> c.x >> c1 >> c.y >> c2 >> c.z) || c1 != ',' || c2 != ',' || c.x < 0 || c.y < 0 || c.z < 0 ||
        !std::isfinite(c.x + c.y + c.z))
      throw UsageError("--background: '" + bg + "' (expected env, black or R,G,B with each >= 0)", args.command());
    o.env_background = false, o.background_color = glm::vec3(c);
  }
  const std::string curve = args.Choice("--tonemap", ToneCurveName(d.tonemap), {"srgb", "reinhard", "aces"});
  o.tonemap = *ParseToneCurve(curve);
  o.exposure = args.Double("--exposure", d.exposure, -20.0, 20.0);
  o.ssaa = args.Int("--ssaa", d.ssaa, 1, 8);
  if (static_cast<long long>(o.width) * o.ssaa > kMaxTargetSide || static_cast<long long>(o.height) * o.ssaa > kMaxTargetSide)
    throw UsageError("--ssaa: " + std::to_string(o.ssaa) + " times the frame size exceeds " +
                     std::to_string(kMaxTargetSide) + " samples per side", args.command());
  const std::string view = args.String("--view", d.view);
  if (view.rfind("transport:", 0) == 0) {
    const std::string k = view.substr(10);
    char* end = nullptr;
    const long index = std::strtol(k.c_str(), &end, 10);
    if (k.empty() || *end != '\0' || index < 0 || index >= CoeffCount(kMaxLmax))
      throw UsageError("--view: '" + view + "' (expected transport:K with K a coefficient index from 0)", args.command());
    o.view = "transport", o.transport_index = static_cast<int>(index);
  } else if (view == "radiance" || view == "irradiance" || view == "albedo" || view == "light") {
    o.view = view;
  } else {
    throw UsageError("--view: unknown value '" + view + "' (expected radiance, irradiance, albedo, transport:K or light)",
                     args.command());
  }
  if (auto v = args.Vec3("--eye")) o.eye = v;
  if (auto v = args.Vec3("--target")) o.target = v;
  if (auto v = args.Vec3("--up")) o.up = v;
  if (args.Has("--fov")) o.fov = args.Double("--fov", 35.0, 1e-3, 179.0);
  return o;
}

}  // namespace prt
