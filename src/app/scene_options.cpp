#include "app/scene_options.h"

#include "app/report_auto_lmax.h"
#include "env/load_environment.h"

#include <cmath>

#include "core/error.h"
#include "core/log.h"
#include "core/parallel.h"
#include "sh/coeffs.h"

namespace prt {

const char* const kSceneOptionsHelp =
    "scene options:\n"
    "  --mesh PATH        OBJ file (default: the embedded demo scene)\n"
    "  --env ENV          cubemap folder (posx negx posy negy posz negz, jpg/png/hdr/exr), an\n"
    "                     equirectangular .hdr/.exr/.png/.jpg file, or a built-in: furnace[:C],\n"
    "                     sky[:sun=3,elevation=40,azimuth=35,radius=2] (default: sky)\n"
    "  --lmax L           highest SH band, 0..64; (L+1)^2 coefficients (default 2: 9); `auto`:\n"
    "                     the smallest whose irradiance error is below --tolerance\n"
    "  --tolerance X      relative error for --lmax auto, 1e-12..1 (default 0.01)\n"
    "  --transport MODE   unshadowed | shadowed | interreflection (default shadowed)\n"
    "  --samples N        directions per vertex (default 1024)\n"
    "  --sampler NAME     fibonacci | stratified | uniform (default fibonacci)\n"
    "  --bounces B        interreflection bounces, 1..1000 (default 1)\n"
    "  --direction-sets K independent direction sets the vertices draw from, 1..1024 (default 64):\n"
    "                     many give independent per-vertex noise, 1 gives smooth, correlated error\n"
    "  --albedo R,G,B     override the material colour, each in [0,1]\n"
    "  --seed S           random seed (default 1)\n"
    "  --threads N        worker threads, 1..1024; results do not depend on it (default: all cores)\n"
    "  --games202-faces   read cubemaps with the course's face mapping and pow(x, 2.2) decoding,\n"
    "                     to reproduce its published light.txt files\n"
    "  --window W         none | hann | lanczos | auto: SH windowing against ringing (default none)\n"
    "  --quiet            no progress, warnings or summary on stderr\n";

SceneOptions ReadSceneOptions(Args& args, const SceneOptions& d) {
  SceneOptions o = d;
  o.mesh = args.String("--mesh", d.mesh);
  o.env = args.String("--env", d.env);
  const std::string lmax_text = args.String("--lmax", std::to_string(d.lmax));
  o.tolerance = args.Double("--tolerance", d.tolerance, 1e-12, 1.0);
  if (lmax_text == "auto") {
    o.lmax_auto = true;
  } else {
    const auto v = ParseNumber(lmax_text);
    if (!v || *v != std::floor(*v) || *v < 0 || *v > kMaxLmax)
      throw UsageError("--lmax: '" + lmax_text + "' is out of range (expected an integer from 0 to " +
                           std::to_string(kMaxLmax) + ") or auto",
                       args.command());
    o.lmax = static_cast<int>(*v);
  }
  o.transport = args.Choice("--transport", d.transport, {"unshadowed", "shadowed", "interreflection"});
  o.samples = args.Int("--samples", d.samples, 1, 1 << 24);
  o.sampler = args.Choice("--sampler", d.sampler, {"fibonacci", "stratified", "uniform"});
  o.bounces = args.Int("--bounces", d.bounces, 1, 1000);
  o.direction_sets = args.Int("--direction-sets", d.direction_sets, 1, 1024);
  if (auto albedo = args.Vec3("--albedo")) {
    for (int c = 0; c < 3; ++c)
      if ((*albedo)[c] < 0.0 || (*albedo)[c] > 1.0)
        throw UsageError("--albedo: each channel must be in [0, 1]", args.command());
    o.albedo = albedo;
  }
  o.seed = static_cast<std::uint64_t>(args.Double("--seed", double(d.seed), 0.0, 9007199254740992.0));
  o.threads = args.Int("--threads", d.threads, 1, 1024);
  if (!args.Has("--threads")) o.threads = d.threads;
  if (args.Flag("--games202-faces")) o.layout = CubeLayout::kGames202;
  o.window = args.Choice("--window", d.window, {"none", "hann", "lanczos", "auto"});
  SetQuiet(args.Flag("--quiet"));
  SetThreadCount(o.threads);
  if (o.lmax_auto) {
    // Measured on the environment itself (loaded here once more: the commands load it again).
    const AutoLmax choice = ChooseLmax(*LoadEnvironment(o.env, o.layout), o.tolerance, kMaxLmax);
    o.lmax = choice.lmax;
    Summary(choice.why);
  }
  return o;
}

std::set<std::string> SceneFlags(std::set<std::string> extra) {
  extra.insert({"--games202-faces", "--quiet"});
  return extra;
}

}  // namespace prt
