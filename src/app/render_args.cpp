#include "app/render_args.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include <glm/geometric.hpp>

#include <fcntl.h>
#include <unistd.h>

#include "app/render_video.h"
#include "bases/list.h"
#include "core/atomic_file.h"  // WriteProblem
#include "core/error.h"
#include "core/output_folder.h"
#include "core/text.h"
#include "options/option_table.h"
#include "raster/camera.h"
#include "raster/rasterizer.h"
#include "render/frame_limits.h"
#include "render/render_frames.h"
#include "sh/coeffs.h"
#include "video/apng_writer.h"
#include "video/ffmpeg_encoder.h"

namespace prt {
namespace {

/// The --view value of `o` as the command line writes it (transport:K with its index).
std::string ViewText(const RenderOptions& o) {
  return o.view == View::kTransport ? "transport:" + std::to_string(o.transport_index) : ViewName(o.view);
}

/// --cache's default: each basis's file in the output folder, the default's first.
std::string CacheDefaultText() {
  std::string text;
  for (const Basis* b : Bases())
    text += text.empty() ? "DIR/" + b->CacheName() : "; DIR/" + b->CacheName() + " with --basis " + b->Name();
  return text;
}

std::map<std::string, OptionSpec> RenderSpecs(const RenderJobOptions& job) {
  const RenderOptions& d = job.draw;
  const RenderOptions demo = WithDemoCamera({});  // the embedded scene's camera
  std::map<std::string, OptionSpec> s;
  auto add = [&s](OptionSpec o) { s[o.name] = std::move(o); };
  add({"--frames", "N", "frames over the turns, 1..100000 (frame i shows the light turned by 360 * turns * i / N degrees)",
       std::to_string(d.frames)});
  add({"--size", "WxH", "frame size in pixels, each " + std::to_string(kMinFrameSide) + ".." + std::to_string(kMaxFrameSide), std::to_string(d.width) + "x" + std::to_string(d.height)});
  add({"--out", "DIR",
       "output folder, created if missing; one run at a time; after a successful run it holds this run's outputs, "
       "and what earlier runs of this command wrote and this one did not is removed (other commands' outputs and "
       "files prt did not write are never touched)",
       job.out.empty() ? "required" : job.out});
  add(ReplaceOption());
  add({"--axis", "X,Y,Z", "rotation axis of the light", VecText(d.axis) + ", world up"});
  add({"--turns", "T", "full turns of the light over all frames, -1e6..1e6", Formatted("%g", double(d.turns))});
  add({"--start-angle", "DEGREES",
       "the light's turn about the axis at frame 0, -1e6..1e6 (frame i: DEGREES + 360 * turns * i / N); prt view's "
       "command line uses it to start a sequence where the page left the light",
       Formatted("%g", d.start_degrees)});
  add({"--background", "B", "env | black | R,G,B (linear, each >= 0): env draws the environment, turning with the light",
       d.env_background ? "env" : "black"});
  add({"--tonemap", "T", "srgb (clamp) | reinhard | aces (a filmic curve that keeps bright suns from clipping)",
       ToneCurveName(d.tonemap)});
  add({"--exposure", "EV",
       "radiance is scaled by 2^EV before tone mapping, -20..20; auto: chosen from frame 0's mesh pixels and "
       "printed on the run summary, so a run can be repeated exactly",
       d.exposure ? Formatted("%g", double(*d.exposure)) : "auto"});
  add({"--ssaa", "K", "K x K supersampling per pixel, 1..8", std::to_string(d.ssaa)});
  add({"--view", "V",
       "radiance | irradiance | albedo | transport:K | light | glossy: the final colour; the lighting alone (albedo 1); "
       "the albedo; the K-th transport coefficient in false colour with a legend, on a grey background; the "
       "light as the basis keeps it (on the mesh: in the normal's direction; no transport is computed for it); a "
       "glossy material's lobe term alone (the highlights, without the diffuse part)",
       ViewText(d)});
  add({"--eye", "X,Y,Z", "camera position",
       d.eye ? VecText(*d.eye)
             : "a three-quarter view fitted to the mesh's projected bounds; " + VecText(*demo.eye) + " for the embedded scene"});
  add({"--target", "X,Y,Z", "point the camera looks at (the image centre)",
       d.target ? VecText(*d.target)
                : "fitted with --eye; the mesh's centre when only --eye is given; " + VecText(*demo.target) +
                      " for the embedded scene"});
  add({"--up", "X,Y,Z",
       "camera up direction (when the default 0,1,0 is parallel to the view, a perpendicular one is chosen and "
       "printed)",
       d.up ? VecText(*d.up) : "0,1,0"});
  add({"--fov", "DEGREES", "vertical field of view, 0.001..179", d.fov ? Formatted("%g", double(*d.fov))
             : Formatted("%g; %g for the embedded scene", double(Camera{}.fov_deg), *demo.fov)});
  add({"--orbit", "DEGREES",
       "the camera turns this many degrees about the target (around its up direction) over the frames, "
       "-1e6..1e6; a glossy --material then uses transfer matrices, so highlights follow the view",
       Formatted("%g", d.orbit)});
  add({"--cpca", "C,K|off",
       "a glossy --orbit's transfer matrices compressed by clustered PCA: C clusters (1..65536), each a mean and K "
       "principal matrices (0..(lmax+1)^4), each vertex K weights; the run summary says the memory and the error "
       "measured; off: the full matrices",
       job.cpca.clusters > 0 ? std::to_string(job.cpca.clusters) + "," + std::to_string(job.cpca.terms) : "off"});
  add({"--vertex-radiance", "FILE",
       "write frame 0's per-vertex linear RGB radiance toward the camera (its light turned by --start-angle; albedo "
       "in, before tone mapping) in transport.txt's layout: the welded vertex count, then three `R G B` rows per "
       "face of the mesh as read in file order, one per corner (with --max-edge, the corners of the faces before "
       "the split; the vertices it adds are not written)",
       job.vertex_radiance.empty() ? "none" : job.vertex_radiance});
  add({"--video", "FILE",
       "the frames also as one video: .png or .apng an animated PNG that loops (written by prt, plays in every "
       "browser), .mp4 H.264 or .webm VP9 through Debian's ffmpeg program; written when the run succeeds, like the "
       "frames",
       job.video.path.empty() ? "none" : job.video.path});
  add({"--fps", "F", "frames per second of --video, 0.1..240 (at most 90 for an animated PNG)",
       Formatted("%g", job.video.fps)});
  add({"--cache", "PATH",
       "transport cache to reuse and update, so a re-run with the same mesh and options skips the precompute; "
       "`none` disables it; a path that cannot be used is a warning, not an error",
       job.cache.empty() ? CacheDefaultText() : job.cache});
  return s;
}

/// WxH, each from kMinFrameSide to kMaxFrameSide (640x480 or 640X480).
void ReadSize(Args& args, RenderOptions& o) {
  const auto size = args.String("--size");
  if (!size) return;
  const auto x = size->find_first_of("xX");
  // No separator: the height is read from "", which is no number.
  const auto w = ParseNumber(size->substr(0, x)), h = ParseNumber(x == std::string::npos ? "" : size->substr(x + 1));
  const std::string expected =
      " (expected WxH, each from " + std::to_string(kMinFrameSide) + " to " + std::to_string(kMaxFrameSide) + ")";
  if (!w || !h || std::floor(*w) != *w || std::floor(*h) != *h) args.Fail("--size: '" + *size + "' is not a size" + expected);
  if (*w < kMinFrameSide || *h < kMinFrameSide || *w > kMaxFrameSide || *h > kMaxFrameSide)
    args.Fail("--size: '" + *size + "' is out of range" + expected);
  o.width = static_cast<int>(*w), o.height = static_cast<int>(*h);
}

void ReadBackground(Args& args, RenderOptions& o, const RenderOptions& d) {
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
      args.Fail("--background: '" + bg + "' (expected env, black or R,G,B with each >= 0)");
    o.env_background = false, o.background_color = glm::vec3(c);
  }
}

void ReadView(Args& args, RenderOptions& o, const RenderOptions& d) {
  const std::string view = args.String("--view", ViewText(d));
  if (view.rfind("transport:", 0) == 0) {
    const std::string k = view.substr(10);
    char* end = nullptr;
    const long index = std::strtol(k.c_str(), &end, 10);
    if (k.empty() || *end != '\0' || index < 0 || index >= CoeffCount(kMaxLmax))
      args.Fail("--view: '" + view + "' is not a coefficient index (expected transport:K with K an integer from 0)");
    o.view = View::kTransport, o.transport_index = static_cast<int>(index);
  } else if (const auto v = ViewFromName(view); v && *v != View::kTransport) {
    o.view = *v;
  } else {
    // The views' own words: `transport` is offered as transport:K, and never suggested bare.
    const std::vector<std::string> names = ViewNames();
    std::vector<std::string> whole;
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const bool transport = names[i] == ViewName(View::kTransport);
      if (!transport) whole.push_back(names[i]);
      list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i] + (transport ? ":K" : "");
    }
    const std::string near = NearestChoice(view, whole);
    args.Fail("--view: unknown value '" + view + "' (" + (near.empty() ? "" : "did you mean " + near + "? ") +
              "expected " + list + ")");
  }
}

/// The camera options, checked on their own: a zero --up, --eye equal to --target, and an
/// explicit --up along an explicit view are errors; a default up along the view is not (it is
/// replaced when the camera is built, raster/camera.h).
void ReadCamera(Args& args, RenderOptions& o) {
  if (auto v = args.Vec3("--eye")) o.eye = v;
  if (auto v = args.Vec3("--target")) o.target = v;
  if (auto v = args.Vec3("--up")) {
    if (glm::length(*v) < 1e-12) args.Fail("--up: '" + *args.String("--up") + "' is zero (expected a direction, such as 0,1,0)");
    o.up = v;
  }
  if (args.Has("--fov")) o.fov = args.Double("--fov", 35.0, kMinFov, kMaxFov);
  if (args.Has("--eye") && args.Has("--target")) {
    const glm::dvec3 view = *o.target - *o.eye;
    if (glm::length(view) < 1e-12) args.Fail("--eye: equals --target (expected two different points)");
    if (args.Has("--up") && glm::length(glm::cross(glm::normalize(view), glm::normalize(*o.up))) < 1e-6)
      args.Fail("--up: parallel to the view direction --target - --eye (expected a direction across it)");
  }
}

}  // namespace

void ReadCpca(Args& args, CpcaOptions& o) {
  const auto text = args.String("--cpca");
  if (!text) return;
  if (*text == "off") {
    o.clusters = 0;
    return;
  }
  const auto comma = text->find(',');
  const auto c = ParseNumber(text->substr(0, comma));
  const auto k = comma == std::string::npos ? std::nullopt : ParseNumber(text->substr(comma + 1));
  if (!c || !k || std::floor(*c) != *c || std::floor(*k) != *k || *c < 1 || *c > 65536 || *k < 0 || *k > 40401.0 * 40401.0)
    args.Fail("--cpca: '" + *text + "' (expected C,K with C clusters from 1 to 65536 and K terms from 0, or off)");
  o.clusters = int(*c), o.terms = int(std::min(*k, 1e9));
}

void CheckCpcaTerms(Args& args, const CpcaOptions& o, int lmax) {
  const long long dim = (long long)CoeffCount(lmax) * CoeffCount(lmax);
  if (o.clusters > 0 && o.terms > dim)
    args.Fail("--cpca: " + std::to_string(o.terms) + " terms is more than the " + std::to_string(dim) +
              " numbers of a transfer matrix at lmax " + std::to_string(lmax) + " (expected K from 0 to " +
              std::to_string(dim) + ")");
}

bool IsFolderOwnName(const std::string& file, const RenderJobOptions& o) {
  const std::string name = std::filesystem::path(file).filename().string();
  if (LiesIn(file, o.out) && (IsFrameName(name, true) || name.rfind(".prt", 0) == 0)) return true;
  if (o.cache == "none") return false;
  if (!o.cache.empty()) return ResolvedPath(file) == ResolvedPath(o.cache);
  // Every basis's cache in the folder: a run of one keeps the others' (render_job.cpp).
  for (const Basis* basis : Bases())
    if (ResolvedPath(file) == ResolvedPath(o.out + "/" + basis->CacheName())) return true;
  return false;
}

bool HasControlCharacter(const std::string& file) {
  for (unsigned char c : file)
    if (c < 0x20 || c == 0x7f) return true;
  return false;
}

const std::vector<std::string>& AllRenderOptionNames() {
  static const std::vector<std::string> names = {
      "--frames", "--size",     "--out",  "--replace", "--axis", "--turns", "--start-angle", "--background", "--tonemap", "--exposure",
      "--ssaa",   "--view",     "--eye",  "--target", "--up",   "--fov",        "--orbit", "--cpca",
      "--vertex-radiance", "--video", "--fps", "--cache"};
  return names;
}

OptionGroup RenderOptionGroup(const RenderJobOptions& defaults, const std::vector<std::string>& names,
                              const std::string& title) {
  return PickOptions(RenderSpecs(defaults), names, title);
}

RenderJobOptions ReadRenderOptions(Args& args, const RenderJobOptions& job_defaults) {
  RenderJobOptions job = job_defaults;
  const RenderOptions& d = job_defaults.draw;
  RenderOptions& o = job.draw;
  const auto has = [&args](const char* name) { return args.Accepts(name); };
  if (has("--frames")) o.frames = args.Int("--frames", d.frames, 1, 100000);
  if (has("--size")) ReadSize(args, o);
  if (has("--out")) job.out = args.String("--out", job_defaults.out);
  if (has("--replace")) job.replace = args.Flag("--replace");
  if (has("--axis")) {
    if (const auto axis = args.Vec3("--axis")) {
      if (glm::length(*axis) < 1e-12)
        args.Fail("--axis: '" + *args.String("--axis") + "' is zero (expected a direction, such as 0,1,0)");
      o.axis = *axis;
    }
  }
  if (has("--turns")) o.turns = args.Double("--turns", d.turns, -1e6, 1e6);
  if (has("--start-angle")) o.start_degrees = args.Double("--start-angle", d.start_degrees, -kMaxAngle, kMaxAngle);
  if (has("--background")) ReadBackground(args, o, d);
  if (has("--tonemap")) {
    const std::string curve = args.Choice("--tonemap", ToneCurveName(d.tonemap), ToneCurveNames());
    o.tonemap = *ParseToneCurve(curve);
  }
  if (has("--exposure")) {
    const auto text = args.String("--exposure");
    if (text && *text == "auto") {
      o.exposure.reset();
    } else if (text) {
      const auto v = ParseNumber(*text);
      if (!v || *v < -kMaxExposure || *v > kMaxExposure)
        args.Fail("--exposure: " + NumberProblem(*text, false, "a number from -20 to 20, or auto"));
      o.exposure = *v;
    }
  }
  if (has("--ssaa")) o.ssaa = args.Int("--ssaa", d.ssaa, 1, kMaxSsaa);
  if (static_cast<long long>(o.width) * o.ssaa > kMaxTargetSide || static_cast<long long>(o.height) * o.ssaa > kMaxTargetSide)
    args.Fail("--ssaa: " + std::to_string(o.ssaa) + " times the frame size exceeds " + std::to_string(kMaxTargetSide) +
              " samples per side (expected a smaller --ssaa or --size)");
  if (has("--view")) ReadView(args, o, d);
  if (has("--eye")) ReadCamera(args, o);
  if (has("--cache")) job.cache = args.String("--cache", job_defaults.cache);
  if (has("--orbit")) o.orbit = args.Double("--orbit", d.orbit, -1e6, 1e6);
  if (has("--cpca")) ReadCpca(args, job.cpca);
  if (has("--vertex-radiance") && args.Has("--vertex-radiance")) {
    job.vertex_radiance = args.String("--vertex-radiance", job_defaults.vertex_radiance);
    // Checked now, not after the precompute: the folder exists and takes new files.
    namespace fs = std::filesystem;
    std::error_code ec;
    const std::string& file = job.vertex_radiance;
    const std::string expected = " (expected a file name in a writable folder for --vertex-radiance)";
    if (file.empty()) args.Fail("--vertex-radiance: an empty name" + expected);
    if (HasControlCharacter(file))
      args.Fail("--vertex-radiance: the name has a control character (a newline, a tab)" + expected);
    if (IsFolderOwnName(file, job))
      args.Fail("--vertex-radiance: '" + file + "' is the name of one of the run's own files (a frame, the transport "
                "cache or prt's own .prt-* files; expected another name, such as radiance.txt)");
    if (fs::is_directory(file, ec)) throw Error(file + ": is a folder" + expected);
    fs::path dir = fs::path(file).parent_path();
    if (dir.empty()) dir = ".";
    if (!fs::is_directory(dir, ec)) throw Error(file + ": folder '" + dir.string() + "' does not exist" + expected);
    // A probe file, not access(): root passes access() on folders that take no files (/proc).
    const std::string probe = (dir / (".prt-probe-" + std::to_string(::getpid()))).string();
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) throw Error(file + ": " + WriteProblem(file, errno) + expected);
    ::close(fd);
    ::unlink(probe.c_str());
  }
  ReadVideoOptions(args, job, job_defaults);
  return job;
}

RenderJobOptions CompleteRenderOptions(Args& args, RenderJobOptions job, const SceneOptions& scene) {
  RenderOptions& o = job.draw;
  // A file the run writes must not be one it reads.
  const std::pair<const char*, const std::string*> written[] = {{"--video", &job.video.path},
                                                                {"--vertex-radiance", &job.vertex_radiance}};
  for (const auto& [option, file] : written)
    for (const std::string& input : {scene.mesh, scene.texture, scene.env})
      if (!file->empty() && !input.empty() && std::filesystem::exists(input) && SameFile(*file, input))
        args.Fail(std::string(option) + ": '" + *file + "' is an input of this run (expected another name: the run would "
                  "replace " + input + ")");
  if (o.view == View::kTransport && !scene.basis->Traits().coefficient_view)
    args.Fail("--view transport: shows one SH transfer coefficient per vertex; --basis " + scene.basis->Name() +
              " has none (expected --basis " + DefaultBasis()->Name() + ", or another view such as light)");
  if (o.view == View::kTransport && o.transport_index >= CoeffCount(scene.lmax))
    args.Fail("--view: transport:" + std::to_string(o.transport_index) + " is out of range (expected 0 to " +
              std::to_string(CoeffCount(scene.lmax) - 1) + " for lmax " + std::to_string(scene.lmax) + ")");
  CheckCpcaTerms(args, job.cpca, scene.lmax);
  if (scene.mesh.empty()) {
    // The embedded scene: each camera value not given is the demo's (help promises them one by
    // one), so --fov 50 alone widens the demo's view instead of refitting the camera.
    const RenderOptions demo = WithDemoCamera(o);
    if (!o.eye) o.eye = demo.eye;
    if (!o.target) o.target = demo.target;
    if (!o.fov) o.fov = demo.fov;
    if (glm::length(*o.target - *o.eye) < 1e-12)
      args.Fail(std::string(args.Has("--eye") ? "--eye" : "--target") +
                ": equals the embedded scene's camera " +
                (args.Has("--eye") ? "target " + VecText(*demo.target) : "eye " + VecText(*demo.eye)) +
                " (expected two different points)");
    if (args.Has("--up") && glm::length(glm::cross(glm::normalize(*o.target - *o.eye), glm::normalize(*o.up))) < 1e-6)
      args.Fail("--up: parallel to the view direction --target - --eye (expected a direction across it)");
  }
  return job;
}

namespace {

/// True if `file` names an output the run writes itself: a frame or a file of prt's own in the
/// output folder, the transport cache, the --vertex-radiance file.
bool IsRunOutputName(const std::string& file, const RenderJobOptions& o) {
  return IsFolderOwnName(file, o) ||
         (!o.vertex_radiance.empty() && ResolvedPath(file) == ResolvedPath(o.vertex_radiance));
}

}  // namespace

void ReadVideoOptions(Args& args, RenderJobOptions& job, const RenderJobOptions& job_defaults) {
  namespace fs = std::filesystem;
  VideoOptions& o = job.video;
  const VideoOptions& d = job_defaults.video;
  const RenderOptions& draw = job.draw;
  if (!args.Accepts("--video")) return;
  const bool has_video = args.Has("--video");
  if (args.Has("--fps") && !has_video) args.Fail("--fps: sets the rate of --video, which is not given (expected --video FILE)");
  if (!has_video) return;
  o.path = args.String("--video", d.path);
  const std::string& v = o.path;
  if (HasControlCharacter(v))
    args.Fail("--video: the name has a control character (a newline, a tab) (expected a plain file name)");
  const auto format = VideoFormatOf(v);
  if (!format)
    args.Fail("--video: '" + v + "' has no video extension (expected .png or .apng for an animated PNG, .mp4 or .webm "
              "through ffmpeg)");
  o.fps = args.Double("--fps", d.fps, 0.1, 240.0);
  if (*format == VideoFormat::kApng && o.fps > kApngMaxFps)
    args.Fail("--fps: " + Formatted("%g", o.fps) + " is too fast for an animated PNG (expected at most " +
              Formatted("%g", kApngMaxFps) + ": browsers play frames of 10 ms or less at 10 frames per second)");
  if (*format == VideoFormat::kMp4 && (draw.width % 2 != 0 || draw.height % 2 != 0))
    args.Fail("--video: H.264 in '" + v + "' needs an even frame size, not " + std::to_string(draw.width) + "x" +
              std::to_string(draw.height) + " (expected even --size values, or a .png or .webm video)");
  if (IsRunOutputName(v, job))
    args.Fail("--video: '" + v + "' is the name of one of the run's own outputs (a frame, the transport cache or the "
              "--vertex-radiance file; expected another name, such as turn.png)");
  std::error_code ec;
  if (fs::is_directory(v, ec)) throw Error(v + ": is a folder (expected a file name for --video)");
  if (*format != VideoFormat::kApng)
    o.ffmpeg = FindFfmpeg(*format == VideoFormat::kMp4 ? FfmpegCodec::kH264Mp4 : FfmpegCodec::kVp9Webm, "--video " + v);
}

}  // namespace prt
