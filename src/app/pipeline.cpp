#include "app/pipeline.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <unistd.h>

#include "app/seen_ringing.h"
#include "core/atomic_file.h"  // WriteProblem
#include "core/error.h"
#include "core/log.h"
#include "core/memory.h"
#include "core/text.h"
#include "env/load_environment.h"
#include "precompute/bounce_senders.h"
#include "precompute/light.h"
#include "precompute/transfer_matrix.h"
#include "precompute_io/transport_cache.h"
#include "raster/exposure.h"
#include "sh/dering.h"
#include "sh/window.h"
#include "wavelet/transport_cache.h"

namespace prt {
namespace {

/// The share of the available memory the transfer matrices may take (the rest is for the mesh,
/// BVH, frames and the system).
constexpr double kMatrixMemoryShare = 0.6;

/// A vertex whose T_0 is below this share of the unoccluded T_0 sees (almost) no light: inside
/// an inside-out mesh only what leaks through holes in it, a few percent.
constexpr double kBlockedShare = 0.05;
/// Warn when more than this share of the vertices is blocked: a closed, right-way-out mesh on
/// its own has well under half of its vertices in full shadow.
constexpr double kBlockedWarnShare = 0.5;

void WarnIfMostlyBlocked(const Mesh& mesh, const Transport& transport, TransportMode mode) {
  if (mode == TransportMode::kUnshadowed || mesh.vertex_count() == 0) return;
  const double open_t0 = 0.28209479177387814;  // (A_0/pi) Y_00 = 1 * 1/(2 sqrt(pi))
  std::size_t blocked = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) blocked += transport.at(v, 0)[0] < kBlockedShare * open_t0;
  if (double(blocked) > kBlockedWarnShare * double(mesh.vertex_count()))
    Warn(std::to_string(blocked) + " of " + std::to_string(mesh.vertex_count()) +
         " vertices see almost no sky (less than 5% of an open one): is the mesh inside out (normals "
         "pointing inward) or enclosed? Check that faces wind counter-clockwise seen from outside and that "
         "normals point outward");
}

/// The run-summary line of a glossy material's fixed-view transfer: what was done and why it is
/// enough.
std::string GlossyLine(const TransportOptions& o, const TransportReport& r, const Transport& t) {
  if (o.matrices)
    return "material: " + o.material.Name() + ", transfer matrices for a view that moves: " +
           std::to_string(CoeffCount(o.lmax)) + "x" + std::to_string(CoeffCount(o.lmax)) + " per vertex" +
           (t.channels == 3 ? " and colour channel" : "") + " (" + ByteText(t.matrices.size() * sizeof(float)) +
           "), each frame's view applied by the lobe's zonal coefficients; they truncate the product of light, "
           "visibility and cosine to lmax before the lobe (prt report measures the difference from the "
           "fixed-camera vectors)" +
           (o.mode == TransportMode::kInterreflection ? "; blocked directions carry their hit points' light as diffuse surfaces" : "") +
           Formatted(" [%.3f s]", r.matrix_seconds);
  std::string line = "material: " + o.material.Name() +
                     ", fixed camera: one view-dependent transfer vector per vertex toward the eye (exact for the "
                     "band-limited light, the product of visibility, lobe and cosine not truncated; the camera does "
                     "not move, so no transfer matrices are needed); the lobe's unshadowed transfer by quadrature";
  if (o.mode != TransportMode::kUnshadowed)
    line += " minus what " + std::to_string(r.lobe_samples) + " lobe rays per vertex find blocked (" +
            std::to_string(r.lobe_rays) + " rays)";
  if (o.mode == TransportMode::kInterreflection)
    line += "; blocked lobe rays gather their hit points' light as diffuse surfaces (bounces up to B - 1 there)";
  return line + Formatted(" [%.3f s]", r.glossy_seconds);
}

/// Applies --window auto to `light`; its run-summary clause (sh/dering.h).
std::string ApplyAutoWindow(ShRgb& light) {
  const auto t0 = std::chrono::steady_clock::now();
  const AutoWindow choice = ChooseAutoWindow(light);
  ApplyWeights(choice.weights, light);
  return choice.Describe() + Formatted(" [%.3f s]", SecondsSince(t0));
}

/// kDefaultWindow for the frames of `view`: the auto window when they would show the light's
/// ringing (FindSeenRinging), else none; the run-summary clause ("" when nothing was checked).
std::string DefaultWindow(ShRgb& light, const SceneOptions& options, View view) {
  // A basis whose frames are not lit by the SH light (the wavelets: its SH light feeds only the
  // bounces) keeps the raw light. (kMaxLmax <= kMaxAutoWindowLmax: auto takes any lmax here.)
  static_assert(kMaxLmax <= kMaxAutoWindowLmax);
  if (!options.basis->windowed_light) return "";
  const auto t0 = std::chrono::steady_clock::now();
  const SeenRinging seen = FindSeenRinging(light, options.material, view);
  if (seen.what.empty()) return "";  // --view albedo or transport shows no light
  if (!seen.rings)
    return "; no window needed (" + seen.what + " stays non-negative" + Formatted(") [%.3f s]", SecondsSince(t0));
  const double share = seen.peak > 0 ? seen.lowest / seen.peak : 0.0;
  return "; window auto (default: " + seen.what + Formatted(" goes down to %.3g, %.3g%% of its peak", seen.lowest, 100.0 * share) +
         "; --window none keeps the raw light): " + ApplyAutoWindow(light);
}

}  // namespace

std::unique_ptr<Environment> LoadSceneEnvironment(const SceneOptions& options, OutputFolder* folder) {
  const auto t0 = std::chrono::steady_clock::now();
  auto env = LoadEnvironment(options.env, options.layout);
  std::error_code ec;
  if (folder && std::filesystem::exists(options.env, ec)) folder->KeepInput(options.env);  // not a built-in
  Summary("environment: " + env->Describe() + Formatted(" [%.3f s]", SecondsSince(t0)));
  return env;
}

ShRgb ComputeLight(const Environment& env, const SceneOptions& options, View view) {
  const auto t0 = std::chrono::steady_clock::now();
  ShRgb light = ProjectLight(env, options.lmax);
  std::string line = "light: lmax " + std::to_string(options.lmax) + " (" +
                     std::to_string(CoeffCount(options.lmax)) + " coefficients)" +
                     Formatted(" [%.3f s]", SecondsSince(t0));
  if (options.window == kDefaultWindow) {
    line += DefaultWindow(light, options, view);
  } else if (options.window == "auto") {
    line += "; window auto: " + ApplyAutoWindow(light);
  } else if (options.window != "none") {
    ApplyWindow(WindowFromName(options.window), light);
    line += "; window " + options.window;
  }
  Summary(line);
  return light;
}

Camera SceneCamera(const Mesh& mesh, const RenderOptions& render) {
  std::string up_note;
  const Camera camera = ChooseCamera(mesh, render, &up_note);
  Summary("camera: " + CameraArgs(camera) + (up_note.empty() ? "" : " (" + up_note + ")"));
  return camera;
}

void ReportAutoExposure(double ev, const std::string& what) {
  Summary(Formatted("exposure: auto -> %.1f EV, measured on %s (--exposure %.1f repeats it)", ev, what.c_str(), ev) +
          AutoExposureLimitNote(ev));
}

TransportOptions TransportOptionsOf(const SceneOptions& options, const std::optional<glm::dvec3>& eye) {
  TransportOptions t;
  t.material = options.material;
  t.eye = eye;
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

CachePlan PlanCache(const std::string& option, OutputFolder* folder, const std::string& name) {
  namespace fs = std::filesystem;
  if (option == "none") return {"", false};
  const bool given = !option.empty();
  if (!given && !folder) return {"", false};
  const std::string path = given ? option : folder->dir() + "/" + name;
  const std::string what = (given ? "--cache: " : "cache: ") + path + ": ";
  const auto skip = [&what](const std::string& why) {
    Warn(what + why + "; going on without the cache");
    return CachePlan{"", false};
  };
  std::error_code ec;
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  if (fs::is_directory(path, ec)) return skip("is a folder (expected a file name)");
  if (!fs::exists(dir, ec)) return skip("folder '" + dir.string() + "' does not exist");
  if (!fs::is_directory(dir, ec)) return skip("'" + dir.string() + "' is a file, not a folder");
  // What is there already is replaced only when it is prt's: a cache (however damaged) at any
  // path, anything prt listed at the output folder's own cache name; an empty --cache file.
  // Never a device, pipe or socket, never another file (a typo must not cost the user a file).
  const fs::file_status link = fs::symlink_status(path, ec);
  if (fs::exists(link)) {
    if (!fs::is_regular_file(fs::status(path, ec))) return skip("is not a regular file: left alone");
    // In the output folder, a file prt listed as its own may be replaced whatever it holds, an
    // unlisted one only if it is a cache; a --cache file if it is a cache or empty.
    const bool listed = !given && !folder->IsForeign(name);
    const bool cache = StartsLikeTransportCache(path) || StartsLikeWaveletCache(path);
    if (!listed && (!given || fs::file_size(path, ec) > 0) && !cache)
      return skip("exists and is not a prt transport cache: left as it is");
    if (fs::is_symlink(link)) {
      Warn(what + "is a symbolic link: the cache is read if it matches, but never replaced");
      return {path, false};
    }
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    Warn(what + WriteProblem(path, errno) + ": the cache is read if it matches, but not updated");
    return {path, false};
  }
  return {given ? path : folder->OutputInPlace(name), true};
}

namespace {

/// How many directions the transport's vertices took, for its summary line.
std::string DirectionsText(const SceneOptions& options, const TransportOptions& o, const TransportReport& r,
                           std::size_t vertices) {
  const std::string sampler = SamplerName(o.sampler);
  // One count when every vertex took it: no camera (precompute), or every vertex seen.
  if (r.hidden_directions == 0 || r.hidden_vertices == 0)
    return std::to_string(r.directions_per_vertex) + " " + sampler + " directions per vertex" +
           SamplesOrigin(options, o.seen.empty());
  return std::to_string(r.directions_per_vertex) + " " + sampler + " directions for each of the " +
         std::to_string(vertices - r.hidden_vertices) + " vertices the camera sees, " +
         std::to_string(r.hidden_directions) + " for the " + std::to_string(r.hidden_vertices) +
         " it does not" + SamplesOrigin(options);
}

}  // namespace

Transport ComputeSceneTransport(const Mesh& mesh, const SceneOptions& options, const CachePlan& cache,
                                const std::vector<std::uint8_t>& seen, const Camera* camera, bool matrices) {
  std::optional<glm::dvec3> eye;
  if (camera && !matrices) eye = glm::dvec3(camera->eye);
  TransportOptions topts = TransportOptionsOf(options, eye);
  topts.matrices = matrices && options.material.glossy;
  topts.seen = seen;  // used only where the two counts differ (direction_pool.h, the cache key)
  const std::uint64_t key = TransportKey(mesh, topts);
  std::string why;
  if (!cache.path.empty() && StartsLikeWaveletCache(cache.path)) {
    why = "a wavelet transport cache (--basis wavelet), not an SH one";  // the SH reader knows only its own
  } else if (!cache.path.empty()) {
    if (auto cached = ReadTransportCache(cache.path, key, why)) {
      Summary("transport: taken from the cache " + cache.path + " (same mesh and options)");
      cached->material = topts.material;
      WarnIfMostlyBlocked(mesh, *cached, topts.mode);
      return std::move(*cached);
    }
    // A transport with --samples at every vertex (what precompute writes) holds at least what
    // this one needs at every vertex: taken as it is.
    TransportOptions every = topts;
    every.seen.clear();
    const std::uint64_t every_key = TransportKey(mesh, every);
    std::string ignored;
    if (every_key != key) {
      if (auto cached = ReadTransportCache(cache.path, every_key, ignored)) {
        Summary("transport: taken from the cache " + cache.path + " (same mesh and options, with " +
                std::to_string(topts.samples) + " directions at every vertex, not only those the camera sees)");
        cached->material = topts.material;
        WarnIfMostlyBlocked(mesh, *cached, topts.mode);
        return std::move(*cached);
      }
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  TransportReport r;
  Transport transport = ComputeTransport(mesh, topts, &r);
  const double seconds = SecondsSince(t0);
  std::string line = std::string("transport: ") + TransportModeName(topts.mode) + ", lmax " +
                     std::to_string(topts.lmax) + Formatted(" [%.3f s]", seconds);
  if (topts.mode == TransportMode::kUnshadowed) {
    line += "; closed form at every vertex: no BVH, no rays";
  } else {
    line += Formatted("; BVH %.3f s; ", r.bvh_seconds) + DirectionsText(options, topts, r, mesh.vertex_count()) + ", " + std::to_string(r.rays) +
            " rays (none below the horizon); " + std::to_string(r.closed_form_vertices) + " of " +
            std::to_string(mesh.vertex_count()) + " vertices unoccluded, given the exact closed form";
  }
  Summary(line);
  if (topts.mode == TransportMode::kInterreflection) ReportBounces(r, transport.channels);
  if (topts.material.glossy) Summary(GlossyLine(topts, r, transport));
  WarnIfMostlyBlocked(mesh, transport, topts.mode);
  if (!cache.path.empty() && cache.write) {
    if (why != "no cache yet") Summary("cache: " + cache.path + " ignored (" + why + "), recomputed");
    try {
      WriteTransportCache(cache.path, transport, key);
    } catch (const Error& e) {
      Warn(std::string(e.what()) + "; the transport was computed but not cached");
    }
  }
  return transport;
}

void CheckMatrixMemory(const Mesh& mesh, const SceneOptions& options) {
  const int channels = TransportChannels(mesh, TransportModeFromName(options.transport));
  const std::uint64_t need = TransferMatrixBytes(mesh.vertex_count(), options.lmax, channels);
  const std::uint64_t available = AvailableMemoryBytes();
  const std::uint64_t budget = std::uint64_t(kMatrixMemoryShare * double(available));
  if (available == 0 || need <= budget) {
    Summary("transfer matrices: " + ByteText(need) + " for " + std::to_string(mesh.vertex_count()) + " vertices at lmax " +
            std::to_string(options.lmax) + (available ? " (" + ByteText(available) + " available)" : ""));
    return;
  }
  int fits = -1;
  while (fits + 1 <= options.lmax && TransferMatrixBytes(mesh.vertex_count(), fits + 1, channels) <= budget) ++fits;
  throw Error("--lmax " + std::to_string(options.lmax) + ": the transfer matrices would take " + ByteText(need) + " (" +
              std::to_string(mesh.vertex_count()) + " vertices x " + std::to_string(channels) + " x " +
              std::to_string(CoeffCount(options.lmax)) + "^2 floats), more than the " + ByteText(budget) +
              " prt allows itself (" + Formatted("%.0f%%", 100.0 * kMatrixMemoryShare) + " of the " + ByteText(available) +
              " available) (expected " +
              (fits >= 0 ? "--lmax " + std::to_string(fits) + " or lower" : "a mesh with fewer vertices") +
              ", or no --orbit: the fixed camera needs one vector per vertex)");
}

void FinishOutputs(OutputFolder& folder) {
  const OutputFolder::Finished f = folder.Finish();
  const auto names = [](const std::vector<std::string>& v) {
    return v.front() + (v.size() > 2 ? " ... " + v.back() : v.size() == 2 ? ", " + v.back() : "");
  };
  if (!f.kept_as_orig.empty())
    Summary("outputs: replaced " + std::to_string(f.kept_as_orig.size()) + " file" +
            (f.kept_as_orig.size() > 1 ? "s" : "") + " prt did not write in " + folder.dir() +
            " (--replace), kept as " + names(f.kept_as_orig));
  if (!f.removed.empty())
    Summary("outputs: removed " + std::to_string(f.removed.size()) + " file" + (f.removed.size() > 1 ? "s" : "") +
            " an earlier run of this command wrote in " + folder.dir() + " and this one did not (" +
            f.removed.front() + (f.removed.size() > 1 ? " ... " + f.removed.back() : "") + ")");
}

}  // namespace prt
