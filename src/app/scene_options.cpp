#include "app/scene_options.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "core/error.h"
#include "core/log.h"
#include "core/parallel.h"
#include "core/text.h"
#include "env/cubemap.h"
#include "env/load_environment.h"
#include "io/image_load.h"
#include "precompute/sample_rule.h"
#include "report/report_auto_lmax.h"
#include "sh/coeffs.h"

namespace prt {
namespace {

/// --basis's help: the names of the table's rows, then what each but the default is.
std::string BasisHelp() {
  std::string names, what;
  for (const Basis* b : Bases()) {
    names += (names.empty() ? "" : " | ") + b->Name();
    if (!b->Help().empty()) what += " " + b->Help();
  }
  return names + ": the basis of the transport." + what;
}

std::map<std::string, OptionSpec> SceneSpecs(const SceneOptions& d) {
  const std::string albedo =
      d.albedo ? VecText(*d.albedo)
               : "the materials' Kd; 0.8 grey without materials";
  std::map<std::string, OptionSpec> s;
  auto add = [&s](OptionSpec o) { s[o.name] = std::move(o); };
  add({"--mesh", "PATH", "the OBJ mesh (polygons are triangulated; Kd of its .mtl is the albedo)",
       d.mesh.empty() ? "the embedded demo scene, a torus knot on a ground plane" : d.mesh});
  add({"--env", "ENV",
       "the environment light: a cubemap folder (posx negx posy negy posz negz, jpg/png/hdr/exr), an "
       "equirectangular .hdr/.exr/.png/.jpg file, or a built-in: furnace[:C] (constant radiance C, default 1) "
       "or sky[:sun=3,elevation=40,azimuth=35,radius=2] (an HDR sky with a sun disk)",
       d.env});
  add({"--lmax", "L", "highest SH band, 0.." + std::to_string(d.max_lmax) +
                          ": (L+1)^2 coefficients; `auto`: the smallest whose irradiance error is within --tolerance",
       std::to_string(d.lmax) + ", " + std::to_string(CoeffCount(d.lmax)) + " coefficients"});
  add({"--tolerance", "X", "relative irradiance error that --lmax auto must reach, 1e-12..1", Formatted("%g", double(d.tolerance))});
  add({"--transport", "MODE",
       "unshadowed (closed form, no rays) | shadowed (visibility by ray casting) | interreflection (shadowed "
       "plus --bounces bounces of light between surfaces)",
       d.transport});
  add({"--samples", "N",
       "ray directions per vertex that a frame shows (every vertex without a camera), 1..16777216; fewer than the "
       "sample rule's minimum for --lmax and --sampler is warned about (" + SampleRuleText(Sampler::kFibonacci) + ")",
       d.samples ? std::to_string(d.samples)
                 : "follows --lmax and --sampler, e.g. fibonacci " + std::to_string(DefaultSamples(2, Sampler::kFibonacci)) +
                       " at lmax 2"});
  add({"--hidden-samples", "N",
       "ray directions per vertex the camera does not see (facing away or behind other surfaces in every "
       "frame), 1..16777216: they show only through the light they bounce; not used with --vertex-radiance, which "
       "writes every vertex",
       d.hidden_samples ? std::to_string(d.hidden_samples)
                        : "the sample rule's, e.g. fibonacci " + std::to_string(DefaultHiddenSamples(2, Sampler::kFibonacci)) +
                              " at lmax 2, at most --samples"});
  add({"--sampler", "NAME", "fibonacci (spherical Fibonacci) | stratified (the course's jittered grid) | uniform",
       d.sampler});
  add({"--bounces", "B", "interreflection bounces, 1..1000 (stops early once negligible)", std::to_string(d.bounces)});
  add({"--direction-sets", "K",
       "independent direction sets the vertices draw from, 1..1024: many give independent per-vertex noise, 1 "
       "gives smooth, correlated error",
       std::to_string(d.direction_sets)});
  add({"--albedo", "R,G,B", "override the material colour, each channel in [0, 1] (on a textured mesh, its textures too)",
       albedo});
  add({"--texture", "FILE",
       "one albedo texture for every face of --mesh, by its texture coordinates (png/jpg as sRGB, hdr/exr "
       "linear); it replaces the materials' Kd and map_Kd",
       d.texture.empty() ? "each material's map_Kd (relative to its .mtl); Kd without one" : d.texture});
  add({"--material", "M",
       "diffuse: f = albedo/pi | phong:N[,KS]: f = albedo/pi + KS (N+2)/(2 pi) max(0, r.s)^N, r the view direction "
       "mirrored about the normal, s the light direction, N an integer 1..1000, KS 0..1 (default 0.5); the "
       "outgoing radiance is the integral of L V f max(0, n.s); albedo + KS must not exceed 1 (a texture's "
       "texels above 1 - KS are scaled down to it)",
       d.material.Name()});
  add({"--seed", "S", "random seed; the same seed gives the same bytes for any --threads", std::to_string(d.seed)});
  add({"--threads", "N", "worker threads, 1..1024; results do not depend on it",
       d.threads ? std::to_string(d.threads) : "all cores"});
  add({"--games202-faces", "",
       "read cubemaps with the course's face mapping and pow(x, 2.2) decoding, to reproduce its published "
       "light.txt files (which have up and down swapped)",
       ""});
  add({"--window", "W",
       "none | hann | lanczos | auto: SH windowing against ringing (auto: the least blurring window whose "
       "reconstruction is non-negative; render and demo choose it by default where the irradiance, a glossy "
       "lobe's light or --view light would go negative)",
       d.window == kDefaultWindow ? "auto where the frames would show ringing, else none" : d.window});
  add({"--max-edge", "L",
       "split triangles until no edge is longer than L world units (`2%`: 2 % of the bounding-box diagonal), so "
       "per-vertex transport can show shadows inside large triangles",
       d.max_edge > 0 ? Formatted("%g", double(d.max_edge)) + (d.max_edge_relative ? "%" : "") : "none"});
  add({"--basis", "B", BasisHelp(), d.basis->Name()});
  for (const Basis* b : Bases())
    for (OptionSpec o : b->OwnOptions()) add(std::move(o));
  return s;
}

/// "did you mean PATH? " for the existing path nearest to `path` (NearestPath), or "".
std::string DidYouMean(const std::string& path) {
  const std::string near = NearestPath(path);
  return near.empty() ? "" : "did you mean " + near + "? ";
}

/// Refuses --mesh and --env values that name nothing or cannot be read, before any of them is
/// loaded: the mesh file exists; a cubemap folder has its six faces, square and of one size (from
/// their headers); an image file is not one face of a cubemap (RefuseCubemapFace); a built-in's
/// parameters parse. A path that does not exist is a failure (exit
/// 1); a malformed built-in is a usage error (exit 2), an unknown one names the nearest.
void CheckInputs(Args& args, const SceneOptions& o) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!o.mesh.empty()) {
    if (!fs::exists(o.mesh, ec)) throw Error(o.mesh + ": no such file (" + DidYouMean(o.mesh) + "expected an OBJ mesh for --mesh)");
    if (fs::is_directory(o.mesh, ec)) throw Error(o.mesh + ": is a directory (expected an OBJ file for --mesh)");
  }
  if (!o.texture.empty()) {
    if (o.mesh.empty()) args.Fail("--texture: needs --mesh (an OBJ with texture coordinates; the demo scene has none)");
    if (o.albedo) args.Fail("--texture and --albedo both set the albedo (expected one of them)");
    if (!fs::exists(o.texture, ec))
      throw Error(o.texture + ": no such file (" + DidYouMean(o.texture) + "expected an image for --texture)");
    int width = 0, height = 0;
    ImageSize(o.texture, width, height);  // exists, is an image, and of a size prt accepts
  }
  if (fs::is_directory(o.env, ec)) {
    CheckCubemapFolder(o.env);
    return;
  }
  if (fs::exists(o.env, ec)) {
    RefuseCubemapFace(o.env);  // an image file: its header is read when it is loaded
    return;
  }
  const std::string name = o.env.substr(0, o.env.find(':'));
  const auto& builtins = BuiltinEnvironmentNames();
  if (std::find(builtins.begin(), builtins.end(), name) == builtins.end()) {
    const std::string near = NearestName(name, builtins);
    if (o.env.find_first_of("/.") != std::string::npos || near.empty())
      throw Error(o.env + ": no such file, folder or built-in environment (" + DidYouMean(o.env) +
                  "expected a cubemap folder, an equirectangular .hdr/.exr/.png/.jpg file, or one of furnace, sky)");
    args.Fail("--env: '" + o.env + "': no such file, folder or built-in environment (did you mean " + near + "?)");
  }
  try {
    ParseBuiltinEnvironment(o.env);
  } catch (const Error& e) {
    args.Fail(std::string("--env: ") + e.what());
  }
}

/// The direction count of the sample rule when none was given; a warning when the one given is
/// below the rule's minimum and the transport casts rays (unshadowed is closed form).
void ResolveSamples(Args& args, SceneOptions& o) {
  const Sampler sampler = SamplerFromName(o.sampler);
  const bool given = args.Has("--samples");
  if (!given && o.samples == 0) {
    o.samples = DefaultSamples(o.lmax, sampler);
    o.samples_from_rule = true;
  }
  if (o.hidden_samples == 0) o.hidden_samples = std::min(o.samples, DefaultHiddenSamples(o.lmax, sampler));
  if (!given) return;
  const int minimum = MinimumSamples(o.lmax, sampler);
  if (o.transport != "unshadowed" && o.samples < minimum)
    Warn("--samples " + std::to_string(o.samples) + " is below the " + std::to_string(minimum) + " " + o.sampler +
         " directions per vertex that lmax " + std::to_string(o.lmax) +
         " needs for its sampling error to stay under its SH truncation error: shadows will be blotchy (raise "
         "--samples to at least " + std::to_string(minimum) + ", or leave it out for the default " +
         std::to_string(DefaultSamples(o.lmax, sampler)) + ")");
}

/// Warns when the bands up to lmax keep less than kLobeShareWarning of a glossy lobe's energy: its
/// highlight will be as broad as the bands, not as the lobe.
void WarnIfLobeTooSharp(const SceneOptions& o) {
  if (!o.material.glossy) return;
  const double share = LobeBandShare(o.material.lobe, o.lmax);
  if (share >= kLobeShareWarning) return;
  const int needed = LmaxForShare(o.material.lobe, kLobeShareWarning, kMaxLmax);
  Warn("--material " + o.material.Name() + Formatted(": bands 0..%d keep %.0f%% of the lobe's energy", o.lmax, 100.0 * share) +
       ", so highlights come out as broad as lmax " + std::to_string(o.lmax) + " allows, not as sharp as N = " +
       std::to_string(o.material.lobe.exponent) + " (lmax " + std::to_string(needed) + " keeps " +
       Formatted("%.0f%%", 100.0 * kLobeShareWarning) + "; the rule of thumb lmax ~ sqrt(N) says " +
       std::to_string(int(std::lround(std::sqrt(double(o.material.lobe.exponent))))) + ")");
}

}  // namespace

const std::vector<std::string>& AllSceneOptionNames() {
  static std::vector<std::string> names = {
      "--mesh",    "--env",          "--lmax",   "--tolerance", "--transport",      "--samples",
      "--hidden-samples", "--sampler", "--bounces",      "--direction-sets",        "--albedo",         "--texture", "--material", "--seed",
      "--threads", "--games202-faces", "--window", "--max-edge", "--basis"};
  static const bool own = [] {  // then every basis's own options, in list order
    for (const Basis* b : Bases())
      for (const OptionSpec& o : b->OwnOptions()) names.push_back(o.name);
    return true;
  }();
  (void)own;
  return names;
}

const std::vector<std::string>& LightOptionNames() {
  static const std::vector<std::string> names = {"--env", "--lmax", "--tolerance", "--window",
                                                 "--games202-faces", "--threads"};
  return names;
}

OptionGroup SceneOptionGroup(const SceneOptions& defaults, const std::vector<std::string>& names,
                             const std::string& title) {
  return PickOptions(SceneSpecs(defaults), names, title);
}

SceneOptions ReadSceneOptions(Args& args, const SceneOptions& d) {
  SceneOptions o = d;
  const auto has = [&args](const char* name) { return args.Accepts(name); };
  if (has("--mesh")) o.mesh = args.String("--mesh", d.mesh);
  if (has("--texture")) o.texture = args.String("--texture", d.texture);
  if (has("--env")) o.env = args.String("--env", d.env);
  if (has("--tolerance")) o.tolerance = args.Double("--tolerance", d.tolerance, 1e-12, 1.0);
  if (has("--lmax")) {
    const std::string text = args.String("--lmax", std::to_string(d.lmax));
    if (text == "auto") {
      o.lmax_auto = true;
    } else {
      const auto v = ParseNumber(text);
      if (!v || *v != std::floor(*v) || *v < 0 || *v > d.max_lmax)
        args.Fail("--lmax: " + NumberProblem(text, true, "an integer from 0 to " + std::to_string(d.max_lmax) + ", or auto"));
      o.lmax = static_cast<int>(*v);
    }
  }
  if (has("--transport"))
    o.transport = args.Choice("--transport", d.transport, TransportModeNames());
  if (has("--samples")) o.samples = args.Int("--samples", d.samples, 1, 1 << 24);
  if (has("--hidden-samples")) o.hidden_samples = args.Int("--hidden-samples", d.hidden_samples, 1, 1 << 24);
  if (has("--sampler")) o.sampler = args.Choice("--sampler", d.sampler, SamplerNames());
  if (has("--bounces")) o.bounces = args.Int("--bounces", d.bounces, 1, 1000);
  if (has("--direction-sets")) o.direction_sets = args.Int("--direction-sets", d.direction_sets, 1, 1024);
  if (has("--albedo")) {
    if (auto albedo = args.Vec3("--albedo")) {
      for (int c = 0; c < 3; ++c)
        if ((*albedo)[c] < 0.0 || (*albedo)[c] > 1.0)
          args.Fail("--albedo: '" + *args.String("--albedo") + "' is out of range (expected R,G,B, each from 0 to 1)");
      o.albedo = albedo;
    }
  }
  if (has("--material")) {
    if (const auto text = args.String("--material")) {
      try {
        o.material = ParseMaterial(*text);
      } catch (const Error& e) {
        args.Fail(std::string("--material: ") + e.what());
      }
    }
    if (o.albedo) {
      try {
        CheckMaterialEnergy(o.material, std::max({o.albedo->x, o.albedo->y, o.albedo->z}), "--albedo");
      } catch (const Error& e) {
        args.Fail(e.what());
      }
    }
  }
  if (has("--seed")) {
    if (const auto text = args.String("--seed")) {
      const auto v = ParseNumber(*text);
      if (!v || *v != std::floor(*v) || *v < 0 || *v > 9007199254740992.0)
        args.Fail("--seed: " + NumberProblem(*text, true, "an integer from 0 to 2^53"));
      o.seed = static_cast<std::uint64_t>(*v);
    }
  }
  if (has("--threads")) o.threads = args.Int("--threads", d.threads, 1, 1024);
  if (has("--games202-faces") && args.Flag("--games202-faces")) o.layout = CubeLayout::kGames202;
  if (has("--window") && args.Has("--window"))  // not given: the default stays, kDefaultWindow included
    o.window = args.Choice("--window", d.window, {"none", "hann", "lanczos", "auto"});
  if (has("--max-edge")) {
    if (const auto text = args.String("--max-edge")) {
      const bool relative = text->back() == '%';
      const std::string number = relative ? text->substr(0, text->size() - 1) : *text;
      const auto v = ParseNumber(number);
      if (!v || !(*v > 0.0) || (relative && *v > 100.0))
        args.Fail("--max-edge: '" + *text + "' " + (v ? "is out of range" : "is not a number") +
                  " (expected a length > 0, or a percentage of the bounding-box diagonal such as 2%, at most 100%)");
      o.max_edge = relative ? *v / 100.0 : *v;
      o.max_edge_relative = relative;
    }
  }
  if (has("--basis")) o.basis = FindBasis(args.Choice("--basis", d.basis->Name(), BasisNames()));
  o.basis_options = BasisOptionSet::Read(args);
  if (!o.basis->Traits().glossy && o.material.glossy)
    args.Fail("--basis " + o.basis->Name() + ": glossy materials are not built in the " + o.basis->Name() +
              " basis (--material " + o.material.Name() + "); use --basis " + DefaultBasis()->Name() +
              ", or --material diffuse");
  BasisOptionSet::RefuseOthers(args, *o.basis);
  SetQuiet(args.Flag("--quiet"));
  SetThreadCount(o.threads);
  CheckInputs(args, o);
  if (o.lmax_auto) {
    // Measured on the environment itself, loaded here once: the command takes it from here
    // (LoadSceneEnvironment).
    o.loaded_env = LoadEnvironment(o.env, o.layout);
    o.loaded_env_spec = o.env;
    o.loaded_env_layout = o.layout;
    const AutoLmax choice = ChooseLmax(*o.loaded_env, o.tolerance, kMaxLmax);
    o.lmax = choice.lmax;
    Summary(choice.why);
  }
  // A basis may take its own lmax when none is given (the wavelets' bounces: wavelet/wavelet_basis.cpp).
  if (o.basis->Lmax() >= 0 && !args.Has("--lmax") && !o.lmax_auto) {
    o.lmax = o.basis->Lmax();
    o.lmax_why = o.basis->LmaxWhy();
  }
  ResolveSamples(args, o);
  if (has("--lmax")) WarnIfLobeTooSharp(o);  // commands without bands (reference) have nothing to warn of
  return o;
}

TransportOptions TransportOptionsOf(const SceneOptions& options) {
  TransportOptions t;
  t.material = options.material;
  t.mode = TransportModeFromName(options.transport);
  t.lmax = options.lmax;
  t.samples = options.samples;
  t.hidden_samples = options.hidden_samples;
  t.sampler = SamplerFromName(options.sampler);
  t.bounces = options.bounces;
  t.seed = options.seed;
  t.direction_sets = options.direction_sets;
  return t;
}

double MaxEdgeLength(const SceneOptions& options, double diagonal) {
  return options.max_edge_relative ? options.max_edge * diagonal : options.max_edge;
}

}  // namespace prt
